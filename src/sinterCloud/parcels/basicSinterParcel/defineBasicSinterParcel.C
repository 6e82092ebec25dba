// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "basicSinterParcel.H"
#include "Cloud.H"

namespace Foam
{
    defineTemplateTypeNameAndDebug(basicSinterParcel, 0);
    defineTemplateTypeNameAndDebug(Cloud<basicSinterParcel>, 0);
}
