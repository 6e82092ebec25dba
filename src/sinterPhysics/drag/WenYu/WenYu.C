// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "WenYu.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace dragLaws
{
    defineTypeNameAndDebug(WenYu, 0);
    addToRunTimeSelectionTable(dragLaw, WenYu, dictionary);
}
}


Foam::scalar Foam::dragLaws::WenYu::value(const scalar eps, const scalar Re)
{
    return CdRe24SchillerNaumann(Re)*std::pow(eps, -3.65);
}


Foam::scalar Foam::dragLaws::WenYu::F(const scalar eps, const scalar Re) const
{
    return value(eps, Re);
}
