// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    Test-bedThermal

Description
    The bed quantities of the thermal wall condition:

    - ZehnerSchlunder (eq 4.19-4.24): with k_s = k_f (A = 1) the bed
      conducts as the gas, k_b = k_f, relative 1e-12; k_b and k_s_mol for
      glass in N2 (k_f 0.026, k_s 1.4) and for an oxide in hot N2 (k_f 0.07,
      k_s 5) at voidages 0.4, 0.6, 0.9 against values computed by hand
      (Python, 40-digit decimals), relative 1e-12; the kinetic conductivity
      (eq 4.24) of 1 mm glass at Theta = 1e-4 m^2/s^2, relative 1e-14; each
      solidContribution adds its term; no solids (eps = 1) gives k_f;
      continuous where A = B (within 1e-3 of its neighbours at
      B = A (1 +- 1e-3));
    - granularTemperature (eq 4.37-4.38): two opposite velocities (1/3),
      one particle (0), an empty cell (0), three particles on a common
      velocity of 1000 m/s (14/27 exactly, relative 1e-9: the mean removed
      first keeps the fluctuation).

    Run with -bad solidContribution to check its bad-input error.
*/

#include "argList.H"
#include "unitCheck.H"
#include "ZehnerSchlunder.H"
#include "granularTemperature.H"
#include "IOstreams.H"
#include "mathematicalConstants.H"

using namespace Foam;

using unitTest::check;


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList::addOption("bad", "key", "report the error of a bad key");
    argList args(argc, argv);

    if (args.found("bad"))
    {
        dictionary dict;
        dict.add("solidContribution", "kinetic");
        ZehnerSchlunder law(dict);
        return 0;
    }

    Info().precision(15);

    dictionary dict;
    const ZehnerSchlunder full(dict);
    dict.add("solidContribution", "molecular");
    const ZehnerSchlunder molecular(dict);
    dict.set("solidContribution", "none");
    const ZehnerSchlunder none(dict);

    // Equal conductivities: the bed is the gas
    for (const scalar eps : {0.36, 0.45, 0.7, 0.95})
    {
        check
        (
            "k_b with k_s = k_f at eps " + Foam::name(eps),
            molecular.bed(eps, 0.03, 0.03, 0),
            0.03,
            1e-12
        );
    }

    // Hand values: {eps, k_f, k_s, k_b (molecular), k_s_mol}
    const scalar hand[6][5] =
    {
        {0.4, 0.026, 1.4, 1.95877136725784661841e-01, 3.16694416876772077973e-01},
        {0.4, 0.07,  5,   5.84258852836182729362e-01, 9.47467699471810975709e-01},
        {0.6, 0.026, 1.4, 1.05527806581359795413e-01, 2.39929126035588413668e-01},
        {0.6, 0.07,  5,   3.08163059296179597801e-01, 7.06087366346342282242e-01},
        {0.9, 0.026, 1.4, 3.74118911647852367408e-02, 1.96338130812230227118e-01},
        {0.9, 0.07,  5,   1.04953831013324797028e-01, 5.70897746345034429183e-01}
    };
    for (const auto& row : hand)
    {
        const scalar eps = row[0], kf = row[1], ks = row[2];
        const std::string at =
            " at eps " + Foam::name(eps) + ", k_f " + Foam::name(kf)
          + ", k_s " + Foam::name(ks);
        check
        (
            "k_s_mol" + at,
            ZehnerSchlunder::solidMolecular(eps, kf, ks),
            row[4],
            1e-12
        );
        check("k_b (molecular)" + at, molecular.bed(eps, kf, ks, 0), row[3], 1e-12);

        const scalar gas = (1 - std::sqrt(1 - eps))*kf;
        check("k_b (none)" + at, none.bed(eps, kf, ks, 7), gas, 1e-12);
        check
        (
            "k_b (molecularAndKinetic, k_s_kin 2)" + at,
            full.bed(eps, kf, ks, 2),
            row[3] + (1 - eps)*2,
            1e-12
        );
    }

    // Kinetic conductivity of 1 mm glass (2500 kg/m^3, 840 J/(kg K))
    check
    (
        "k_s_kin of 1 mm glass at Theta 1e-4",
        ZehnerSchlunder::solidKinetic(2500, 840, 1e-3, 1e-4),
        2.32634567931348978931,
        1e-14
    );

    // No solids
    check("k_b at eps = 1", full.bed(1, 0.026, 1.4, 3), 0.026, 1e-14);

    // Where A = B: eps with 1.25 ((1 - eps)/eps)^(10/9) = A = 5
    {
        const scalar A = 5;
        const scalar q = std::pow(A/1.25, 0.9);
        const scalar eps = 1/(1 + q);
        const scalar kf = 0.1;
        const scalar at = ZehnerSchlunder::solidMolecular(eps, kf, A*kf);
        for (const scalar f : {1 - 1e-3, 1 + 1e-3})
        {
            check
            (
                "k_s_mol where A = B, against A = " + Foam::name(f) + " B",
                at,
                ZehnerSchlunder::solidMolecular(eps, kf, f*A*kf),
                1e-3
            );
        }
    }

    // Granular temperature
    {
        const labelList cell({0, 0, 1, 2, 2, 2});
        const List<vector> U
        ({
            vector(1, 0, 0), vector(-1, 0, 0),
            vector(3, 4, 5),
            vector(1001, 0, 0), vector(999, 0, 0), vector(1000, 2, 0)
        });
        const scalarField Theta(granularTemperature::cells(4, cell, U));
        check("Theta of two opposite velocities", Theta[0], 1.0/3, 1e-14);
        check("Theta of one particle", Theta[1], 0, 0);
        check("Theta of three on a common 1000 m/s", Theta[2], 14.0/27, 1e-9);
        check("Theta of an empty cell", Theta[3], 0, 0);
    }

    Info<< nl << (unitTest::nFailed() ? "FAILED: " : "passed: ")
        << unitTest::nFailed() << " failed check(s)" << endl;
    return unitTest::nFailed() ? 1 : 0;
}
