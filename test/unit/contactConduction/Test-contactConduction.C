// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    Test-contactConduction

Description
    Heat conduction through contacts in the DEM engine (contactConduction)
    against the analytic solutions of the thesis's App. B: a 1 mm glass
    particle (k 1.4 W/(m K), c_p 840 J/(kg K), 2500 kg/m^3; Y 5 MPa,
    Y_0 60 GPa, nu 0.22) at 363.15 K held still at a fixed gap or overlap
    from an aluminium wall (k 238; Y 5 MPa, Y_0 69 GPa, nu 0.34) at
    293.15 K, in N2 (k_f 0.026). Then m c_p dT/dt = G (T_w - T) with G
    constant, and

        (T - T_0)/(T_w - T_0) = 1 - exp(-G t/(m c_p))           (B.1-B.4)

    -case wallDirect    Batchelor-O'Brien at overlaps 0.002-0.02 r_p with
                        the thermal overlap c = (Y* / Y*_0)^(2/3)
                        (Fig B.5);
    -case wallIndirect  Rong-Horio (lens 1.4 r_p, s = 1e-7 m) at gaps 0.02
                        and 0.002 r_p (case 2), 0 (case 4), and overlaps
                        0.002, 0.02 r_p (case 5, thermal overlap)
                        (Fig B.2-B.4);
    -case pairDirect    two such particles pressed together at overlaps
                        0.002-0.02 r_p, one at 363.15 K, one at 293.15 K:
                        their difference decays at 2 G/(m c_p) and their
                        mean stays;
    -case pairIndirect  the two at surface gaps 0.4, 0.04, 0.0004 r_p
                        through the gas lens (the lists reach the lens);
    -case coarseGrain   a column of 16 primaries on a hot floor against 8
                        parcels of K = 2, limited by the chain and by the
                        floor: the heat taken in agrees within one primary
                        layer's (the coarse-grain law of contactConduction:
                        K between parcels, K^2 to a wall).

    G is computed here from eq 4.25-4.36 independently of the engine's
    code path (the laws' own functions are tested in Test-conductionLaws).
    The engine's explicit step (dt = 1e-4 s, 50,000 steps) differs from the
    exponential by about t dt G^2/(2 (m c_p)^2) of the difference: the
    tolerance is 1e-4 of it over 5 s.
    -case badInput -bad noConductivity: a fatal error.
*/

#include "argList.H"
#include "unitCheck.H"
#include "IStringStream.H"
#include "demEngine.H"
#include "conductionGeometry.H"
#include "RongHorio.H"
#include "effectiveProperties.H"
#include "mathematicalConstants.H"
#include "OFstream.H"

using namespace Foam;

namespace
{

using unitTest::check;

const scalar rho = 2500;
const scalar cp = 840;
const scalar r = 0.5e-3;
const scalar kp = 1.4;
const scalar kw = 238;
const scalar kf = 0.026;
const scalar T0 = 363.15;
const scalar Tw = 293.15;
const scalar dt = 1e-4;
const label nSteps = 50000;


//- The lens law's settings of every case (lens 1.4 r_p, s = 1e-7 m)
dictionary lensDict()
{
    dictionary coeffs;
    coeffs.add("lensRadius", 1.4);
    coeffs.add("minimumDistance", 1e-7);
    dictionary dict;
    dict.add("indirect", "RongHorio");
    dict.add("RongHorioCoeffs", coeffs);
    return dict;
}


dictionary settings(const word& direct, const word& indirect)
{
    OStringStream os;
    os  << "contactLaw HertzMindlin;"
        << "particleParticle { restitution 0.9; friction 0.3; }"
        << "particleWall { restitution 0.9; friction 0.3; }"
        << "conduction { direct " << direct << "; indirect " << indirect
        << "; }";
    IStringStream is(os.str());
    dictionary dict(is);
    dict.subDict("conduction").add
    (
        "RongHorioCoeffs", lensDict().subDict("RongHorioCoeffs")
    );
    return dict;
}


dictionary materials
(
    const bool withConductivity = true,
    const scalar k = kp,
    const scalar kWall = kw
)
{
    OStringStream os;
    os  << "glass { demYoungsModulus 5e6; youngsModulus 60e9;"
        << " poissonsRatio 0.22; density " << rho << "; specificHeat " << cp
        << ";";
    if (withConductivity)
    {
        os << " thermalConductivity " << k << ";";
    }
    os  << " }"
        << "aluminium { demYoungsModulus 5e6; youngsModulus 69e9;"
        << " poissonsRatio 0.34; thermalConductivity " << kWall << "; }"
        << "particle glass;"
        << "walls { \".*\" aluminium; }";
    IStringStream is(os.str());
    return dictionary(is);
}


//- A square wall face at z = 0, normal -z, at temperature Tw
demWalls floor()
{
    const scalar h = 100*r;
    pointField pts
    ({
        point(-h, -h, 0), point(-h, h, 0), point(h, h, 0), point(h, -h, 0)
    });
    faceList faces(1, face(labelList({0, 1, 2, 3})));
    return demWalls(pts, faces);
}


scalar mcp()
{
    return rho*4.0/3.0*constant::mathematical::pi*pow3(r)*cp;
}


//- Hold every particle still: the external force cancels the forces of
//  the initial state
void holdStill(demEngine& dem)
{
    dem.initialise();
    demParticles& P = dem.particles();
    for (label i = 0; i < P.size(); ++i)
    {
        P.externalForce[i] = -P.force[i];
    }
}


//- Run, comparing particle 0's (T - T_0)/(T_w - T_0) with the exponential
//  of rate G/(m c_p) at 5 times; the largest difference
//- Where -write puts the histories of the wall cases (empty: no files)
fileName writeDir;


//- Run for endTime in steps of step, comparing particle 0's
//  theta = (T - T_0)/(T_partner - T_0) with the exponential of rate
//  G/(m c_p) at n times (written to writeDir/name.dat with -write); the
//  largest difference
scalar runAgainst
(
    demEngine& dem,
    const scalar G,
    const scalar Tpartner,
    const word& name = word::null,
    const scalar endTime = nSteps*dt,
    const scalar step = dt,
    const label n = 5
)
{
    const demParticles& P = dem.particles();
    const scalar rate = G/mcp();
    autoPtr<OFstream> os;
    if (!writeDir.empty() && !name.empty())
    {
        os.reset(new OFstream(writeDir/name + ".dat"));
        os() << "# t [s]  theta simulated  theta analytic (G " << G
             << " W/K, m c_p " << mcp() << " J/K)" << nl;
        os() << 0 << ' ' << 0 << ' ' << 0 << nl;
    }
    scalar worst = 0;
    const label every = label(endTime/step/n + 0.5);
    for (label k = 1; k <= n; ++k)
    {
        dem.advance(step, every);
        const scalar t = k*every*step;
        const scalar theta = (P.temperature[0] - T0)/(Tpartner - T0);
        const scalar exact = 1 - std::exp(-rate*t);
        worst = max(worst, mag(theta - exact));
        if (os.valid())
        {
            os() << t << ' ' << theta << ' ' << exact << nl;
        }
        else
        {
            Info<< "    t " << t << " s: theta " << theta << " (analytic "
                << exact << ")" << nl;
        }
    }
    return worst;
}


//- Two held particles, at T0 and Tw, exchanging G (T_j - T_i) each: the
//  difference decays at 2 G/(m c_p), so particle 0 relaxes towards their
//  mean as towards a wall at the mean with twice G; checked against that
//  exponential (1e-4), and the mean conserved (1e-14)
void checkPairRelaxes(demEngine& dem, const scalar G, const std::string& what)
{
    const scalar worst = runAgainst(dem, 2*G, 0.5*(T0 + Tw));
    check(what + ": largest difference from the exponential", worst, 0, 1e-4);
    const UList<scalar>& T = dem.particles().temperature;
    check("  mean temperature conserved", 0.5*(T[0] + T[1]), 0.5*(T0 + Tw), 1e-14);
}


void caseWall(const bool direct)
{
    const scalar c =
        conductionGeometry::overlapFactor
        (
            effective::modulus(5e6, 0.22, 5e6, 0.34),
            effective::modulus(60e9, 0.22, 69e9, 0.34),
            2.0/3.0
        );

    const indirectConductions::RongHorio lens(lensDict(), 0);

    // Positive: overlap; negative: gap (in units of r)
    const List<scalar> overlaps =
        direct
      ? List<scalar>({0.002, 0.005, 0.01, 0.02})
      : List<scalar>({-0.02, -0.002, 0, 0.002, 0.02});

    for (const scalar f : overlaps)
    {
        demEngine dem
        (
            direct
          ? settings("BatchelorOBrien", "none")
          : settings("none", "RongHorio"),
            materials(),
            1
        );
        dem.setWalls(floor());
        dem.setWallTemperature(scalarField(1, Tw));
        demParticles& P = dem.resetParticles();
        P.append(point(0, 0, r - f*r), Zero, Zero, r, rho, 0);
        P.temperature[0] = T0;
        P.gasConductivity[0] = kf;
        holdStill(dem);

        // G from eq 4.25-4.27 (direct), 4.31-4.36 (indirect)
        scalar G = 0;
        if (direct)
        {
            const scalar delta = c*f*r;
            G = 4*kp*kw/(kp + kw)*std::sqrt(r*r - sqr(r - delta));
        }
        else
        {
            const scalar gap = f > 0 ? -c*f*r : -f*r;
            G = lens.wallConductance(kf, r, gap);
        }
        Info<< (direct ? "direct" : "indirect") << ", overlap " << f
            << " r_p: G = " << G << " W/K, m c_p/G = " << mcp()/G << " s"
            << nl;
        // The test: 5 s in steps of 1e-4 s; with -write, the histories of
        // App. B's figures (300 s direct, 20 s indirect, same steps)
        const word name
        (
            word(direct ? "wallDirect_" : "wallIndirect_") + Foam::name(f)
        );
        const scalar worst =
            writeDir.empty()
          ? runAgainst(dem, G, Tw)
          : runAgainst(dem, G, Tw, name, direct ? 300 : 20, dt, 100);
        check
        (
            word(direct ? "direct" : "indirect") + " particle-wall, overlap "
          + Foam::name(f) + " r_p: largest difference from the exponential",
            worst, 0, 1e-4
        );
        check
        (
            "  the particle stayed at its overlap",
            dem.particles().position[0].z(), r - f*r, 1e-12
        );
    }
}


void casePairDirect()
{
    const scalar YStar = effective::modulus(5e6, 0.22, 5e6, 0.22);
    const scalar YStar0 = effective::modulus(60e9, 0.22, 60e9, 0.22);
    const scalar c = conductionGeometry::overlapFactor(YStar, YStar0, 2.0/3.0);

    for (const scalar f : {0.002, 0.005, 0.01, 0.02})
    {
        demEngine dem(settings("BatchelorOBrien", "none"), materials(), 1);
        demParticles& P = dem.resetParticles();
        const scalar half = r - 0.5*f*r;
        P.append(point(-half, 0, 0), Zero, Zero, r, rho, 0);
        P.append(point(half, 0, 0), Zero, Zero, r, rho, 1);
        P.temperature[0] = T0;
        P.temperature[1] = Tw;
        holdStill(dem);

        // Two equal spheres: contact circle of radius^2 r d - d^2/4 at the
        // thermal overlap d = c delta; each loses G (T_i - T_j), so the
        // difference decays at 2 G/(m c_p): theta of particle 0 towards
        // the mean is that of a wall at the mean with twice G
        const scalar d = c*f*r;
        const scalar G = 4*kp*kp/(2*kp)*std::sqrt(r*d - d*d/4);
        Info<< "pair direct, overlap " << f << " r_p: G = " << G << " W/K"
            << nl;
        checkPairRelaxes
        (
            dem, G, "direct particle-particle, overlap " + Foam::name(f) + " r_p"
        );
    }
}


void casePairIndirect()
{
    const indirectConductions::RongHorio lens(lensDict(), 0);

    // Surface gaps (in units of r): no contact, no force: they stay
    for (const scalar f : {0.4, 0.04, 0.0004})
    {
        demEngine dem(settings("none", "RongHorio"), materials(), 1);
        demParticles& P = dem.resetParticles();
        const scalar half = r + 0.5*f*r;
        P.append(point(-half, 0, 0), Zero, Zero, r, rho, 0);
        P.append(point(half, 0, 0), Zero, Zero, r, rho, 1);
        P.temperature[0] = T0;
        P.temperature[1] = Tw;
        P.gasConductivity[0] = kf;
        P.gasConductivity[1] = kf;
        holdStill(dem);

        const scalar G = lens.pairConductance(kf, r, r, f*r);
        Info<< "pair indirect, gap " << f << " r_p: G = " << G << " W/K"
            << nl;
        checkPairRelaxes
        (
            dem, G, "indirect particle-particle, gap " + Foam::name(f) + " r_p"
        );
    }
}


//- Mean (T - T_0)/(T_w - T_0) of a column of particles on the hot floor
//  (wall at Tw, particles at T0), every tenth of the run
List<scalar> column
(
    const scalar K,
    const label n,
    const scalar overlap,
    const word& indirect,
    const scalar k,
    const scalar kWall
)
{
    demEngine dem
    (
        settings("BatchelorOBrien", indirect), materials(true, k, kWall), K
    );
    dem.setWalls(floor());
    dem.setWallTemperature(scalarField(1, Tw));
    demParticles& P = dem.resetParticles();
    const scalar R = K*r;
    const scalar d = K*overlap;
    for (label i = 0; i < n; ++i)
    {
        P.append(point(0, 0, R - d + i*(2*R - d)), Zero, Zero, R, rho, i);
        P.temperature[i] = T0;
        P.gasConductivity[i] = kf;
    }
    holdStill(dem);

    List<scalar> theta(10);
    const label every = 10000;
    for (label k = 0; k < 10; ++k)
    {
        dem.advance(1e-3, every);
        scalar sum = 0;
        for (label i = 0; i < n; ++i)
        {
            sum += dem.particles().temperature[i];
        }
        theta[k] = (sum/n - T0)/(Tw - T0);
    }
    return theta;
}


//- The heat taken in by a column of 16 primaries and by 8 parcels of K = 2
//  standing for K^2 such columns; true if within one primary layer's
bool sameHeat
(
    const word& what,
    const word& indirect,
    const scalar k,
    const scalar kWall
)
{
    const label nPrimaries = 16;
    const List<scalar> a = column(1, nPrimaries, 0.01*r, indirect, k, kWall);
    const List<scalar> b = column(2, nPrimaries/2, 0.01*r, indirect, k, kWall);
    scalar worst = 0;
    forAll(a, i)
    {
        Info<< "    t " << 10*(i + 1) << " s: mean theta K = 1 " << a[i]
            << ", K = 2 " << b[i] << nl;
        worst = max(worst, mag(a[i] - b[i]));
    }
    // In primary layers: the column's heat is nPrimaries x theta layers
    const scalar layers = nPrimaries*worst;
    const bool ok = layers <= 1 && a.last() > 0.5 && b.last() > 0.5;
    Info<< (ok ? "ok   " : "FAIL ") << what.c_str() << ": K = 2 against"
        << " K = 1, largest difference of the heat taken in " << layers
        << " primary layers (at most 1); taken in at the end "
        << a.last() << ", " << b.last() << " (more than half)" << nl;
    return ok;
}


void caseCoarseGrain()
{
    // Columns on the hot floor, overlaps 0.01 r (0.01 K r for the
    // parcels). The parcel layer at the floor is K primary layers thick
    // and is heated as one: the columns may differ by about one primary
    // layer's heat, not more.
    // 1. Limited by the chain (particles and floor of k = 200, direct and
    //    through the gas lens): a parcel-parcel contact must conduct K
    //    times a primary's
    // 2. Limited by the floor (particles of k = 2000, floor of k = 20,
    //    direct only: the column heats nearly uniformly): a parcel-floor
    //    contact must conduct K^2 times a primary's (with K times, the
    //    parcels fall behind by several primary layers)
    const bool chain = sameHeat("chain-limited", "RongHorio", 200, 200);
    const bool floor = sameHeat("floor-limited", "none", 2000, 20);
    if (!chain || !floor)
    {
        ++unitTest::nFailed();
    }
}


void caseBadInput(const word& what)
{
    if (what == "noConductivity")
    {
        demEngine dem(settings("BatchelorOBrien", "none"), materials(false), 1);
    }
    else
    {
        FatalErrorInFunction << "Unknown -bad " << what << exit(FatalError);
    }
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote("Contact conduction in the DEM engine against App. B");
    argList::noParallel();
    argList::noCheckProcessorDirectories();
    argList::addOption("case", "name", "wallDirect|wallIndirect|pairDirect|pairIndirect|coarseGrain|badInput");
    argList::addOption("bad", "what", "with -case badInput: noConductivity");
    argList::addOption
    (
        "write", "dir",
        "with -case wallDirect|wallIndirect: the histories of App. B's"
        " figures into dir"
    );
    argList args(argc, argv);

    const word which(args.get<word>("case"));
    args.readIfPresent("write", writeDir);
    if (which == "wallDirect") caseWall(true);
    else if (which == "wallIndirect") caseWall(false);
    else if (which == "pairDirect") casePairDirect();
    else if (which == "pairIndirect") casePairIndirect();
    else if (which == "coarseGrain") caseCoarseGrain();
    else if (which == "badInput") caseBadInput(args.get<word>("bad"));
    else
    {
        FatalErrorInFunction
            << "Unknown -case " << which
            << ". Valid: wallDirect wallIndirect pairDirect pairIndirect coarseGrain badInput"
            << exit(FatalError);
    }

    if (unitTest::nFailed())
    {
        FatalErrorInFunction << "Test-contactConduction -case " << which
            << " failed" << exit(FatalError);
    }

    Info<< "End" << nl;
    return 0;
}
