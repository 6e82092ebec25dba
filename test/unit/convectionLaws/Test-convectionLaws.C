// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    Test-convectionLaws

Description
    The particle-fluid convection laws of src/sinterPhysics/heatTransfer
    against values computed by hand (a separate Python evaluation of eq 4.8
    and of Ranz-Marshall, 15 significant digits), relative tolerance 1e-12:
    Gunn at six (eps, Re, Pr) points from packed (0.4) to free (1, Re = 0,
    where Nu = 2), Ranz-Marshall at three.

    Coarse graining (convectionLaw::parcelConductance): a parcel of
    diameter K d_p has K^3 times the conductance h A of one primary of
    diameter d_p at the same slip and voidage (K = 2, 4, 6, 16, both laws),
    so its temperature changes at the primary's rate h A/(m c_p)
    (relative 1e-12); and the primary's conductance is the law's
    Nu k_f pi d_p (Re formed with d_p and eps, eq 4.9).

    Run with -law NAME -bad to check the selection error instead.
*/

#include "argList.H"
#include "unitCheck.H"
#include "convectionLaw.H"
#include "mathematicalConstants.H"
#include "IOstreams.H"

using namespace Foam;

using unitTest::check;


autoPtr<convectionLaw> law(const word& name)
{
    dictionary dict;
    dict.add("law", name);
    return convectionLaw::New(dict);
}


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList::addOption("law", "name", "select only this law (with -bad)");
    argList::addBoolOption("bad", "select -law and report the error");
    argList args(argc, argv);

    if (args.found("bad"))
    {
        law(args.get<word>("law"));
        return 0;
    }

    Info().precision(15);

    // Gunn, eq 4.8: (eps, Re, Pr) and the hand-computed Nu
    {
        autoPtr<convectionLaw> gunn(law("Gunn"));
        const scalar points[][4] =
        {
            {0.4, 10, 0.7, 10.0441743660924},
            {0.45, 0.5, 0.72, 5.70295981685893},
            {0.6, 50, 0.7, 11.026338407008},
            {0.8, 200, 0.69, 12.5448968694443},
            {0.95, 1000, 0.71, 21.953028693929},
            {1.0, 0, 0.7, 2}
        };
        for (const auto& pt : points)
        {
            check
            (
                "Gunn Nu(eps " + Foam::name(pt[0]) + ", Re "
              + Foam::name(pt[1]) + ", Pr " + Foam::name(pt[2]) + ")",
                gunn->Nu(pt[0], pt[1], pt[2]),
                pt[3],
                1e-12
            );
        }
    }

    // Ranz-Marshall: (Re, Pr) and Nu
    {
        autoPtr<convectionLaw> rm(law("RanzMarshall"));
        const scalar points[][3] =
        {
            {0, 0.7, 2},
            {100, 0.7, 7.3274240104556},
            {12.5, 0.72, 3.90129901131929}
        };
        for (const auto& pt : points)
        {
            check
            (
                "RanzMarshall Nu(Re " + Foam::name(pt[0]) + ", Pr "
              + Foam::name(pt[1]) + ")",
                rm->Nu(0.5, pt[0], pt[1]),
                pt[2],
                1e-12
            );
        }
    }

    // Coarse graining: N2 at 1000 K, a 58 micron primary of hematite
    const scalar rho = 0.3369, mu = 4.16e-5, kappa = 0.0647, Pr = 0.72;
    const scalar dp = 58e-6, rhoP = 5240, cp = 650;
    const scalar eps = 0.47, slip = 0.12;
    const scalar pi = constant::mathematical::pi;
    for (const word name : {"Gunn", "RanzMarshall"})
    {
        autoPtr<convectionLaw> l(law(name));

        const scalar Re = eps*rho*dp*slip/mu;
        const scalar hAPrimary = l->Nu(eps, Re, Pr)*kappa/dp*pi*dp*dp;
        check
        (
            name + ": conductance of a primary (K = 1) = Nu k_f pi d_p",
            l->parcelConductance(1, dp, eps, slip, rho, mu, kappa, Pr),
            hAPrimary,
            1e-12
        );

        const scalar mPrimary = rhoP*pi/6*pow3(dp);
        for (const scalar K : {2.0, 4.0, 6.0, 16.0})
        {
            const scalar d = K*dp;
            const scalar hA =
                l->parcelConductance(K, d, eps, slip, rho, mu, kappa, Pr);
            check
            (
                name + ": parcel of K = " + Foam::name(K)
              + " exchanges K^3 primaries' heat",
                hA,
                pow3(K)*hAPrimary,
                1e-12
            );
            const scalar mParcel = rhoP*pi/6*pow3(d);
            check
            (
                name + ": parcel of K = " + Foam::name(K)
              + " heats at the primary's rate h A/(m c_p)",
                hA/(mParcel*cp),
                hAPrimary/(mPrimary*cp),
                1e-12
            );
        }
    }

    Info<< nl << (unitTest::nFailed() ? "FAILED: " : "passed: ") << unitTest::nFailed()
        << " failed check(s)" << endl;
    return unitTest::nFailed() ? 1 : 0;
}
