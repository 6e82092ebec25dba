// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "Gidaspow.H"
#include "addToRunTimeSelectionTable.H"
#include "WenYu.H"
#include "ErgunDrag.H"

namespace Foam
{
namespace dragLaws
{
    defineTypeNameAndDebug(Gidaspow, 0);
    addToRunTimeSelectionTable(dragLaw, Gidaspow, dictionary);
}
}


Foam::scalar Foam::dragLaws::Gidaspow::F(const scalar eps, const scalar Re) const
{
    return eps < 0.8 ? ErgunDrag::F(eps, Re) : WenYu::value(eps, Re);
}
