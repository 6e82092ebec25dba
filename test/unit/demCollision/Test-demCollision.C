// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    Test-demCollision

Description
    The DEM engine (libsinterDEM) against analytic collisions. Particles:
    glass of thesis Tables 4.1-4.2, d = 1 mm, rho = 2500 kg/m^3, DEM modulus
    Y = 5 MPa, nu = 0.22; wall Y = 5 MPa, nu = 0.34. Step: 1/237 of the
    collision time (the contact time is resolved to that step). Each check states its tolerance.

    -case headOn      two equal spheres, approach velocity 1 m/s:
        Hertz-Mindlin, e = 1: rebound/approach = 1 within 2 %, contact time
            within 2 % of eq 2.11 / 5.12 (HertzCollision, elastic);
        Hertz-Mindlin, e = 0.9 and 0.5: restitution within 2 % of e;
        linear (Table 4.1: k_n 7000 N/m, gamma_n 0.00131 kg/s): restitution
            and contact time within 2 % of exp(-z t_c), pi/sqrt(w0^2 - z^2).
    -case wall        the same against a wall face (partner of infinite
        mass: r* = r, m* = m).
    -case oblique     sphere on a wall at 0.5 m/s normal and v_t = 2 and
        4 m/s (gross sliding through the whole contact, mu = 0.1, e = 0.9):
        rebound tangential velocity v_t - mu (1 + e) v_n and spin
        5/2 mu (1 + e) v_n/r (rigid-body impulse theory) within 1 %.
    -case settledBed  384 spheres (r 0.9-1.0 x 0.5 mm) dropped in a box
        settle for 0.5 s under gravity; the floor's normal force equals the
        bed's weight within 0.5 % (frictionless walls, particle friction
        0.5, e = 0.5); so does the floor's load from the impulses the
        engine gives each wall face over 100 more steps (0.5 %), and the
        side faces carry nothing along z (1e-12 of the weight).

    -case persistentState  lists persist across steps; a copy with its
        contact records continues bit-identically, a reordered one to
        round-off.
    -case spatialSort  the engine sorting its particles at each list
        build: the particles are found through newIndex; a copy in reverse
        order is bit-identical; sorted equals unsorted to 1e-10 r.

    -case badInput -bad unknownLaw|poissonsRatio|restitution|negativeModulus|
        hugeModulus
        one bad entry must stop construction with a FatalIOError naming
        the keyword (CTest matches the message).

    Failure is a FatalError, so the test's exit status shows it.
*/

#include "argList.H"
#include "unitCheck.H"
#include "IStringStream.H"
#include "demEngine.H"
#include "HertzCollision.H"
#include "mathematicalConstants.H"

using namespace Foam;

namespace
{

using unitTest::check;

const scalar rho = 2500;
const scalar r = 0.5e-3;
const scalar Yp = 5e6;
const scalar nup = 0.22;
const scalar Yw = 5e6;
const scalar nuw = 0.34;


dictionary settings
(
    const word& law,
    const scalar e,
    const scalar mu,
    const scalar muR = 0,
    const scalar muWall = -1
)
{
    OStringStream os;
    os  << "contactLaw " << law << ";"
        << "particleParticle { restitution " << e << "; friction " << mu
        << "; rollingFriction " << muR << "; }"
        << "particleWall { restitution " << e << "; friction "
        << (muWall < 0 ? mu : muWall)
        << "; rollingFriction " << muR << "; }"
        << "linearSpringDashpotCoeffs { kn 7000; kt 2250; gammaN 0.00131;"
        << " gammaT 0.0137; }";
    IStringStream is(os.str());
    return dictionary(is);
}


//- The materials (constant/materialProperties): particles and walls of
//  softened moduli Yp, Yw (demYoungsModulus) and real ones 60, 69 GPa
dictionary materials()
{
    OStringStream os;
    os  << "glass { demYoungsModulus " << Yp << "; youngsModulus 60e9;"
        << " poissonsRatio " << nup << "; }"
        << "steel { demYoungsModulus " << Yw << "; youngsModulus 69e9;"
        << " poissonsRatio " << nuw << "; }"
        << "particle glass;"
        << "walls { \".*\" steel; }";
    IStringStream is(os.str());
    return dictionary(is);
}


//- A square wall face at height z, normal -z (out of the domain above it)
demWalls floor(const scalar halfWidth, const scalar z = 0)
{
    pointField pts
    ({
        point(-halfWidth, -halfWidth, z),
        point(-halfWidth, halfWidth, z),
        point(halfWidth, halfWidth, z),
        point(halfWidth, -halfWidth, z)
    });
    faceList faces(1, face(labelList({0, 1, 2, 3})));
    return demWalls(pts, faces);
}


struct collisionResult
{
    scalar restitution;
    scalar contactTime;
    vector velocity;
    vector angularVelocity;
};


//- Time at which the gap closes and opens again, linearly interpolated
//  between steps (the drift is a straight line); checks on the way that
//  the contact history's duration is the time since the gap closed
class contactClock
{
    scalar t_ = 0;
    scalar gap_ = GREAT;
    scalar start_ = -1;
    scalar end_ = -1;

public:

    void advance(const scalar dt, const scalar gap)
    {
        const scalar t0 = t_;
        t_ += dt;
        if (gap_ > 0 && gap <= 0 && start_ < 0)
        {
            start_ = t0 + dt*gap_/(gap_ - gap);
        }
        if (gap_ <= 0 && gap > 0 && start_ >= 0 && end_ < 0)
        {
            end_ = t0 + dt*gap_/(gap_ - gap);
        }
        gap_ = gap;
    }

    bool ended() const { return end_ >= 0; }
    scalar duration() const { return end_ - start_; }
    scalar time() const { return t_; }
    scalar start() const { return start_; }
};


//- Head-on collision of two equal spheres at approach velocity v
collisionResult headOn(demEngine& dem, const scalar v, const scalar dt)
{
    demParticles& P = dem.resetParticles();
    const scalar gap = 0.01*r;
    P.append(point(-r - gap, 0, 0), vector(0.5*v, 0, 0), Zero, r, rho, 0);
    P.append(point(r + gap, 0, 0), vector(-0.5*v, 0, 0), Zero, r, rho, 1);
    dem.initialise();

    const demParticles& Q = dem.particles();
    contactClock clock;
    scalar history = 0;
    scalar age = 0;
    for (label step = 0; step < 100000 && !clock.ended(); ++step)
    {
        dem.step(dt);
        clock.advance(dt, mag(Q.position[1] - Q.position[0]) - 2*r);
        if (dem.nPairContacts())
        {
            history = dem.pairs().stateOf(0)[dem.durationSlot()];
            age = clock.time() - clock.start();
        }
    }
    check("  history duration = time since the gap closed", history, age, 1e-9);

    return
    {
        (Q.velocity[1].x() - Q.velocity[0].x())/v,
        clock.duration(),
        Q.velocity[0],
        Q.angularVelocity[0]
    };
}


//- A sphere hitting the floor z = 0 with velocity U
collisionResult onWall(demEngine& dem, const vector& U, const scalar dt)
{
    dem.setWalls(floor(100*r));
    demParticles& P = dem.resetParticles();
    P.append(point(0, 0, 1.01*r), U, Zero, r, rho, 0);
    dem.initialise();

    const demParticles& Q = dem.particles();
    contactClock clock;
    scalar history = 0;
    scalar age = 0;
    for (label step = 0; step < 100000 && !clock.ended(); ++step)
    {
        dem.step(dt);
        clock.advance(dt, Q.position[0].z() - r);
        if (dem.nWallContacts())
        {
            history = dem.wallContacts().stateOf(0)[dem.durationSlot()];
            age = clock.time() - clock.start();
        }
    }
    check("  history duration = time since the gap closed", history, age, 1e-9);

    return
    {
        -Q.velocity[0].z()/U.z(),
        clock.duration(),
        Q.velocity[0],
        Q.angularVelocity[0]
    };
}


scalar mass()
{
    return rho*4.0/3.0*constant::mathematical::pi*Foam::pow3(r);
}


void linearAnalytic(const scalar mStar, scalar& e, scalar& tc)
{
    const scalar w02 = 7000/mStar;
    const scalar z = 0.00131/(2*mStar);
    tc = constant::mathematical::pi/Foam::sqrt(w02 - sqr(z));
    e = Foam::exp(-z*tc);
}


void caseHeadOn()
{
    const scalar m = mass();
    const HertzCollision hertz(r, m, Yp, nup);
    const scalar v = 1;
    const scalar tc = hertz.contactTime(v);
    const scalar dt = tc/237;

    {
        demEngine dem(settings("HertzMindlin", 1, 0.5), materials(), 1);
        const collisionResult res = headOn(dem, v, dt);
        check("HertzMindlin e=1 restitution", res.restitution, 1, 0.02);
        check("HertzMindlin e=1 contact time vs eq 5.12", res.contactTime, tc, 0.02);
    }
    for (const scalar e : {0.9, 0.5})
    {
        demEngine dem(settings("HertzMindlin", e, 0.5), materials(), 1);
        const collisionResult res = headOn(dem, v, dt);
        check("HertzMindlin e=" + name(e) + " restitution", res.restitution, e, 0.02);
        Info<< "     contact time / eq 5.12 (elastic): " << res.contactTime/tc << nl;
    }
    {
        scalar e, tcLin;
        linearAnalytic(0.5*m, e, tcLin);
        demEngine dem(settings("linearSpringDashpot", 1, 0.5), materials(), 1);
        const collisionResult res = headOn(dem, v, tcLin/237);
        check("linear restitution", res.restitution, e, 0.02);
        check("linear contact time", res.contactTime, tcLin, 0.02);
    }
}


void caseWall()
{
    const scalar m = mass();
    const scalar v = 1;

    // Wall: r* = r, m* = m, Y* from particle and wall
    const scalar YStar =
        1/((1 - sqr(nup))/Yp + (1 - sqr(nuw))/Yw);
    const scalar tc = 2.868*Foam::pow(sqr(m)/(r*sqr(YStar)*v), 0.2);
    const scalar dt = tc/237;

    {
        demEngine dem(settings("HertzMindlin", 1, 0.5), materials(), 1);
        const collisionResult res = onWall(dem, vector(0, 0, -v), dt);
        check("wall HertzMindlin e=1 restitution", res.restitution, 1, 0.02);
        check("wall HertzMindlin e=1 contact time vs eq 5.12", res.contactTime, tc, 0.02);
    }
    for (const scalar e : {0.9, 0.5})
    {
        demEngine dem(settings("HertzMindlin", e, 0.5), materials(), 1);
        const collisionResult res = onWall(dem, vector(0, 0, -v), dt);
        check("wall HertzMindlin e=" + name(e) + " restitution", res.restitution, e, 0.02);
    }
    {
        scalar e, tcLin;
        linearAnalytic(m, e, tcLin);
        demEngine dem(settings("linearSpringDashpot", 1, 0.5), materials(), 1);
        const collisionResult res = onWall(dem, vector(0, 0, -v), tcLin/237);
        check("wall linear restitution", res.restitution, e, 0.02);
        check("wall linear contact time", res.contactTime, tcLin, 0.02);
    }
}


void caseOblique()
{
    const scalar m = mass();
    const HertzCollision hertz(r, m, Yp, nup);
    const scalar vn = 0.5;
    const scalar dt = hertz.contactTime(vn)/400;
    const scalar e = 0.9;
    const scalar mu = 0.1;

    for (const scalar vt : {2.0, 4.0})
    {
        demEngine dem(settings("HertzMindlin", e, mu), materials(), 1);
        const collisionResult res = onWall(dem, vector(vt, 0, -vn), dt);
        check
        (
            "sliding impact v_t=" + name(vt) + " rebound tangential velocity",
            res.velocity.x(), vt - mu*(1 + e)*vn, 0.01
        );
        check
        (
            "sliding impact v_t=" + name(vt) + " spin",
            res.angularVelocity.y(), 2.5*mu*(1 + e)*vn/r, 0.01
        );
    }
}


//- A box of frictionless walls (the floor is face 0, normals out of the
//  box) holding nLayers staggered layers of nSide x nSide spheres of radii
//  0.9-1.0 r, at rest under gravity; the time step and the bed's weight
scalar fillBox
(
    demEngine& dem,
    const label nSide,
    const label nLayers,
    scalar& weight
)
{
    const scalar g = 9.81;
    const scalar half = nSide*r*1.05;

    const scalar H = 40*r;
    pointField pts
    ({
        point(-half, -half, 0), point(half, -half, 0),
        point(half, half, 0), point(-half, half, 0),
        point(-half, -half, H), point(half, -half, H),
        point(half, half, H), point(-half, half, H)
    });
    faceList faces
    ({
        face(labelList({0, 3, 2, 1})),
        face(labelList({0, 1, 5, 4})),
        face(labelList({1, 2, 6, 5})),
        face(labelList({2, 3, 7, 6})),
        face(labelList({3, 0, 4, 7}))
    });
    dem.setWalls(demWalls(pts, faces));

    demParticles& P = dem.resetParticles();
    label id = 0;
    weight = 0;
    for (label k = 0; k < nLayers; ++k)
    {
        for (label j = 0; j < nSide; ++j)
        {
            for (label i = 0; i < nSide; ++i)
            {
                // Slightly staggered lattice, a little under r apart
                const scalar ri = r*(0.9 + 0.1*((i + 2*j + 3*k) % 3)/2);
                const point x
                (
                    -half + r*1.05*(2*i + 1) + 0.05*r*(k % 2),
                    -half + r*1.05*(2*j + 1) - 0.05*r*(k % 2),
                    r*1.1*(2*k + 1)
                );
                const label p = P.append(x, Zero, Zero, ri, rho, id++);
                P.externalForce[p] = vector(0, 0, -g*P.mass(p));
                weight += g*P.mass(p);
            }
        }
    }

    const HertzCollision hertz(r, mass(), Yp, nup);
    return hertz.contactTime(0.1)/50;
}


void caseSettledBed()
{
    // Frictionless walls, so that the side walls cannot carry weight
    demEngine dem(settings("HertzMindlin", 0.5, 0.5, 0, 0), materials(), 1);
    scalar weight;
    const scalar dt = fillBox(dem, 8, 6, weight);
    const demParticles& P = dem.particles();
    dem.initialise();

    // Settle for 0.5 s
    const label nSteps = label(0.5/dt);
    for (label step = 0; step < nSteps; ++step)
    {
        dem.step(dt);
    }

    // The contact forces of the pairs cancel, and the frictionless side
    // walls push horizontally: the vertical sum of all contact forces on
    // the particles is what the floor carries
    scalar floorForce = 0;
    scalar kinetic = 0;
    forAll(P.velocity, i)
    {
        floorForce += P.force[i].z();
        kinetic += 0.5*P.mass(i)*magSqr(P.velocity[i]);
    }
    Info<< "     " << P.size() << " particles, " << dem.nPairContacts()
        << " pair contacts, " << dem.nWallContacts() << " wall contacts, "
        << "kinetic energy " << kinetic << " J after " << nSteps
        << " steps (" << dem.nBuilds() << " list builds)" << nl;
    check("settled bed floor force vs weight", floorForce, weight, 0.005);

    // The walls' own account over 100 more steps: the impulse the contacts
    // gave each face over the time is the load on it; the floor (face 0)
    // carries the weight downwards, the frictionless side faces nothing
    // along z
    const label nMore = 100;
    dem.beginStep();
    dem.advance(dt, nMore);
    const List<vector>& J = dem.wallFaceImpulse();
    scalar sideLoad = 0;
    for (label f = 1; f < J.size(); ++f)
    {
        sideLoad += mag(J[f].z())/(nMore*dt);
    }
    check("floor load from the wall impulses vs weight",
        -J[0].z()/(nMore*dt), weight, 0.005);
    check("side faces' vertical load vs weight (frictionless: 0)",
        sideLoad/weight, 0, 1e-12);
}


//- A box of 6 x 6 x 3 spheres (fillBox) settled for 20,000 steps; the
//  step [s]
scalar settledBox(demEngine& dem, scalar& weight)
{
    const scalar dt = fillBox(dem, 6, 3, weight);
    dem.initialise();
    for (label step = 0; step < 20000; ++step)
    {
        dem.step(dt);
    }
    return dt;
}


//- The order n - 1, ..., 0
labelList reversedOrder(const label n)
{
    labelList order(n);
    forAll(order, k)
    {
        order[k] = n - 1 - k;
    }
    return order;
}


//- 2000 steps with a sideways push on every particle (half the bed's
//  weight in all)
void shake(demEngine& dem, const scalar weight, const scalar dt)
{
    demParticles& P = dem.particles();
    const label n = P.size();
    forAll(P.externalForce, i)
    {
        P.externalForce[i].x() += 0.5*weight/n;
    }
    for (label step = 0; step < 2000; ++step)
    {
        dem.step(dt);
    }
}


//- Copy the particles of one engine into another (a restart): the state
//  the cloud keeps on its parcels, in the given order, and the contacts
//  as records
void copyParticles
(
    const demEngine& from,
    demEngine& to,
    const labelList& order
)
{
    const demParticles& A = from.particles();
    demParticles& B = to.resetParticles();
    B.resize(order.size());
    forAll(order, k)
    {
        const label i = order[k];
        B.position[k] = A.position[i];
        B.velocity[k] = A.velocity[i];
        B.angularVelocity[k] = A.angularVelocity[i];
        B.force[k] = A.force[i];
        B.torque[k] = A.torque[i];
        B.radius[k] = A.radius[i];
        B.invMass[k] = A.invMass[i];
        B.invInertia[k] = A.invInertia[i];
        B.externalForce[k] = A.externalForce[i];
        B.identity[k] = A.identity[i];
    }
    contactRecords records;
    forAll(order, k)
    {
        from.recordsOf(order[k], records);
        to.addRecords(k, records);
    }
}


//- Largest distance between the positions of the same particles (by
//  identity) of two engines [m]
scalar largestDifference(const demEngine& a, const demEngine& b)
{
    const demParticles& A = a.particles();
    const demParticles& B = b.particles();
    scalar d = 0;
    forAll(A.position, i)
    {
        forAll(B.position, k)
        {
            if (B.identity[k] == A.identity[i])
            {
                d = max(d, mag(A.position[i] - B.position[k]));
            }
        }
    }
    return d;
}


//- The engine's state across CFD steps: the lists persist while nothing
//  moves far; a copy of the particles with their contact records (a
//  restart) continues bit-identically once the original rebuilds its
//  lists too (as the cloud does at each write); a reordered copy continues
//  to round-off (1e-10 r after 2000 steps); every touching contact is
//  carried
void casePersistentState()
{
    const dictionary dict(settings("HertzMindlin", 0.5, 0.5));
    demEngine a(dict, materials(), 1);
    scalar weight;
    const scalar dt = settledBox(a, weight);

    // Settled: CFD steps of 10 sub-steps, lists rebuilt only on demand
    const label builds0 = a.nBuilds();
    for (label cfd = 0; cfd < 20; ++cfd)
    {
        a.beginStep();
        for (label k = 0; k < 10; ++k)
        {
            a.step(dt);
        }
    }
    Info<< "     settled bed of " << a.particles().size() << ": "
        << a.nPairContacts() << " pair and " << a.nWallContacts()
        << " wall contacts; " << a.nBuilds() - builds0
        << " list builds in 20 CFD steps" << nl;
    check("list builds in 20 settled CFD steps", a.nBuilds() - builds0, 0, 0);

    // The candidate pairs are exactly the pairs within the skin (brute
    // force over all pairs; the engine's skin is 0.1 of the largest
    // diameter)
    {
        const demParticles& P = a.particles();
        scalar rMax = 0;
        forAll(P.radius, i)
        {
            rMax = max(rMax, P.radius[i]);
        }
        const scalar skin = 0.1*2*rMax;
        label expected = 0;
        forAll(P.position, i)
        {
            for (label j = i + 1; j < P.size(); ++j)
            {
                const scalar range = P.radius[i] + P.radius[j] + skin;
                expected += magSqr(P.position[i] - P.position[j]) < range*range;
            }
        }
        a.invalidateLists();
        a.beginStep();
        label unique = 0;
        const contactList& C = a.pairs();
        for (label k = 0; k < C.size(); ++k)
        {
            bool seen = false;
            for (label q = 0; q < k && !seen; ++q)
            {
                seen = C.first[q] == C.first[k] && C.second[q] == C.second[k];
            }
            unique += !seen && C.first[k] < C.second[k];
        }
        check("candidate pairs against all pairs within the skin", unique, expected, 0);
        check("candidate pairs listed once", C.size(), expected, 0);
    }

    // A particle leaves (another processor takes it): each of its partners
    // that stays keeps the contact, from its own side
    {
        demEngine e(dict, materials(), 1);
        e.setWalls(a.walls());
        copyParticles(a, e, identity(a.particles().size()));
        e.beginStep();
        const contactList& C = e.pairs();
        label k = 0;
        while (k < C.size() && C.stateOf(k)[e.durationSlot()] <= 0)
        {
            ++k;
        }
        const label first = C.first[k];
        const label second = C.second[k];
        const demIdentity idFirst = e.particles().identity[first];
        const vector spring
        (
            C.stateOf(k)[e.law().springSlot()],
            C.stateOf(k)[e.law().springSlot() + 1],
            C.stateOf(k)[e.law().springSlot() + 2]
        );

        // All but the first particle of that pair stay
        labelList stay(e.particles().size() - 1);
        label n = 0;
        forAll(e.particles().position, i)
        {
            if (i != first)
            {
                stay[n++] = i;
            }
        }
        e.reorder(stay);
        const label partner = second - (second > first);
        contactRecords kept;
        e.recordsOf(partner, kept);
        label found = -1;
        forAll(kept.partner, r)
        {
            if (kept.partner[r] == idFirst)
            {
                found = r;
            }
        }
        check("the partner keeps the contact of the particle that left", found >= 0, 1, 0);
        if (found >= 0)
        {
            const scalar* b = kept.stateOf(found);
            const label o = e.law().springSlot();
            check
            (
                "its spring, seen from its side (minus the other's) [m]",
                mag(vector(b[o], b[o + 1], b[o + 2]) + spring),
                0,
                0
            );
            check("the spring is not zero", mag(spring) > 0, 1, 0);
        }
    }

    // A restart: same order, contacts as records
    const label n = a.particles().size();
    labelList same(identity(n));
    const labelList reversed(reversedOrder(n));
    demEngine b(dict, materials(), 1);
    demEngine c(dict, materials(), 1);
    b.setWalls(a.walls());
    c.setWalls(a.walls());
    copyParticles(a, b, same);
    copyParticles(a, c, reversed);

    a.invalidateLists();
    a.beginStep();
    b.beginStep();
    c.beginStep();
    check("pair contacts carried", b.nPairContacts(), a.nPairContacts(), 0);
    check("wall contacts carried", b.nWallContacts(), a.nWallContacts(), 0);
    check
    (
        "pair contacts carried in reverse order",
        c.nPairContacts(), a.nPairContacts(), 0
    );

    // Shaken: 2000 steps with a sideways push on every particle
    for (demEngine* e : {&a, &b, &c})
    {
        shake(*e, weight, dt);
    }
    check("restart copy: largest position difference [m]", largestDifference(a, b), 0, 0);
    const scalar dc = largestDifference(a, c);
    Info<< "     reordered copy: largest position difference " << dc
        << " m after 2000 steps" << nl;
    // Round-off: the forces on a particle are summed in another order
    check("reordered copy within 1e-10 r", dc < 1e-10*r, 1, 0);
}


//- The engine sorting its particles by position at each list build (as
//  the cloud has it): the owner follows each particle through newIndex;
//  the result does not depend on the order the particles came in (a copy
//  in reverse order is bit-identical: a restart sorts as the continuous
//  run does), and it equals the unsorted engine's to round-off (1e-10 r
//  after 2000 steps)
void caseSpatialSort()
{
    const dictionary dict(settings("HertzMindlin", 0.5, 0.5));
    demEngine a(dict, materials(), 1);
    scalar weight;
    const scalar dt = settledBox(a, weight);

    const label n = a.particles().size();
    const labelList reversed(reversedOrder(n));
    demEngine b(dict, materials(), 1);
    demEngine c(dict, materials(), 1);
    for (demEngine* e : {&b, &c})
    {
        e->setWalls(a.walls());
        e->setSpatialSort(true);
    }
    copyParticles(a, b, identity(n));
    copyParticles(a, c, reversed);

    const List<demIdentity> before(b.particles().identity);
    a.invalidateLists();
    a.beginStep();
    b.beginStep();
    c.beginStep();

    check("the sorting engine moved its particles", b.moved(), 1, 0);
    label lost = 0;
    forAll(before, k)
    {
        lost += b.particles().identity[b.newIndex()[k]] != before[k];
    }
    check("particles found through newIndex", lost, 0, 0);
    label sameOrder = 0;
    for (label k = 0; k < n; ++k)
    {
        sameOrder +=
            b.particles().identity[k] == c.particles().identity[k];
    }
    check("both copies in the same order", sameOrder, n, 0);
    check("pair contacts carried", b.nPairContacts(), a.nPairContacts(), 0);
    check("wall contacts carried", b.nWallContacts(), a.nWallContacts(), 0);

    for (demEngine* e : {&a, &b, &c})
    {
        shake(*e, weight, dt);
    }
    check
    (
        "copy in reverse order: largest position difference [m]",
        largestDifference(b, c), 0, 0
    );
    const scalar d = largestDifference(a, b);
    Info<< "     sorted against unsorted: largest position difference " << d
        << " m after 2000 steps" << nl;
    check("sorted within 1e-10 r of unsorted", d < 1e-10*r, 1, 0);
}


//- Construct the engine from settings with one bad entry: must be fatal
void caseBadInput(const word& what)
{
    dictionary dict(settings("HertzMindlin", 0.9, 0.5));
    dictionary mats(materials());
    if (what == "unknownLaw")
    {
        dict.set("contactLaw", word("Hooke"));
    }
    else if (what == "poissonsRatio")
    {
        mats.subDict("glass").set("poissonsRatio", 0.6);
    }
    else if (what == "restitution")
    {
        dict.subDict("particleWall").set("restitution", 1.2);
    }
    else if (what == "negativeModulus")
    {
        mats.subDict("steel").set("youngsModulus", -5e6);
    }
    else if (what == "hugeModulus")
    {
        // its contact time overflowed (a floating-point trap)
        mats.subDict("glass").set("demYoungsModulus", 1e300);
    }
    else
    {
        FatalErrorInFunction << "Unknown -bad " << what << exit(FatalError);
    }
    demEngine dem(dict, mats, 1);
    FatalErrorInFunction
        << "bad input " << what << " was accepted" << exit(FatalError);
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote("DEM engine against analytic collisions");
    argList::noParallel();
    argList::noCheckProcessorDirectories();
    argList::addOption
    (
        "case", "name",
        "headOn|wall|oblique|settledBed|persistentState|spatialSort|badInput"
    );
    argList::addOption
    (
        "bad", "entry",
        "with -case badInput: unknownLaw|poissonsRatio|restitution"
        "|negativeModulus"
    );
    argList args(argc, argv);

    const word which(args.get<word>("case"));

    if (which == "headOn") caseHeadOn();
    else if (which == "wall") caseWall();
    else if (which == "oblique") caseOblique();
    else if (which == "settledBed") caseSettledBed();
    else if (which == "persistentState") casePersistentState();
    else if (which == "spatialSort") caseSpatialSort();
    else if (which == "badInput") caseBadInput(args.get<word>("bad"));
    else
    {
        FatalErrorInFunction
            << "Unknown -case " << which
            << ". Valid: headOn wall oblique settledBed persistentState"
            << " spatialSort"
            << exit(FatalError);
    }

    if (unitTest::nFailed())
    {
        FatalErrorInFunction << "Test-demCollision -case " << which
            << " failed" << exit(FatalError);
    }

    Info<< "End" << nl;
    return 0;
}
