// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "Gidaspow.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

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
    if (eps < 0.8)
    {
        return (150*(1 - eps) + 1.75*Re)/(18*sqr(eps));
    }
    return CdRe24SchillerNaumann(Re)*std::pow(eps, -3.65);
}
