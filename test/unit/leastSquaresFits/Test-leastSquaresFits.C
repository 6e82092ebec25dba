// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    Test-leastSquaresFits

Description
    The least-squares code (Eigen) against problems with known answers:

    - linearLeastSquares: a square system solved exactly (1e-12); a
      straight line through 5 points equal to the normal equations' hand
      solution (1e-12);
    - levenbergMarquardt: the same straight line from a far start, its
      standard errors equal to the textbook s/sqrt(Sxx) and
      s sqrt(1/N + xbar^2/Sxx) (1e-8); y = a exp(-b t) from exact data
      recovered from a start 10 times off (1e-10), with its Jacobian by
      central differences too (1e-8); two identical columns reported as
      rank 1 with the direction (1, -1)/sqrt(2) left free;
    - HancockSharpFit on synthetic curves made by the law itself
      (reductionLaws::HancockSharp::advance, k0 4.37 1/s, E_a 61.02
      kJ/mol, n 1.97/1.75/1.60 at 500/550/600 degC, m 0.93; 5 curves of
      20 points at 100 and 50 % H2), started from k0 20 1/s, E_a 80
      kJ/mol, n 1, m 0.3: every parameter recovered to 1e-8 relative
      without noise, for n per temperature, and for n linear (curves
      made with n linear) and constant (curves with one n);
    - with Gaussian noise of 0.01 in X, 200 seeds: the fraction of seeds
      whose estimate lies within 2 standard errors of the truth is, for
      every parameter, within [0.91, 0.995] (0.954 expected; three
      binomial standard deviations of 200 seeds, 0.015, either side);
    - the thesis's tiny-powder points (Table 3.3 at 500 degC, 100 and
      50 % H2, 60 min; Table 3.2 at 550 degC, 23 min) with n held at the
      thesis's 1.97/1.75: three points for k0, E_a and m, solved exactly,
      equal to the hand inversion of eq 3.2 (1e-8); the difference from
      the thesis's k0 4.37 1/s and E_a 61.02 kJ/mol printed;
    - all five points of Tables 3.2 and 3.3 (n held): the thesis's ln k0
      and E_a within 2 standard errors of the fit.
*/

#include "argList.H"
#include "levenbergMarquardt.H"
#include "linearLeastSquares.H"
#include "HancockSharpFit.H"
#include "unitCheck.H"

#include <random>

using namespace Foam;
using unitTest::check;

namespace
{

const scalar R = reductionLaws::HancockSharp::R;

dictionary lawDict
(
    const scalar k0,
    const scalar Ea,
    const List<FixedList<scalar, 2>>& n,
    const scalar m
)
{
    dictionary d;
    d.add("law", "HancockSharp");
    d.add("k0", k0);
    d.add("activationEnergy", Ea);
    if (n.size() == 1)
    {
        d.add("n", n[0][1]);
    }
    else
    {
        d.add("n", n);
    }
    d.add("hydrogenOrder", m);
    return d;
}


//- Curves of 20 points to X = 0.95 made by the law (advance from 0 over
//  the whole time: eq 3.2), noise of standard deviation sd added (X kept
//  in [0, 1])
List<HancockSharpFit::curve> synthetic
(
    const reductionLaws::HancockSharp& law,
    const scalar sd,
    std::mt19937& gen
)
{
    std::normal_distribution<double> noise(0, 1);
    const List<FixedList<scalar, 2>> TH
    ({
        {773.15, 1}, {773.15, 0.5}, {823.15, 1}, {823.15, 0.5}, {873.15, 1}
    });
    List<HancockSharpFit::curve> curves(TH.size());
    forAll(TH, i)
    {
        HancockSharpFit::curve& c = curves[i];
        c.name = "c" + Foam::name(i);
        c.T = TH[i][0];
        c.yH2 = TH[i][1];
        const scalar k = law.kEffective(c.T, c.yH2);
        const scalar tEnd =
            std::pow(-std::log(0.05), 1/law.n(c.T))/k;
        for (label j = 1; j <= 20; ++j)
        {
            const scalar t = tEnd*j/20;
            const scalar X = law.advance(0, c.T, c.yH2, t) + sd*noise(gen);
            c.t.append(t);
            c.X.append(min(max(X, scalar(0)), scalar(1)));
        }
    }
    return curves;
}


//- The parameter named in a fit's list
const HancockSharpFit::parameter& find
(
    const List<HancockSharpFit::parameter>& ps,
    const word& name
)
{
    for (const auto& p : ps)
    {
        if (p.name == name)
        {
            return p;
        }
    }
    FatalErrorInFunction << "No parameter " << name << exit(FatalError);
    return ps[0];
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList args(argc, argv, false, false, false);

    // linearLeastSquares: a square system
    {
        scalarRectangularMatrix A(3, 3);
        A(0, 0) = 2; A(0, 1) = 1; A(0, 2) = 0;
        A(1, 0) = 1; A(1, 1) = 3; A(1, 2) = 1;
        A(2, 0) = 0; A(2, 1) = 1; A(2, 2) = 4;
        // x = (1, -2, 3): b = A x
        const scalarField b({0, -2, 10});
        const scalarField x(linearLeastSquares(A, b));
        check("linearLeastSquares, square system: x0", x[0], 1, 1e-12);
        check("linearLeastSquares, square system: x1", x[1], -2, 1e-12);
        check("linearLeastSquares, square system: x2", x[2], 3, 1e-12);
    }

    // A straight line y = c0 + c1 x through 5 points: the normal
    // equations by hand, and the standard errors of the textbook
    const scalarField xs({0, 1, 2, 3, 4});
    const scalarField ys({1.1, 2.9, 5.2, 6.8, 9.1});
    {
        const label N = xs.size();
        const scalar xbar = sum(xs)/N, ybar = sum(ys)/N;
        scalar Sxx = 0, Sxy = 0;
        forAll(xs, i)
        {
            Sxx += sqr(xs[i] - xbar);
            Sxy += (xs[i] - xbar)*(ys[i] - ybar);
        }
        const scalar c1 = Sxy/Sxx, c0 = ybar - c1*xbar;
        scalar SSR = 0;
        forAll(xs, i)
        {
            SSR += sqr(ys[i] - c0 - c1*xs[i]);
        }
        const scalar s = std::sqrt(SSR/(N - 2));

        scalarRectangularMatrix A(N, 2);
        forAll(xs, i)
        {
            A(i, 0) = 1;
            A(i, 1) = xs[i];
        }
        const scalarField c(linearLeastSquares(A, ys));
        check("linearLeastSquares, line: intercept", c[0], c0, 1e-12);
        check("linearLeastSquares, line: slope", c[1], c1, 1e-12);

        const levenbergMarquardt lm
        (
            N, 2,
            [&](const scalarField& p, scalarField& r, scalarRectangularMatrix* J)
            {
                forAll(xs, i)
                {
                    r[i] = p[0] + p[1]*xs[i] - ys[i];
                    if (J)
                    {
                        (*J)(i, 0) = 1;
                        (*J)(i, 1) = xs[i];
                    }
                }
            },
            true
        );
        const levenbergMarquardt::solution sol = lm.solve(scalarField(scalarList({-50.0, 30.0})));
        check("levenbergMarquardt, line: intercept", sol.p[0], c0, 1e-10);
        check("levenbergMarquardt, line: slope", sol.p[1], c1, 1e-10);
        check
        (
            "levenbergMarquardt, line: standard error of the slope"
            " s/sqrt(Sxx)",
            sol.standardErrors[1], s/std::sqrt(Sxx), 1e-8
        );
        check
        (
            "levenbergMarquardt, line: standard error of the intercept"
            " s sqrt(1/N + xbar^2/Sxx)",
            sol.standardErrors[0], s*std::sqrt(1.0/N + sqr(xbar)/Sxx), 1e-8
        );
        check
        (
            "levenbergMarquardt, line: correlation -xbar/sqrt(Sxx/N + xbar^2)",
            sol.correlation(0, 1), -xbar/std::sqrt(Sxx/N + sqr(xbar)), 1e-8
        );
    }

    // y = a exp(-b t), exact data, from a start 10 times off; analytic
    // Jacobian and central differences
    {
        const scalar a = 2.5, b = 0.7;
        scalarField ts(12), yt(12);
        forAll(ts, i)
        {
            ts[i] = 0.5*i;
            yt[i] = a*std::exp(-b*ts[i]);
        }
        const auto f =
            [&](const scalarField& p, scalarField& r, scalarRectangularMatrix* J)
            {
                forAll(ts, i)
                {
                    const scalar e = std::exp(-p[1]*ts[i]);
                    r[i] = p[0]*e - yt[i];
                    if (J)
                    {
                        (*J)(i, 0) = e;
                        (*J)(i, 1) = -p[0]*ts[i]*e;
                    }
                }
            };
        for (const bool analytic : {true, false})
        {
            const levenbergMarquardt lm(ts.size(), 2, f, analytic);
            const levenbergMarquardt::solution sol =
                lm.solve(scalarField(scalarList({25.0, 0.07})));
            const word how(analytic ? "analytic" : "differences");
            const scalar tol = analytic ? 1e-10 : 1e-8;
            check("levenbergMarquardt, a exp(-b t), " + how + ": a", sol.p[0], a, tol);
            check("levenbergMarquardt, a exp(-b t), " + how + ": b", sol.p[1], b, tol);
            check
            (
                "levenbergMarquardt, a exp(-b t), " + how + ": converged",
                scalar(sol.converged), 1, 0
            );
        }
    }

    // Two identical columns: rank 1, the free direction (1, -1)/sqrt(2)
    {
        const levenbergMarquardt lm
        (
            xs.size(), 2,
            [&](const scalarField& p, scalarField& r, scalarRectangularMatrix* J)
            {
                forAll(xs, i)
                {
                    r[i] = (p[0] + p[1])*xs[i] - ys[i];
                    if (J)
                    {
                        (*J)(i, 0) = xs[i];
                        (*J)(i, 1) = xs[i];
                    }
                }
            },
            true
        );
        const levenbergMarquardt::solution sol = lm.solve(scalarField(scalarList({1.0, 1.0})));
        check("levenbergMarquardt, identical columns: rank", sol.rank, 1, 0);
        check
        (
            "levenbergMarquardt, identical columns: |free direction . (1,-1)/sqrt2|",
            mag(sol.nullDirection[0] - sol.nullDirection[1])/std::sqrt(2.0),
            1, 1e-8
        );
        check
        (
            "levenbergMarquardt, identical columns: no standard errors",
            sol.standardErrors.size(), 0, 0
        );
    }

    // HancockSharpFit: synthetic curves without noise
    const scalar k0 = 4.37, Ea = 61.02e3, m = 0.93;
    const List<FixedList<scalar, 2>> nTrue
    ({
        {773.15, 1.97}, {823.15, 1.75}, {873.15, 1.6}
    });
    const reductionLaws::HancockSharp start
    (
        lawDict(20, 80e3, List<FixedList<scalar, 2>>({{773.15, 1}}), 0.3)
    );
    std::mt19937 gen(12345);

    struct modelCase
    {
        word name;
        List<FixedList<scalar, 2>> n;
    };
    const List<modelCase> models
    ({
        {"perTemperature", nTrue},
        {"linear", List<FixedList<scalar, 2>>({{773.15, 1.97}, {873.15, 1.59}})},
        {"constant", List<FixedList<scalar, 2>>({{773.15, 1.8}})}
    });
    for (const modelCase& mc : models)
    {
        const reductionLaws::HancockSharp truth(lawDict(k0, Ea, mc.n, m));
        const List<HancockSharpFit::curve> curves(synthetic(truth, 0, gen));
        const HancockSharpFit fit
        (
            curves, "synthetic", start,
            HancockSharpFit::exponentModelNames[mc.name], wordList()
        );
        const List<HancockSharpFit::parameter> ps(fit.parameters());
        const word w("synthetic, no noise, n " + mc.name + ": ");
        check(w + "k0 [1/s]", find(ps, "k0").value, k0, 1e-8);
        check(w + "E_a [J/mol]", find(ps, "activationEnergy").value, Ea, 1e-8);
        check(w + "m", find(ps, "hydrogenOrder").value, m, 1e-8);
        for (const scalar T : {773.15, 823.15, 873.15})
        {
            // n at T from the fit's curves: X of the fit equals the law's
            // at every point when n(T) is recovered; check n itself
            // through the law's n(T)
            if (mc.name == "perTemperature")
            {
                check
                (
                    w + "n(" + Foam::name(T) + " K)",
                    find(ps, "n(" + Foam::name(T) + "K)").value,
                    truth.n(T), 1e-8
                );
            }
        }
        if (mc.name == "linear")
        {
            check
            (
                w + "dn/dT [1/K]", find(ps, "dn/dT").value,
                (1.59 - 1.97)/100, 1e-8
            );
        }
        if (mc.name == "constant")
        {
            check(w + "n", find(ps, "n").value, 1.8, 1e-8);
        }
        check(w + "converged", scalar(fit.solution().converged), 1, 0);
    }

    // With noise: coverage of +-2 standard errors over 200 seeds
    {
        const reductionLaws::HancockSharp truth(lawDict(k0, Ea, nTrue, m));
        const wordList names
        ({
            "ln(k0)", "activationEnergy", "hydrogenOrder",
            "n(773.15K)", "n(823.15K)", "n(873.15K)"
        });
        const scalarField truths
        ({
            std::log(k0), Ea, m, 1.97, 1.75, 1.6
        });
        labelList inside(names.size(), Zero);
        const label nSeeds = 200;
        for (label seed = 0; seed < nSeeds; ++seed)
        {
            std::mt19937 g(1000 + seed);
            const HancockSharpFit fit
            (
                synthetic(truth, 0.01, g), "synthetic", start,
                HancockSharpFit::exponentModel::perTemperature, wordList()
            );
            const List<HancockSharpFit::parameter> ps(fit.parameters());
            forAll(names, i)
            {
                const auto& p = find(ps, names[i]);
                inside[i] += mag(p.value - truths[i]) <= 2*p.standardError;
            }
        }
        forAll(names, i)
        {
            const scalar f = scalar(inside[i])/nSeeds;
            const bool pass = f >= 0.91 && f <= 0.995;
            Info<< (pass ? "ok   " : "FAIL ") << "noise 0.01, " << nSeeds
                << " seeds: " << names[i] << " within 2 standard errors in "
                << f << " of them (0.954 expected; [0.91, 0.995])" << nl;
            if (!pass)
            {
                ++unitTest::nFailed();
            }
        }
    }

    // The thesis's tiny points, n held: exact, against the hand inversion
    {
        const reductionLaws::HancockSharp thesis
        (
            lawDict(4.37, 61.02e3, List<FixedList<scalar, 2>>({{773.15, 1.97}, {823.15, 1.75}}), 0.93)
        );
        List<HancockSharpFit::curve> tiny(3);
        const List<FixedList<scalar, 4>> pts
        ({
            {773.15, 1, 3600, 0.7377},
            {773.15, 0.5, 3600, 0.3124},
            {823.15, 1, 1380, 0.5169}
        });
        forAll(pts, i)
        {
            tiny[i].name = "p" + Foam::name(i);
            tiny[i].T = pts[i][0];
            tiny[i].yH2 = pts[i][1];
            tiny[i].t = scalarList({pts[i][2]});
            tiny[i].X = scalarList({pts[i][3]});
        }
        const HancockSharpFit fit
        (
            tiny, "thesis", thesis,
            HancockSharpFit::exponentModel::perTemperature, wordList({"n"})
        );
        // Eq 3.2 inverted: k = (-ln(1 - X))^(1/n)/t
        const scalar k500 = std::pow(-std::log(1 - 0.7377), 1/1.97)/3600;
        const scalar k550 = std::pow(-std::log(1 - 0.5169), 1/1.75)/1380;
        const scalar EaHand =
            R*std::log(k550/k500)/(1/773.15 - 1/823.15);
        const scalar k0Hand = k500*std::exp(EaHand/(R*773.15));
        const scalar mHand =
            std::log
            (
                std::pow(-std::log(1 - 0.3124), 1/1.97)/3600/k500
            )/std::log(0.5);
        const List<HancockSharpFit::parameter> ps(fit.parameters());
        check("thesis tiny points, n held: exact (no standard errors)", fit.hasErrors(), 0, 0);
        check("thesis tiny points: k0 [1/s] (hand inversion)", find(ps, "k0").value, k0Hand, 1e-8);
        check("thesis tiny points: E_a [J/mol] (hand inversion)", find(ps, "activationEnergy").value, EaHand, 1e-8);
        check("thesis tiny points: m (hand inversion)", find(ps, "hydrogenOrder").value, mHand, 1e-8);
        Info<< "     thesis tiny points against the thesis's fit: k0 "
            << find(ps, "k0").value << " 1/s (thesis 4.37, ratio "
            << find(ps, "k0").value/4.37 << "), E_a "
            << find(ps, "activationEnergy").value/1e3 << " kJ/mol (thesis"
            << " 61.02, " << (find(ps, "activationEnergy").value - 61.02e3)/1e3
            << " kJ/mol), m " << find(ps, "hydrogenOrder").value << nl;

        // All five points of Tables 3.2 and 3.3
        List<HancockSharpFit::curve> all(tiny);
        all.setSize(5);
        all[3].name = "small"; all[3].T = 823.15; all[3].yH2 = 1;
        all[3].t = scalarList({960}); all[3].X = scalarList({0.3073});
        all[4].name = "big"; all[4].T = 823.15; all[4].yH2 = 1;
        all[4].t = scalarList({780}); all[4].X = scalarList({0.2109});
        const HancockSharpFit fit5
        (
            all, "thesis", thesis,
            HancockSharpFit::exponentModel::perTemperature, wordList({"n"})
        );
        const List<HancockSharpFit::parameter> p5(fit5.parameters());
        const auto& lk = find(p5, "ln(k0)");
        const auto& ea = find(p5, "activationEnergy");
        Info<< "     all five points: ln k0 " << lk.value << " +- "
            << lk.standardError << " (thesis " << std::log(4.37) << "), E_a "
            << ea.value << " +- " << ea.standardError
            << " J/mol (thesis 61020), correlation "
            << fit5.correlationLnK0Ea() << nl;
        check
        (
            "all five points: thesis's ln k0 within 2 standard errors"
            " (|difference|/SE)",
            scalar(mag(lk.value - std::log(4.37))/lk.standardError <= 2), 1, 0
        );
        check
        (
            "all five points: thesis's E_a within 2 standard errors"
            " (|difference|/SE)",
            scalar(mag(ea.value - 61.02e3)/ea.standardError <= 2), 1, 0
        );
    }

    Info<< nl << (unitTest::nFailed() ? "FAILED " : "PASSED ")
        << unitTest::nFailed() << " failures" << endl;
    return unitTest::nFailed() ? 1 : 0;
}
