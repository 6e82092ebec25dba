// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    Test-sinterPhysics

Description
    The Chapter 2 laws of libsinterPhysics against values computed by hand
    (an independent evaluation of the formulas, 11 significant digits) for
    two identical hematite spheres of the tiny powder (Table 2.4: rho 5240
    kg/m^3, Y 359 GPa, nu 0.12; d = 33.7 um):

        m  = rho pi d^3/6                  = 1.0500732903e-10 kg
        r* = d/4 = 8.425e-6 m,  m* = m/2,  Y* = Y/(2 (1 - nu^2)) = 1.8212256494e11 Pa

        v_n [m/s]   delta_max [m] (2.7)  k_n [N/m] (2.6)  F_n [N] (2.5)    t_c [s] (2.11)
        1e-4        1.5402984270e-11     2.7662401814e3   4.2608354001e-8  4.5331021780e-7
        5e-4        5.5818848795e-11     5.2659640167e3   2.9394004921e-7  3.2855002720e-7

    Surface diffusion (2.3), R = 8.314462618 J/(mol K):
        D_s(867.15 K)  = 2.8e-13 exp(-1.74e5/(R T)) = 9.2491006381e-24 m^2/s
        D_s(1266.15 K) = 1.6e5 exp(-5.79e5/(R T))   = 2.0802442743e-19 m^2/s
    Neck radius (2.2), gamma 1 N/m, delta 1.38e-9 m, a = r_p, t = t_c(1e-4),
    k_B = 1.380649e-23 J/K, T = 867.15 K:     x = 6.1696457339e-9 m
    Solid bridge per strength (2.4), C = 1.251: F/sigma = 1.4959863704e-16 m^2

    Neck growth rate G = d(x^7)/dt = 56 gamma delta^4 D_s a^3/(k_B T):
        G(a 16.85 um, 973.15 K) = 9.2679974548e-51 m^7/s
        G(a 1 um, 1273.15 K)    = 3.2522600306e-51 m^7/s
    C 0.8 given as a value, curvatureRadius 1 um, T = 1273.15 K, t = 0.01 s:
        F_sb = C pi sigma(T) (G t)^(2/7) = 6.0274284848e-7 N

    Tolerance 1e-9 relative (the hand values carry 11 digits).
    Also: bridge force = sigma(T) F/sigma; C of the three surface models.
*/

#include "argList.H"
#include "IStringStream.H"
#include "sinterMaterial.H"
#include "solidBridge.H"
#include "HertzCollision.H"
#include "mathematicalConstants.H"

using namespace Foam;

namespace
{
bool ok = true;

void check(const char* what, const scalar value, const scalar reference)
{
    const scalar rel = mag(value - reference)/mag(reference);
    const bool pass = rel <= 1e-9;
    Info<< (pass ? "ok   " : "FAIL ") << what << ": " << value
        << " (hand " << reference << ", relative difference " << rel << ")"
        << nl;
    ok = ok && pass;
}
}


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList args(argc, argv);
    Info().precision(11);

    const dictionary hematiteDict
    (
        IStringStream
        (
            "density 5240; youngsModulus 359e9; poissonsRatio 0.12;"
            "surfaceTension 1; latticeConstant 1.38e-9;"
            "surfaceDiffusion ((1173.15 2.8e-13 1.74e5) (1e30 1.6e5 5.79e5));"
            "tensileStrength polynomial ((4e8 0) (-100 2));"
        )()
    );
    const sinterMaterial hematite(hematiteDict);

    const scalar d = 33.7e-6;
    const scalar m = hematite.rho()*constant::mathematical::pi/6*pow3(d);
    check("m [kg]", m, 1.0500732903e-10);

    const HertzCollision hertz(d/2, m, hematite.Y(), hematite.nu());
    check("r* [m]", hertz.rStar(), 8.425e-6);
    check("m* [kg]", hertz.mStar(), 5.2503664517e-11);
    check("Y* [Pa]", hertz.YStar(), 1.8212256494e11);

    check("delta_max(1e-4) [m]", hertz.maxOverlap(1e-4), 1.5402984270e-11);
    check("k_n(1e-4) [N/m]", hertz.stiffness(1e-4), 2.7662401814e3);
    check("F_n(1e-4) [N]", hertz.maxNormalForce(1e-4), 4.2608354001e-8);
    check("t_c(1e-4) [s]", hertz.contactTime(1e-4), 4.5331021780e-7);
    check("delta_max(5e-4) [m]", hertz.maxOverlap(5e-4), 5.5818848795e-11);
    check("k_n(5e-4) [N/m]", hertz.stiffness(5e-4), 5.2659640167e3);
    check("F_n(5e-4) [N]", hertz.maxNormalForce(5e-4), 2.9394004921e-7);
    check("t_c(5e-4) [s]", hertz.contactTime(5e-4), 3.2855002720e-7);

    check("D_s(867.15 K) [m^2/s]", hematite.Ds(867.15), 9.2491006381e-24);
    check("D_s(1266.15 K) [m^2/s]", hematite.Ds(1266.15), 2.0802442743e-19);

    const solidBridge nine(hematite, solidBridge::surfaceModel::nineMicroContacts);
    const scalar tc = hertz.contactTime(1e-4);
    check("x(867.15 K) [m]", nine.neckRadius(d/2, 867.15, tc), 6.1696457339e-9);
    check
    (
        "F_sb/sigma (C 1.251) [m^2]",
        nine.forcePerStrength(d/2, 867.15, tc),
        1.4959863704e-16
    );
    check
    (
        "F_sb [N] = sigma(T) F_sb/sigma",
        nine.force(d/2, 867.15, tc),
        (4e8 - 100*sqr(867.15))*1.4959863704e-16
    );

    // Neck growth in time; C by value; a roughness length as curvature radius
    check("G(16.85 um, 973.15 K) [m^7/s]", nine.neckGrowthRate(d/2, 973.15), 9.2679974548e-51);
    check("G(1 um, 1273.15 K) [m^7/s]", nine.neckGrowthRate(1e-6, 1273.15), 3.2522600306e-51);
    check
    (
        "F_sb from x^7 = G t equals F_sb(t)",
        nine.forceFromNeck(nine.neckGrowthRate(d/2, 867.15)*tc, 867.15),
        nine.force(d/2, 867.15, tc)
    );
    {
        const solidBridge rough
        (
            hematite,
            dictionary(IStringStream("C 0.8; curvatureRadius 1e-6;")())
        );
        check("C by value", rough.C(), 0.8);
        check("F_sb(C 0.8, a 1 um, 1273.15 K, 0.01 s) [N]", rough.force(d/2, 1273.15, 0.01), 6.0274284848e-7);
        const solidBridge named
        (
            hematite,
            dictionary(IStringStream("C smooth; curvatureRadius particleRadius;")())
        );
        check("C by name (smooth)", named.C(), 1);
        check("curvature radius = particle radius", named.curvatureRadius(d/2), d/2);
    }

    check("C threeMicroContacts", solidBridge::coefficient(solidBridge::surfaceModel::threeMicroContacts), 0.417);
    check("C smooth", solidBridge::coefficient(solidBridge::surfaceModel::smooth), 1);
    check("C nineMicroContacts", solidBridge::coefficient(solidBridge::surfaceModel::nineMicroContacts), 1.251);

    if (!ok)
    {
        FatalErrorInFunction << "FAIL" << exit(FatalError);
    }
    Info<< "PASS" << endl;
    return 0;
}
