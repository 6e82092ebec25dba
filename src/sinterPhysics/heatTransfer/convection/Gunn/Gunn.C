// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "Gunn.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace convectionLaws
{
    defineTypeNameAndDebug(Gunn, 0);
    addToRunTimeSelectionTable(convectionLaw, Gunn, dictionary);
}
}


Foam::scalar Foam::convectionLaws::Gunn::Nu
(
    const scalar eps,
    const scalar Re,
    const scalar Pr
) const
{
    const scalar Pr3 = std::cbrt(Pr);
    return
        (7 - 10*eps + 5*eps*eps)*(1 + 0.7*std::pow(Re, 0.2)*Pr3)
      + (1.33 - 2.40*eps + 1.20*eps*eps)*std::pow(Re, 0.7)*Pr3;
}
