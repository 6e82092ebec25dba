// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "Ergun.H"
#include "ErgunDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace dragLaws
{
    defineTypeNameAndDebug(Ergun, 0);
    addToRunTimeSelectionTable(dragLaw, Ergun, dictionary);
}
}


Foam::scalar Foam::dragLaws::Ergun::F(const scalar eps, const scalar Re) const
{
    return ErgunDrag::F(eps, Re);
}
