// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "HertzMindlin.H"
#include "HertzCollision.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace contactLaws
{
    defineTypeNameAndDebug(HertzMindlin, 0);
    addToRunTimeSelectionTable(contactLaw, HertzMindlin, dictionary);
}
}


Foam::scalar Foam::contactLaws::HertzMindlin::restitution(const scalar alpha)
{
    // RK4 on xi'' = -xi^1.5 - c xi^0.25 xi', c = alpha sqrt(3/2), from
    // xi = 0, xi' = 1 until xi returns to 0 (elastic duration ~3.2)
    const scalar c = alpha*sqrt(1.5);
    auto acc = [c](const scalar xi, const scalar u)
    {
        const scalar s = max(xi, scalar(0));
        return -pow(s, 1.5) - c*pow(s, 0.25)*u;
    };

    const scalar h = 2e-4;
    scalar xi = 0;
    scalar u = 1;
    for (label step = 0; step < 1000000; ++step)
    {
        const scalar k1x = u;
        const scalar k1u = acc(xi, u);
        const scalar k2x = u + 0.5*h*k1u;
        const scalar k2u = acc(xi + 0.5*h*k1x, k2x);
        const scalar k3x = u + 0.5*h*k2u;
        const scalar k3u = acc(xi + 0.5*h*k2x, k3x);
        const scalar k4x = u + h*k3u;
        const scalar k4u = acc(xi + h*k3x, k4x);

        const scalar xiNew = xi + h/6*(k1x + 2*k2x + 2*k3x + k4x);
        const scalar uNew = u + h/6*(k1u + 2*k2u + 2*k3u + k4u);

        if (xiNew <= 0 && step > 0)
        {
            // Velocity at the crossing, linearly interpolated
            const scalar f = xi/(xi - xiNew);
            return -(u + f*(uNew - u));
        }
        xi = xiNew;
        u = uNew;
    }

    return 0;
}


Foam::scalar Foam::contactLaws::HertzMindlin::dampingFactor(const scalar e)
{
    if (e >= 1)
    {
        return 0;
    }

    // restitution(alpha) falls monotonically from 1 at alpha = 0
    scalar lo = 0;
    scalar hi = 1;
    while (restitution(hi) > e)
    {
        hi *= 2;
    }
    for (label iter = 0; iter < 60 && (hi - lo) > 1e-12*hi; ++iter)
    {
        const scalar mid = 0.5*(lo + hi);
        if (restitution(mid) > e)
        {
            lo = mid;
        }
        else
        {
            hi = mid;
        }
    }
    return 0.5*(lo + hi);
}


Foam::contactLaws::HertzMindlin::HertzMindlin
(
    const dictionary& dict,
    const contactMaterials& materials,
    const scalar coarseGrainFactor,
    contactSlots& slots
)
:
    contactLawTemplate<HertzMindlin>
    (
        dict, materials, coarseGrainFactor, slots, true
    ),
    YStarPP_(materials.particle().effectiveModulus(materials.particle())),
    YStarPW_(materials.nWalls()),
    alphaPP_(dampingFactor(particleParticle_.restitution())),
    alphaPW_(dampingFactor(particleWall_.restitution())),
    kappaPP_
    (
        4*materials.particle().effectiveShearModulus(materials.particle())
       /YStarPP_
    ),
    sqrtKappaPP_(sqrt(kappaPP_)),
    kappaPW_(materials.nWalls()),
    sqrtKappaPW_(materials.nWalls())
{
    const contactMaterial& p = materials.particle();
    forAll(YStarPW_, m)
    {
        YStarPW_[m] = p.effectiveModulus(materials.wall(m));
        kappaPW_[m] = 4*p.effectiveShearModulus(materials.wall(m))/YStarPW_[m];
        sqrtKappaPW_[m] = sqrt(kappaPW_[m]);
    }
}


Foam::scalar Foam::contactLaws::HertzMindlin::collisionTime
(
    const scalar r,
    const scalar m,
    const scalar v
) const
{
    // Eq 5.12 for two equal particles of the DEM material, and for a
    // particle on each wall material (r* = r, m* = m: a partner of
    // infinite radius and mass)
    const contactMaterial& p = materials_.particle();
    scalar tc = HertzCollision
    (
        r, m, p.youngsModulus(), p.poissonsRatio()
    ).contactTime(v);
    for (label w = 0; w < materials_.nWalls(); ++w)
    {
        const contactMaterial& wm = materials_.wall(w);
        tc = min
        (
            tc,
            HertzCollision
            (
                r, m, p.youngsModulus(), p.poissonsRatio(),
                GREAT, GREAT, wm.youngsModulus(), wm.poissonsRatio()
            ).contactTime(v)
        );
    }
    return tc;
}
