// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "basicSinterParcel.H"
#include "Cloud.H"

namespace Foam
{
    typedef DEMParcel<CollidingParcel<KinematicParcel<particle>>>
        sinterDEMParcel;
    defineTemplateTypeNameAndDebug(sinterDEMParcel, 0);
    defineTemplateTypeNameAndDebug(basicSinterParcel, 0);
    defineTemplateTypeNameAndDebug(Cloud<basicSinterParcel>, 0);
}
