// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "basicSinterParcel.H"
#include "Cloud.H"

namespace Foam
{
    // The layers below DEMParcel that OpenFOAM's library does not define
    typedef ReducingParcel<ThermoParcel<KinematicParcel<particle>>>
        reducingThermoParcel;
    defineTemplateTypeNameAndDebug(reducingThermoParcel, 0);

    defineTemplateTypeNameAndDebug(basicSinterParcel, 0);
    defineTemplateTypeNameAndDebug(Cloud<basicSinterParcel>, 0);
}
