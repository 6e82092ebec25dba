// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "noCohesion.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace cohesionModels
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(cohesionModel, none, dictionary);
}
}
