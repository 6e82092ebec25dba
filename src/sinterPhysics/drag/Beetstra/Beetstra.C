// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "Beetstra.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace dragLaws
{
    defineTypeNameAndDebug(Beetstra, 0);
    addToRunTimeSelectionTable(dragLaw, Beetstra, dictionary);
}
}


Foam::dragLaws::Beetstra::Beetstra(const dictionary& dict)
:
    polydisperse_(dict.lookupOrDefault<bool>("polydisperse", false))
{}


Foam::scalar Foam::dragLaws::Beetstra::sizeFactor
(
    const scalar eps,
    const scalar y
)
{
    return eps*y + (1 - eps)*sqr(y) + 0.064*eps*pow3(y);
}


Foam::scalar Foam::dragLaws::Beetstra::Fpolydisperse
(
    const scalar eps,
    const scalar Re,
    const scalar y
) const
{
    return sizeFactor(eps, y)*F(eps, Re);
}


Foam::scalar Foam::dragLaws::Beetstra::F(const scalar eps, const scalar Re) const
{
    const scalar phi = 1 - eps;
    const scalar a = 0.5*(1 + 4*phi);

    // Inertial term with Re^a multiplied through, finite at Re = 0:
    // 0.413 Re/(24 eps^2) N/(1 + 10^(3 phi) Re^-a)
    //   = 0.413/(24 eps^2) (Re N) Re^a/(Re^a + 10^(3 phi))
    const scalar ReN = Re/eps + 3*eps*phi*Re + 8.4*std::pow(Re, 0.657);
    const scalar Rea = std::pow(Re, a);

    return
        10*phi/sqr(eps)
      + sqr(eps)*(1 + 1.5*std::sqrt(phi))
      + 0.413/(24*sqr(eps))*ReN*Rea/(Rea + std::pow(10.0, 3*phi));
}
