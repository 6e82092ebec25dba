// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    Test-conductionLaws

Description
    The conduction laws of src/sinterPhysics/heatTransfer/conduction:

    - contact radii (conductionGeometry): a sphere on a wall against
      sqrt(delta (2 r - delta)) (eq 4.26), two equal spheres against
      sqrt(r delta - delta^2/4), a sphere against a very large one against
      the wall's, zero and negative overlaps give 0; relative 1e-12
      (1e-5 for the large sphere);
    - Batchelor-O'Brien (eq 4.25) for App. B's 1 mm glass particle on
      aluminium at overlaps 0.002-0.02 r_p, with the thermal overlap
      c = (Y* / Y*_0)^(2/3) of Table 4.2, against values computed by hand
      (Python, 40-digit decimals), relative 1e-12;
    - Rong-Horio (eq 4.31-4.36): the closed form against a quadrature of
      eq 4.31 (Simpson, split at r_s) in all five cases of Fig 4.2,
      relative 1e-8; zero outside the lens; continuous where the cases
      meet (gap = s, gap = 0), relative 1e-9; two equal particles against
      a quadrature of the gas between them (2 l thick, at least s),
      relative 1e-8, unequal ones as the equal pair of the same r*;
    - lensSolidSeries (the lens with the particle's solid in series): the
      closed form against a quadrature of its integral at k_s/k_f = 54
      (glass in air), 5, 1.0005 (its series branch) and 0.5, from a gap of
      0.15 r_p to an overlap (inside the lens of 1.2 r_p), relative 1e-8;
      zero beyond the lens (gaps 0.2 and 0.3 r_p); k_s = k_f against the slab
      (r_out^2 - r_in^2)/(2 D), relative 1e-12; k_s -> infinity against
      Rong-Horio where its gap exceeds s, relative 1e-9; continuous across
      its switch to the series, relative 1e-9; finite at contact; two
      equal particles against a quadrature of the tube through both,
      relative 1e-8.

    Run with -bad KEY to check a bad-input error instead (direct,
    lensRadius, minimumDistance, solidLensRadius, missingIndirect).
*/

#include "argList.H"
#include "unitCheck.H"
#include "conductionGeometry.H"
#include "directConduction.H"
#include "RongHorio.H"
#include "lensSolidSeries.H"
#include "IOstreams.H"
#include "mathematicalConstants.H"

using namespace Foam;

using unitTest::check;


//- int_{r1}^{r2} r/max(l, s) dr by Simpson's rule with n intervals
scalar simpson
(
    const scalar rp,
    const scalar gap,
    const scalar s,
    const scalar r1,
    const scalar r2,
    const label n
)
{
    if (!(r2 > r1))
    {
        return 0;
    }
    auto f = [&](const scalar r)
    {
        const scalar l = rp + gap - std::sqrt(max(rp*rp - r*r, scalar(0)));
        return r/max(l, s);
    };
    const scalar h = (r2 - r1)/n;
    scalar sum = f(r1) + f(r2);
    for (label i = 1; i < n; ++i)
    {
        sum += (i % 2 ? 4 : 2)*f(r1 + i*h);
    }
    return sum*h/3;
}


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList::addOption("bad", "key", "report the error of a bad key");
    argList args(argc, argv);

    if (args.found("bad"))
    {
        const word key(args.get<word>("bad"));
        dictionary dict;
        dict.add("direct", key == "direct" ? "Batchelor" : "BatchelorOBrien");
        dict.add
        (
            "indirect",
            key == "solidLensRadius" ? "lensSolidSeries"
          : key == "missingIndirect" ? "RongHorios" : "RongHorio"
        );
        dictionary coeffs;
        coeffs.add("lensRadius", key == "lensRadius" ? 0.9 : 1.4);
        coeffs.add("minimumDistance", key == "minimumDistance" ? 0.0 : 1e-7);
        dict.add("RongHorioCoeffs", coeffs);
        dictionary solidCoeffs;
        solidCoeffs.add("lensRadius", 1.0);
        dict.add("lensSolidSeriesCoeffs", solidCoeffs);
        directConduction::New(dict);
        indirectConduction::New(dict, 1.4);
        return 0;
    }

    Info().precision(15);
    const scalar r = 5e-4;

    // Contact radii
    for (const scalar f : {0.002, 0.02, 0.2})
    {
        const scalar d = f*r;
        check
        (
            "wall contact radius at overlap " + Foam::name(f) + " r",
            conductionGeometry::wallContactRadius(r, d),
            std::sqrt(d*(2*r - d)),
            1e-12
        );
        check
        (
            "contact radius of two equal spheres at overlap "
          + Foam::name(f) + " r",
            conductionGeometry::pairContactRadius(r, r, d),
            std::sqrt(r*d - d*d/4),
            1e-12
        );
        check
        (
            "contact radius against a sphere 1e6 times larger, overlap "
          + Foam::name(f) + " r",
            conductionGeometry::pairContactRadius(r, 1e6*r, d),
            conductionGeometry::wallContactRadius(r, d),
            1e-5
        );
    }
    check("wall contact radius at zero overlap", conductionGeometry::wallContactRadius(r, 0), 0, 0);
    check("pair contact radius at a gap", conductionGeometry::pairContactRadius(r, r, -1e-6), 0, 0);

    // Batchelor-O'Brien, App. B: glass (k 1.4, Y 5 MPa, Y_0 60 GPa, nu
    // 0.22) on aluminium (k 238, Y 5 MPa, Y_0 69 GPa, nu 0.34)
    {
        dictionary dict;
        dict.add("direct", "BatchelorOBrien");
        autoPtr<directConduction> law(directConduction::New(dict));
        const scalar YStar = 1/((1 - sqr(0.22))/5e6 + (1 - sqr(0.34))/5e6);
        const scalar YStar0 = 1/((1 - sqr(0.22))/60e9 + (1 - sqr(0.34))/69e9);
        const scalar c = conductionGeometry::overlapFactor(YStar, YStar0, 2.0/3.0);
        check("App. B thermal overlap factor c", c, 0.0018270817509934208, 1e-12);
        const scalar reference[][2] =
        {
            {0.002, 7.5252239873930473e-06},
            {0.005, 1.1898407546962349e-05},
            {0.01, 1.6826850893209107e-05},
            {0.02, 2.3796652047396675e-05}
        };
        for (const auto& ref : reference)
        {
            const scalar Rc =
                conductionGeometry::wallContactRadius(r, c*ref[0]*r);
            check
            (
                "Batchelor-O'Brien glass on aluminium, overlap "
              + Foam::name(ref[0]) + " r_p [W/K]",
                law->conductance(1.4, 238, Rc),
                ref[1],
                1e-12
            );
        }
    }

    // Rong-Horio against a quadrature of eq 4.31
    {
        dictionary dict;
        dict.add("indirect", "RongHorio");
        dictionary coeffs;
        coeffs.add("lensRadius", 1.4);
        coeffs.add("minimumDistance", 1e-7);
        dict.add("RongHorioCoeffs", coeffs);
        autoPtr<indirectConduction> base(indirectConduction::New(dict, 0));
        const auto& law =
            dynamic_cast<const indirectConductions::RongHorio&>(base());
        const scalar s = law.minimumDistance();
        const scalar rLens = law.lensRadius()*r;

        auto quadrature = [&](const scalar gap)
        {
            const scalar a = r + gap;
            if (!(a < rLens))
            {
                return scalar(0);
            }
            const scalar rOut = min(std::sqrt(rLens*rLens - a*a), r);
            const scalar rIn = gap < 0 ? std::sqrt(r*r - a*a) : 0;
            const scalar h = a - s;
            const scalar rs =
                gap < s ? min(h > 0 ? std::sqrt(r*r - h*h) : r, rOut) : rIn;
            return
                simpson(r, gap, s, rIn, max(rs, rIn), 20000)
              + simpson(r, gap, s, max(rs, rIn), rOut, 200000);
        };

        const scalar gaps[][2] =
        {
            {0.3*r, 2}, {0.05*r, 2}, {0.002*r, 2}, {2e-7, 2},
            {5e-8, 3}, {0, 4},
            {-1e-4*r, 5}, {-0.002*r, 5}, {-0.02*r, 5}, {-0.05*r, 5}
        };
        for (const auto& g : gaps)
        {
            check
            (
                "Rong-Horio case " + Foam::name(label(g[1])) + ", gap "
              + Foam::name(g[0]) + " m: closed form against quadrature",
                law.wallIntegral(r, g[0]),
                quadrature(g[0]),
                1e-8
            );
        }
        check("Rong-Horio case 1, gap 0.4 r_p", law.wallIntegral(r, 0.4*r), 0, 0);
        check("Rong-Horio case 1, gap 0.5 r_p", law.wallIntegral(r, 0.5*r), 0, 0);
        // Either side of the case boundaries by 1e-17 m: the integral's
        // slope there (about a/gap) moves it by ~1e-11 relative
        const scalar eps = 1e-17;
        check
        (
            "Rong-Horio continuous at gap = s (case 2 | 3)",
            law.wallIntegral(r, s - eps), law.wallIntegral(r, s + eps), 1e-9
        );
        check
        (
            "Rong-Horio continuous at gap = 0 (case 4 | 5)",
            law.wallIntegral(r, -eps), law.wallIntegral(r, eps), 1e-9
        );
        check
        (
            "Rong-Horio conductance = 2 pi k_f x integral",
            law.wallConductance(0.026, r, 0.002*r),
            2*constant::mathematical::pi*0.026*law.wallIntegral(r, 0.002*r),
            1e-14
        );

        // Two equal spheres at surface gap g: the gas between them at ring
        // radius r is 2 l(r; g/2) thick, s the least: 2 pi k_f int r/max(2l,
        // s) dr from r_in to r_out (of the mid plane at g/2)
        auto pairQuadrature = [&](const scalar g)
        {
            const scalar a = r + 0.5*g;
            if (!(a < rLens))
            {
                return scalar(0);
            }
            const scalar rOut = min(std::sqrt(rLens*rLens - a*a), r);
            const scalar rIn = g < 0 ? std::sqrt(r*r - a*a) : 0;
            // l = s/2 at r_s
            const scalar h = a - 0.5*s;
            const scalar rs =
                0.5*g < 0.5*s ? min(h > 0 ? std::sqrt(r*r - h*h) : r, rOut) : rIn;
            const scalar kf = 0.026;
            return
                2*constant::mathematical::pi*kf*0.5
               *(
                    simpson(r, 0.5*g, 0.5*s, rIn, max(rs, rIn), 20000)
                  + simpson(r, 0.5*g, 0.5*s, max(rs, rIn), rOut, 200000)
                );
        };
        for (const scalar g : {0.6*r, 0.05*r, 4e-7, 5e-8, 0.0, -0.002*r, -0.02*r})
        {
            check
            (
                "Rong-Horio, two equal particles at gap " + Foam::name(g)
              + " m: against quadrature",
                law.pairConductance(0.026, r, r, g), pairQuadrature(g), 1e-8
            );
        }
        check("Rong-Horio, two particles beyond 2 (lens - 1) r", law.pairConductance(0.026, r, r, 0.81*r), 0, 0);
        check
        (
            "Rong-Horio, unequal particles take the equal pair of r* = 2 ri rj/(ri + rj)",
            law.pairConductance(0.026, r, 3*r, 0.01*r),
            law.pairConductance(0.026, 1.5*r, 1.5*r, 0.01*r), 1e-14
        );

        // For the record: App. B's time constants m c_p/G of the 1 mm
        // glass particle through N2 (k_f 0.026)
        const scalar mcp = 2500*constant::mathematical::pi/6*pow3(2*r)*840;
        for (const scalar f : {0.02, 0.002, 0.0, -0.002, -0.02})
        {
            Info<< "for the record: App. B indirect, gap " << f
                << " r_p: m c_p/G = "
                << mcp/law.wallConductance(0.026, r, f*r) << " s" << nl;
        }
    }

    // The lens with the particle's solid in series against a quadrature
    {
        const scalar kf = 0.0257;
        const scalar lens = 1.2;
        const scalar rLens = lens*r;

        // G/(2 pi k_f) = int r dr/(k_f u/k_s + D - u), Simpson in r, split
        // where the solid and the gas resist alike near contact
        auto quadrature = [&](const scalar ks, const scalar gap)
        {
            const scalar D = r + gap;
            if (!(D < rLens))
            {
                return scalar(0);
            }
            const scalar rOut = min(std::sqrt(rLens*rLens - D*D), r);
            const scalar rIn = gap < 0 ? std::sqrt(r*r - D*D) : 0;
            auto f = [&](const scalar x)
            {
                const scalar u = std::sqrt(max(r*r - x*x, scalar(0)));
                return x/(kf/ks*u + D - u);
            };
            auto simpsonF = [&](const scalar a, const scalar b, const label n)
            {
                const scalar h = (b - a)/n;
                scalar sum = f(a) + f(b);
                for (label i = 1; i < n; ++i)
                {
                    sum += (i % 2 ? 4 : 2)*f(a + i*h);
                }
                return sum*h/3;
            };
            const scalar rMid = min(rIn + 0.05*r, rOut);
            return simpsonF(rIn, rMid, 200000) + simpsonF(rMid, rOut, 200000);
        };

        // Gaps inside the lens (r + gap < r_lens = 1.2 r): the quadrature
        // has something to integrate
        const scalar gaps[] =
            {0.15*r, 0.05*r, 0.002*r, 1e-7, 0, -0.002*r, -0.02*r};
        for (const scalar ratio : {54.0, 5.0, 1.0005, 0.5})
        {
            const scalar beta = 1 - 1/ratio;
            // Beyond the lens (r + gap >= r_lens) the gas bridges nothing
            for (const scalar g : {0.2*r, 0.3*r})
            {
                check
                (
                    "lensSolidSeries, k_s/k_f " + Foam::name(ratio)
                  + ", gap " + Foam::name(g) + " m, beyond the lens: zero",
                    indirectConductions::lensSolidSeries::integral
                    (
                        r, g, lens, beta
                    ),
                    0,
                    0
                );
            }
            for (const scalar g : gaps)
            {
                if (!(quadrature(kf*ratio, g) > 0))
                {
                    FatalErrorInFunction
                        << "gap " << g << " lies outside the lens: the"
                        << " quadrature check would compare nothing"
                        << exit(FatalError);
                }
                check
                (
                    "lensSolidSeries, k_s/k_f " + Foam::name(ratio)
                  + ", gap " + Foam::name(g) + " m: closed form against"
                    " quadrature",
                    indirectConductions::lensSolidSeries::integral
                    (
                        r, g, lens, beta
                    ),
                    quadrature(kf*ratio, g),
                    1e-8
                );
            }
        }
        for (const scalar g : {0.05*r, 0.0, -0.02*r})
        {
            const scalar D = r + g;
            const scalar rOut = std::sqrt(rLens*rLens - D*D);
            const scalar rIn = g < 0 ? std::sqrt(r*r - D*D) : 0;
            check
            (
                "lensSolidSeries, k_s = k_f, gap " + Foam::name(g)
              + " m: the slab (r_out^2 - r_in^2)/(2 D)",
                indirectConductions::lensSolidSeries::integral(r, g, lens, 0),
                (rOut*rOut - rIn*rIn)/(2*D),
                1e-12
            );
        }
        for (const scalar g : {0.15*r, 0.05*r, 0.002*r})
        {
            check
            (
                "lensSolidSeries, k_s -> infinity, gap " + Foam::name(g)
              + " m: Rong-Horio (gap > s)",
                indirectConductions::lensSolidSeries::integral
                (
                    r, g, lens, 1 - 1e-14
                ),
                indirectConductions::RongHorio::integral(r, g, lens, 1e-9),
                1e-9
            );
        }
        for (const scalar g : {0.002*r, -0.002*r})
        {
            check
            (
                "lensSolidSeries continuous at its series switch, gap "
              + Foam::name(g) + " m",
                indirectConductions::lensSolidSeries::integral
                (
                    r, g, lens, 1e-3*(1 + 1e-9)
                ),
                indirectConductions::lensSolidSeries::integral
                (
                    r, g, lens, 1e-3*(1 - 1e-9)
                ),
                1e-9
            );
        }

        dictionary dict;
        dict.add("indirect", "lensSolidSeries");
        dictionary coeffs;
        coeffs.add("lensRadius", lens);
        dict.add("lensSolidSeriesCoeffs", coeffs);
        const scalar ks = 54*kf;
        autoPtr<indirectConduction> law(indirectConduction::New(dict, ks));
        const scalar G0 = law->wallConductance(kf, r, 0);
        check
        (
            "lensSolidSeries finite and positive at contact (wall)",
            scalar(std::isfinite(G0) && G0 > 0), 1, 0
        );
        check
        (
            "lensSolidSeries wall conductance = 2 pi k_f x integral",
            G0,
            2*constant::mathematical::pi*kf
           *indirectConductions::lensSolidSeries::integral
            (
                r, 0, lens, 1 - kf/ks
            ),
            1e-14
        );
        check
        (
            "lensSolidSeries zero beyond the lens",
            law->wallConductance(kf, r, 0.21*r), 0, 0
        );

        // Two equal spheres at gap g: each tube crosses both solids (u
        // each) and the gas between them (g + 2 (r - u)):
        // 2 pi int x dx/(2 u/k_s + (2 D - 2 u)/k_f), D = r + g/2
        auto pairQuadrature = [&](const scalar g)
        {
            return
                2*constant::mathematical::pi*kf*0.5*quadrature(ks, 0.5*g);
        };
        for (const scalar g : {0.3*r, 0.05*r, 0.0, -0.002*r})
        {
            check
            (
                "lensSolidSeries, two equal particles at gap "
              + Foam::name(g) + " m: against quadrature",
                law->pairConductance(kf, r, r, g), pairQuadrature(g), 1e-8
            );
        }
        check
        (
            "lensSolidSeries, unequal particles take the equal pair of r*",
            law->pairConductance(kf, r, 3*r, 0.01*r),
            law->pairConductance(kf, 1.5*r, 1.5*r, 0.01*r), 1e-14
        );

        // For the record: two touching 1 mm glass beads in air
        Info<< "for the record: two touching 1 mm glass beads in air (k_s/k_f"
            << " 54), lensRadius 1.2: G = " << law->pairConductance(kf, r, r, 0)
            << " W/K" << nl;
    }

    Info<< nl << (unitTest::nFailed() ? "FAILED: " : "passed: ") << unitTest::nFailed()
        << " failed check(s)" << endl;
    return unitTest::nFailed() ? 1 : 0;
}
