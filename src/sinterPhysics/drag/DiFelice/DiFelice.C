// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "DiFelice.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace dragLaws
{
    defineTypeNameAndDebug(DiFelice, 0);
    addToRunTimeSelectionTable(dragLaw, DiFelice, dictionary);
}
}


Foam::scalar Foam::dragLaws::DiFelice::F(const scalar eps, const scalar Re) const
{
    // Cd Re/24 = (0.63 sqrt(Re) + 4.8)^2/24, finite at Re = 0
    const scalar CdRe24 = sqr(0.63*std::sqrt(Re) + 4.8)/24;
    const scalar chi =
        3.7 - 0.65*std::exp(-0.5*sqr(1.5 - std::log10(max(Re, VSMALL))));

    return CdRe24*std::pow(eps, -chi);
}
