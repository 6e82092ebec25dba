// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "HertzCollision.H"
#include "effectiveProperties.H"
#include "error.H"

Foam::HertzCollision::HertzCollision
(
    const scalar ri, const scalar mi, const scalar Yi, const scalar nui,
    const scalar rj, const scalar mj, const scalar Yj, const scalar nuj
)
:
    rStar_(effective::radius(ri, rj)),
    mStar_(effective::massFromInverse(1/mi, 1/mj)),
    YStar_(effective::modulus(Yi, nui, Yj, nuj))
{
    if (!(ri > 0 && rj > 0 && mi > 0 && mj > 0 && Yi > 0 && Yj > 0))
    {
        FatalErrorInFunction
            << "Radii, masses and Young's moduli must be positive"
            << exit(FatalError);
    }
}


Foam::HertzCollision::HertzCollision
(
    const scalar r, const scalar m, const scalar Y, const scalar nu
)
:
    HertzCollision(r, m, Y, nu, r, m, Y, nu)
{}


Foam::scalar Foam::HertzCollision::maxOverlap(const scalar vn) const
{
    return pow(15*mStar_*sqr(vn)/(16*YStar_*sqrt(rStar_)), 0.4);
}


Foam::scalar Foam::HertzCollision::stiffness(const scalar vn) const
{
    return 4.0/3.0*YStar_*sqrt(rStar_*maxOverlap(vn));
}


Foam::scalar Foam::HertzCollision::maxNormalForce(const scalar vn) const
{
    return stiffness(vn)*maxOverlap(vn);
}


Foam::scalar Foam::HertzCollision::contactTime(const scalar vn) const
{
    return 2.868*pow(sqr(mStar_)/(sqr(YStar_)*rStar_*vn), 0.2);
}
