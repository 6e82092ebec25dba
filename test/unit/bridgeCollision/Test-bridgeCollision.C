// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    Test-bridgeCollision

Description
    Whether two sintering particles stick does not depend on the DEM step
    (solidBridge, neckIntegration exact), where it does with the thesis's
    step count (eq 5.11, neckIntegration stepCount).

    Two labBed parcels (K = 6, primary radius 29 um, hematite of Table 5.1
    softened to Y = 1e6 Pa, e = 0.9) meet head-on at 1000 degC with
    nine-micro-contact bridges (C = 1.251), no gravity, no gas. Below a
    sticking speed v* they stay together; above it they part. Each
    quantity is found with DEM steps of t_c/20, t_c/50 and t_c/400 (t_c:
    eq 5.12's Hertz collision time at 0.1 m/s) and averaged over four
    phases of the first contact within a step:

      - v*: by bisection of the impact speed (to 1e-4 relative);
      - e_b: the separation speed over the impact speed at 2 v*(t_c/400).

    Checks, neckIntegration exact, against t_c/400: v* and e_b at t_c/20
    and t_c/50 within 0.5 % (relative); for every bisection, that v* lies
    in its bracket (the pair sticks at 0.01 m/s and parts at 0.1 m/s). The same figures of stepCount (the
    thesis's eq 5.11) and the rebound without bridges (the contact law's
    own dependence on the step) are printed; the measured figures are in
    validation/labBedSintering/README.md.
*/

#include "argList.H"
#include "unitCheck.H"
#include "sinteringEngine.H"
#include "demEngine.H"

using namespace Foam;

namespace
{

using unitTest::check;

const scalar K = 6;
const scalar r = K*29e-6;
const scalar rho = 5240;
const scalar T = 1273.15;


//- The engine: nine-micro-contact bridges from the start
dictionary engineDict(const word& cohesion, const word& neckIntegration)
{
    return unitTest::sinteringEngineDict
    (
        cohesion, "nineMicroContacts", 0, "wall", neckIntegration
    );
}


//- Outcome of one collision at impact speed v with DEM step dt, the first
//  contact at phase (0, 1) of a step: the separation speed, 0 if the pair
//  still touches 5 t_c after it met (stuck)
scalar collide
(
    const word& cohesion,
    const word& neckIntegration,
    const scalar v,
    const scalar dt,
    const scalar phase,
    const scalar tc
)
{
    demEngine e
    (
        engineDict(cohesion, neckIntegration), unitTest::hematiteMaterials(), K
    );
    demParticles& P = e.resetParticles();
    // The gap closes 'phase' of a step before the end of the third step
    const scalar gap = (3 - phase)*v*dt;
    P.append(vector::zero, vector(0.5*v, 0, 0), Zero, r, rho, 0);
    P.append(vector(2*r + gap, 0, 0), vector(-0.5*v, 0, 0), Zero, r, rho, 1);
    P.temperature = T;

    label touched = 0;
    for (label k = 0; touched*dt < 5*tc; ++k)
    {
        e.step(dt);
        if (e.nPairContacts() > 0)
        {
            ++touched;
        }
        else if (touched)
        {
            return P.velocity[1].x() - P.velocity[0].x();
        }
        if (k > 100000000)
        {
            FatalErrorInFunction << "no contact" << exit(FatalError);
        }
    }
    return 0;
}


//- Mean over the phases of the separation speed over the impact speed v
scalar rebound
(
    const word& cohesion,
    const word& neckIntegration,
    const scalar v,
    const scalar dt,
    const scalar tc,
    const scalarList& phases
)
{
    scalar sum = 0;
    for (const scalar phase : phases)
    {
        sum += collide(cohesion, neckIntegration, v, dt, phase, tc)/v;
    }
    return sum/phases.size();
}


//- Sticking speed: the largest impact speed after which the pair stays
//  together, averaged over the phases; checks that it lies in the
//  bisection's bracket [0.01, 0.1] m/s (the pair sticks at 0.01 m/s and
//  parts at 0.1 m/s), which a bisection would not tell
scalar stickingSpeed
(
    const word& neckIntegration,
    const scalar dt,
    const scalar tc,
    const scalarList& phases
)
{
    scalar sum = 0;
    for (const scalar phase : phases)
    {
        scalar lo = 0.01, hi = 0.1;
        check
        (
            "separation speed after 0.01 m/s (stuck) [m/s]",
            collide("solidBridge", neckIntegration, lo, dt, phase, tc), 0, 0
        );
        check
        (
            "the pair parts after 0.1 m/s",
            collide("solidBridge", neckIntegration, hi, dt, phase, tc) > 0,
            1,
            0
        );
        while (hi - lo > 1e-4*lo)
        {
            const scalar mid = 0.5*(lo + hi);
            const scalar u =
                collide("solidBridge", neckIntegration, mid, dt, phase, tc);
            (u > 0 ? hi : lo) = mid;
        }
        sum += 0.5*(lo + hi);
    }
    return sum/phases.size();
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList args(argc, argv);
    Info().precision(6);

    const scalarList phases({0.125, 0.375, 0.625, 0.875});
    scalar tc = 0;
    {
        demEngine e
        (
            engineDict("none", "exact"), unitTest::hematiteMaterials(), K
        );
        const scalar m = rho*4.0/3.0*constant::mathematical::pi*pow3(r);
        tc = e.law().collisionTime(r, m, 0.1);
    }
    Info<< "t_c(0.1 m/s) = " << tc << " s" << nl;

    const labelList Ns({20, 50, 400});
    for (const label N : Ns)
    {
        const scalar e = rebound("none", "exact", 0.1, tc/N, tc, phases);
        Info<< "no bridges, N " << N << ": e " << e << nl;
    }

    for (const word mode : {"exact", "stepCount"})
    {
        scalarList vs(Ns.size()), eb(Ns.size());
        forAll(Ns, k)
        {
            vs[k] = stickingSpeed(mode, tc/Ns[k], tc, phases);
        }
        forAll(Ns, k)
        {
            eb[k] = rebound("solidBridge", mode, 2*vs.last(), tc/Ns[k], tc, phases);
        }
        for (label k = 0; mode == "exact" && k < Ns.size() - 1; ++k)
        {
            const word at(" at t_c/" + Foam::name(Ns[k]) + ", exact");
            check("v*" + at + " [m/s]", vs[k], vs.last(), 5e-3);
            check("e_b" + at, eb[k], eb.last(), 5e-3);
        }
        forAll(Ns, k)
        {
            Info<< mode << " N " << Ns[k] << ": v* " << vs[k]
                << " (" << vs[k]/vs.last() - 1 << "), e_b " << eb[k]
                << " (" << eb[k]/eb.last() - 1 << ")" << nl;
        }
    }

    if (unitTest::nFailed())
    {
        FatalErrorInFunction << "bridge collision checks failed" << exit(FatalError);
    }
    return 0;
}
