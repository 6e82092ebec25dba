// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "RongHorio.H"
#include "keywordRange.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "error.H"
#include "keywordSource.H"

namespace Foam
{
namespace indirectConductions
{
    defineTypeNameAndDebug(RongHorio, 0);
    addToRunTimeSelectionTable(indirectConduction, RongHorio, dictionary);
}
}


namespace
{

//- int_{r1}^{r2} r/l dr, l = a - sqrt(rp^2 - r^2), both bounds in [0, rp]
//  with l > 0 between them
Foam::scalar layerIntegral
(
    const Foam::scalar rp,
    const Foam::scalar a,
    const Foam::scalar r1,
    const Foam::scalar r2
)
{
    if (!(r2 > r1))
    {
        return 0;
    }
    const Foam::scalar u1 = std::sqrt(Foam::max(rp*rp - r1*r1, Foam::scalar(0)));
    const Foam::scalar u2 = std::sqrt(Foam::max(rp*rp - r2*r2, Foam::scalar(0)));
    return (u2 - u1) + a*std::log((a - u2)/(a - u1));
}

} // End anonymous namespace


Foam::indirectConductions::RongHorio::RongHorio
(
    const dictionary& dict,
    const scalar ks
)
:
    gasLens(dict, ks, typeName),
    s_
    (
        dict.optionalSubDict(typeName + "Coeffs")
            .get<scalar>("minimumDistance")
    )
{
    keywordRange::check
    (
        dict.optionalSubDict(typeName + "Coeffs"), "minimumDistance", s_, 0,
        GREAT, "the minimum conduction distance s [m]", true
    );
}


Foam::scalar Foam::indirectConductions::RongHorio::integral
(
    const scalar r,
    const scalar gap,
    const scalar lens,
    const scalar s
)
{
    const scalar rLens = lens*r;
    const scalar a = r + gap;

    // Case 1: the wall outside the lens; a centre on or behind the wall
    // (an overlap of a radius or more) is not a contact this law describes
    if (!(a < rLens) || !(a > 0))
    {
        return 0;
    }

    const scalar rOut = min(std::sqrt(rLens*rLens - a*a), r);
    const scalar rIn = gap < 0 ? std::sqrt(r*r - a*a) : scalar(0);

    if (!(gap < s))
    {
        // Case 2: the gap is at least s everywhere
        return layerIntegral(r, a, 0, rOut);
    }

    // Cases 3, 4, 5: the layer is thinner than s out to r_s
    const scalar h = a - s;
    const scalar rs = min(h > 0 ? std::sqrt(r*r - h*h) : r, rOut);
    const scalar inner = rs > rIn ? (rs*rs - rIn*rIn)/(2*s) : scalar(0);
    return inner + layerIntegral(r, a, max(rs, rIn), rOut);
}


Foam::scalar Foam::indirectConductions::RongHorio::wallConductance
(
    const scalar kf,
    const scalar r,
    const scalar gap
) const
{
    return 2*constant::mathematical::pi*kf*wallIntegral(r, gap);
}


Foam::scalar Foam::indirectConductions::RongHorio::pairConductance
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
       *integral(pairRadius(ri, rj), 0.5*gap, lensRadius(), 0.5*s_);
}
