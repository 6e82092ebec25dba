// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "lensSolidSeries.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "error.H"

namespace Foam
{
namespace indirectConductions
{
    defineTypeNameAndDebug(lensSolidSeries, 0);
    addToRunTimeSelectionTable(indirectConduction, lensSolidSeries, dictionary);
}
}


Foam::indirectConductions::lensSolidSeries::lensSolidSeries
(
    const dictionary& dict,
    const scalar ks
)
:
    gasLens(dict, ks, typeName),
    ks_(ks)
{
    if (!(ks_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "indirect " << typeName << " in " << dict.name() << " needs"
            << " the particles' thermalConductivity (> 0) from"
            << " constant/materialProperties, not " << ks_
            << exit(FatalIOError);
    }
}


Foam::scalar Foam::indirectConductions::lensSolidSeries::integral
(
    const scalar r,
    const scalar gap,
    const scalar lens,
    const scalar beta
)
{
    const scalar rLens = lens*r;
    const scalar D = r + gap;

    // Outside the lens, or a centre on or behind the wall
    if (!(D < rLens) || !(D > 0))
    {
        return 0;
    }

    const scalar rOut = min(std::sqrt(rLens*rLens - D*D), r);
    const scalar rIn = gap < 0 ? std::sqrt(r*r - D*D) : scalar(0);
    if (!(rOut > rIn))
    {
        return 0;
    }
    const scalar uIn = std::sqrt(max(r*r - rIn*rIn, scalar(0)));
    const scalar uOut = std::sqrt(max(r*r - rOut*rOut, scalar(0)));

    if (mag(beta) > 1e-3)
    {
        // int_{uOut}^{uIn} u/(D - beta u) du; the log's argument as 1 + x
        const scalar x = beta*(uIn - uOut)/(D - beta*uIn);
        return (uOut - uIn)/beta + D/(beta*beta)*std::log1p(x);
    }

    // Near beta = 0: sum_n beta^n (uIn^(n+2) - uOut^(n+2))/((n + 2) D^(n+1)),
    // the terms beyond n = 5 below 1e-18 relative
    scalar sum = 0;
    scalar bn = 1;
    scalar pIn = uIn*uIn;
    scalar pOut = uOut*uOut;
    scalar Dn = D;
    for (label n = 0; n < 6; ++n)
    {
        sum += bn*(pIn - pOut)/((n + 2)*Dn);
        bn *= beta;
        pIn *= uIn;
        pOut *= uOut;
        Dn *= D;
    }
    return sum;
}


Foam::scalar Foam::indirectConductions::lensSolidSeries::wallConductance
(
    const scalar kf,
    const scalar r,
    const scalar gap
) const
{
    return
        2*constant::mathematical::pi*kf
       *integral(r, gap, lensRadius(), 1 - kf/ks_);
}


Foam::scalar Foam::indirectConductions::lensSolidSeries::pairConductance
(
    const scalar kf,
    const scalar ri,
    const scalar rj,
    const scalar gap
) const
{
    // Each sphere of the equal pair to the mid plane at half the gap, in
    // series
    return
        constant::mathematical::pi*kf
       *integral(pairRadius(ri, rj), 0.5*gap, lensRadius(), 1 - kf/ks_);
}
