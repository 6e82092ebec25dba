// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    demBedBenchmark

Description
    The demBed benchmark, sinterFoam's side: the DEM engine alone
    (libsinterDEM, no gas) on the bed that runLiggghts gives LIGGGHTS.
    Spheres of d = 1 mm, 2500 kg/m^3, Y = 5 MPa, nu = 0.22 (particles and
    walls), Hertz-Mindlin with e = 0.5 and mu = 0.5, no rolling friction,
    gravity 9.81 m/s^2, in an open box of planar walls x = 0, Lx, y = 0,
    Ly, z = 0; step 5e-6 s; list skin 0.1 d. The lattice of makeBed.py
    settles for -settle steps, then -steps steps are timed.

    Prints, last, machine-readable lines as runLiggghts does:
        engine particles N | steps S | loopTime T (s, wall clock)
        engine cpuTime C (s, the process's CPU time over the measured run)
        engine particleStepsPerSecondPerCore X   (N S / C)
        engine contactsPerParticle Z   (2 x touching pairs / N)
        engine wallContacts W | listBuilds B (in the measured run)
        engine candidatePairsPerParticle P  (2 x pairs in the lists / N)
        engine maxZ H (m) | meanKE K (J, translational, per particle)

Usage
    demBedBenchmark -positions positions.txt [-settle 20000] [-steps 4000]
        [-Lx 30.5e-3] [-Ly 30.5e-3]
*/

#include "argList.H"
#include "IFstream.H"
#include "IStringStream.H"
#include "demEngine.H"
#include <chrono>
#include <ctime>

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote("The DEM engine alone on the demBed benchmark's bed");
    argList::noParallel();
    argList::noCheckProcessorDirectories();
    argList::noBanner();
    argList::addOption("positions", "file", "n, then x y z per line [m]");
    argList::addOption("settle", "steps", "steps before the measurement");
    argList::addOption("steps", "steps", "measured steps");
    argList::addOption("Lx", "m", "box width in x (default 30.5e-3)");
    argList::addOption("Ly", "m", "box width in y (default 30.5e-3)");
    argList args(argc, argv, false, false);

    const fileName positionsFile(args.get<fileName>("positions"));
    const label nSettle = args.lookupOrDefault<label>("settle", 20000);
    const label nSteps = args.lookupOrDefault<label>("steps", 4000);
    const scalar Lx = args.lookupOrDefault<scalar>("Lx", 30.5e-3);
    const scalar Ly = args.lookupOrDefault<scalar>("Ly", 30.5e-3);

    const scalar r = 0.5e-3;
    const scalar rho = 2500;
    const scalar g = 9.81;
    const scalar dt = 5e-6;
    const scalar H = 0.1;

    IStringStream settings
    (
        "contactLaw HertzMindlin;"
        "particleParticle { restitution 0.5; friction 0.5; }"
        "particleWall { restitution 0.5; friction 0.5; }"
        "skin 0.1;"
    );
    IStringStream materials
    (
        "glass { youngsModulus 5e6; poissonsRatio 0.22; }"
        "particle glass;"
        "walls { \".*\" glass; }"
    );
    demEngine engine(dictionary(settings), dictionary(materials), 1);

    // Floor and four side walls, normals out of the box
    const pointField pts
    ({
        point(0, 0, 0), point(Lx, 0, 0), point(Lx, Ly, 0), point(0, Ly, 0),
        point(0, 0, H), point(Lx, 0, H), point(Lx, Ly, H), point(0, Ly, H)
    });
    const faceList faces
    ({
        face(labelList({0, 3, 2, 1})),
        face(labelList({0, 1, 5, 4})),
        face(labelList({1, 2, 6, 5})),
        face(labelList({2, 3, 7, 6})),
        face(labelList({3, 0, 4, 7}))
    });
    engine.setWalls(demWalls(pts, faces));

    // The lattice: n, then x y z per line
    IFstream is(positionsFile);
    if (!is.good())
    {
        FatalErrorInFunction
            << "Cannot read -positions " << positionsFile << exit(FatalError);
    }
    label n;
    is >> n;
    demParticles& P = engine.resetParticles();
    for (label i = 0; i < n; ++i)
    {
        scalar x, y, z;
        is >> x >> y >> z;
        const label k = P.append(point(x, y, z), Zero, Zero, r, rho, i);
        P.externalForce[k] = vector(0, 0, -g*P.mass(k));
    }

    engine.initialise();
    engine.advance(dt, nSettle);

    const label builds0 = engine.nBuilds();
    const std::clock_t cpu0 = std::clock();
    const auto wall0 = std::chrono::steady_clock::now();
    engine.advance(dt, nSteps);
    const auto wall1 = std::chrono::steady_clock::now();
    const std::clock_t cpu1 = std::clock();
    const scalar loopTime =
        std::chrono::duration<double>(wall1 - wall0).count();
    const scalar cpuTime = scalar(cpu1 - cpu0)/CLOCKS_PER_SEC;

    scalar maxZ = 0;
    scalar ke = 0;
    forAll(P.position, i)
    {
        maxZ = max(maxZ, P.position[i].z());
        ke += 0.5*P.mass(i)*magSqr(P.velocity[i]);
    }

    Info().precision(6);
    Info<< "engine particles " << n << nl
        << "engine steps " << nSteps << nl
        << "engine loopTime " << loopTime << nl
        << "engine cpuTime " << cpuTime << nl
        << "engine particleStepsPerSecondPerCore " << n*nSteps/cpuTime << nl
        << "engine contactsPerParticle "
        << 2.0*engine.nPairContacts()/n << nl
        << "engine wallContacts " << engine.nWallContacts() << nl
        << "engine candidatePairsPerParticle "
        << 2.0*engine.pairs().size()/n << nl
        << "engine listBuilds " << engine.nBuilds() - builds0 << nl
        << "engine maxZ " << maxZ << nl
        << "engine meanKE " << ke/n << nl;

    return 0;
}
