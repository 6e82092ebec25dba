// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    Test-reductionLaws

Description
    The Hancock-Sharp reduction law (thesis eq 3.2-3.4) and the
    iron-oxide path, against hand values:

    - k(T) of eq 3.4 with k0 = 4.37 1/s, E_a = 61.02 kJ/mol at 500 and
      550 degC; n(T) interpolated between 1.97 (500 degC) and 1.75
      (550 degC), constant beyond;
    - the rate form integrates to eq 3.2 at constant T and H2: dX/dt
      integrated by RK4 from X(60 s) to 3600 s, and advance() over one step
      of 3600 s, 3600 steps of 1 s and uneven steps, all equal to eq 3.2;
    - Table 3.3 (tiny, 500 degC, 60 min): 73.77 % in 100 % H2; the
      thesis's order 1.24 is ln(73.77/31.24)/ln 2; through eq 3.2 the same
      two reduction degrees give the order 0.933 of k, with which the law
      gives the 50 % H2 case;
    - Table 3.2 (tiny, 550 degC, 23 min): 51.69 %;
    - the path: pure hematite's first stage ends at 1/9 (the thesis's
      11 %), Table 3.1's powders' hematite fractions, phases summing to 1,
      m/m0 = W0 at X = 1, the total enthalpy the same on both paths
      (Hess), metallic iron only after the oxide stages;
    - the iron on the surface: the iron volume fraction of magnetite half
      reduced (hand, phase densities), the surface fraction phi^s
      (surfaceIron) for s = 1 and 0.21, 0 and 1 at X = 0 and 1, none in
      the wustite stage, never falling as X rises;
    - a parcel's step (parcelReduction): the mass it loses is the oxygen
      removed, its heat that of the path, and a step dt at acceleration A
      is the step A dt at A = 1.
*/

#include "argList.H"
#include "HancockSharp.H"
#include "ironOxidePath.H"
#include "parcelReduction.H"
#include "surfaceIron.H"
#include "unitCheck.H"

using namespace Foam;
using unitTest::check;

namespace
{

dictionary tinyLaw(const scalar m)
{
    dictionary d;
    d.add("law", "HancockSharp");
    d.add("k0", 4.37);
    d.add("activationEnergy", 61.02e3);
    List<FixedList<scalar, 2>> n(2);
    n[0] = FixedList<scalar, 2>({773.15, 1.97});
    n[1] = FixedList<scalar, 2>({823.15, 1.75});
    d.add("n", n);
    d.add("hydrogenOrder", m);
    return d;
}

//- Eq 3.2
scalar avrami(const scalar k, const scalar t, const scalar n)
{
    return 1 - std::exp(-std::pow(k*t, n));
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList args(argc, argv, false, false, false);

    const scalar T500 = 773.15, T550 = 823.15;

    // The order of k from Table 3.3 through eq 3.2 (n at 500 degC)
    const scalar X100 = 0.7377, X50 = 0.3124;
    const scalar mK =
        std::log
        (
            std::pow(-std::log(1 - X50), 1/1.97)
           /std::pow(-std::log(1 - X100), 1/1.97)
        )/std::log(0.5);
    check("thesis's order ln(73.77/31.24)/ln 2 (Table 3.3: 1.24)",
        std::log(X100/X50)/std::log(2.0), 1.24, 0.005);
    check("order of k from Table 3.3 through eq 3.2 (hand 0.9326)",
        mK, 0.9326, 1e-3);

    autoPtr<reductionLaw> lawPtr(reductionLaw::New(tinyLaw(mK)));
    const auto& law = refCast<const reductionLaws::HancockSharp>(lawPtr());

    // eq 3.4
    check("k(500 degC) [1/s] (hand 3.2961e-4)", law.k(T500), 3.2961e-4, 1e-4);
    check("k(550 degC) [1/s] (hand 5.8669e-4)", law.k(T550), 5.8669e-4, 1e-4);
    check("n(500 degC)", law.n(T500), 1.97, 1e-12);
    check("n(525 degC), halfway", law.n(798.15), 1.86, 1e-12);
    check("n(450 degC), below the pairs", law.n(723.15), 1.97, 1e-12);
    check("n(650 degC), above the pairs", law.n(923.15), 1.75, 1e-12);
    check("no hydrogen, no reduction", law.advance(0.3, T500, 0, 1e4), 0.3, 0);

    // The rate form integrates to eq 3.2 (100 % H2, 500 degC, to 60 min)
    const scalar k = law.k(T500), n = law.n(T500), tEnd = 3600;
    const scalar exact = avrami(k, tEnd, n);
    {
        scalar X = avrami(k, 60, n);
        const label nSteps = 35400;
        const scalar h = (tEnd - 60)/nSteps;
        for (label i = 0; i < nSteps; ++i)
        {
            const scalar k1 = law.rate(X, T500, 1);
            const scalar k2 = law.rate(X + h/2*k1, T500, 1);
            const scalar k3 = law.rate(X + h/2*k2, T500, 1);
            const scalar k4 = law.rate(X + h*k3, T500, 1);
            X += h/6*(k1 + 2*k2 + 2*k3 + k4);
        }
        check("dX/dt integrated (RK4, 0.1 s) from X(60 s) to 3600 s = eq 3.2",
            X, exact, 1e-8);
    }
    check("advance: one step of 3600 s = eq 3.2",
        law.advance(0, T500, 1, tEnd), exact, 1e-12);
    {
        scalar X = 0;
        for (label i = 0; i < 3600; ++i)
        {
            X = law.advance(X, T500, 1, 1);
        }
        check("advance: 3600 steps of 1 s = eq 3.2", X, exact, 1e-12);
        X = 0;
        scalar t = 0, dt = 1e-3;
        while (t < tEnd)
        {
            const scalar step = min(dt, tEnd - t);
            X = law.advance(X, T500, 1, step);
            t += step;
            dt *= 1.7;
        }
        check("advance: steps growing from 1 ms by 1.7 = eq 3.2", X, exact, 1e-12);
    }

    // Table 3.3 and 3.2 (tiny powder), tolerance: the fit's spread
    check("Table 3.3: 100 % H2, 500 degC, 60 min (73.77 %)",
        law.advance(0, T500, 1, 3600), X100, 0.03);
    check("Table 3.3: 50 % H2, 500 degC, 60 min (31.24 %), order of k",
        law.advance(0, T500, 0.5, 3600), X50, 0.05);
    check("Table 3.3: ratio 50 %/100 % H2 (31.24/73.77)",
        law.advance(0, T500, 0.5, 3600)/law.advance(0, T500, 1, 3600),
        X50/X100, 0.03);
    check("Table 3.2: tiny, 550 degC, 23 min (51.69 %)",
        law.advance(0, T550, 1, 23*60), 0.5169, 0.05);

    // The path
    {
        const ironOxidePath hem(2*ironOxidePath::MFe
            /(2*ironOxidePath::MFe + 3*ironOxidePath::MO));
        check("pure hematite: first stage ends at X = 1/9 (thesis: 11 %)",
            hem.hematiteEnd(), 1.0/9, 1e-12);

        const ironOxidePath tiny(0.7219), small(0.7104), big(0.7193);
        check("tiny (W0 0.7219): hematite fraction (hand 0.07020)",
            tiny.hematiteFraction(), 0.07020, 1e-3);
        check("small (W0 0.7104): hematite fraction (hand 0.5461)",
            small.hematiteFraction(), 0.5461, 1e-3);
        check("big (W0 0.7193): hematite fraction (hand 0.1778)",
            big.hematiteFraction(), 0.1778, 1e-3);
        check("tiny: hematite gone at X (hand 0.008430)",
            tiny.hematiteEnd(), 0.008430, 1e-3);
        check("tiny: wustite stage ends at X (hand 0.2563)",
            tiny.wustiteEnd(), 0.2563, 1e-3);
        check("tiny: oxygen [mol/kg] (hand 17.382)", tiny.oxygen(), 17.382, 1e-4);
        check("m/m0 at X = 1 is W0", tiny.massRatio(1), 0.7219, 1e-12);

        for (const scalar T : {T500, 923.15})
        {
            for (const scalar X : {0.0, 0.004, 0.1, 0.3, 0.7, 1.0})
            {
                const FixedList<scalar, 4> w = tiny.phases(X, T);
                check
                (
                    "phases sum to 1 at X " + std::to_string(X)
                  + ", T " + std::to_string(T),
                    w[0] + w[1] + w[2] + w[3], 1, 1e-12
                );
            }
        }
        check("X = 1: all iron", tiny.phases(1, T500)[ironOxidePath::iron], 1, 1e-12);
        check("no metallic iron before the hematite is gone (500 degC)",
            tiny.metallicIron(0.008, T500), 0, 0);
        check("no metallic iron in the wustite stage (650 degC)",
            tiny.metallicIron(0.2, 923.15), 0, 0);
        check("no wustite below 570 degC",
            tiny.phases(0.5, T500)[ironOxidePath::wustite], 0, 0);

        // Hess: the same enthalpy both ways for pure magnetite (hand
        // 652.6 kJ/kg), and a step's enthalpy adds up over sub-steps
        const ironOxidePath mag(3*ironOxidePath::MFe
            /(3*ironOxidePath::MFe + 4*ironOxidePath::MO));
        check("magnetite to iron below 570 degC [J/kg] (hand 652595)",
            mag.enthalpy(0, 1, T500), 652595, 1e-5);
        check("the same through wustite (Hess)",
            mag.enthalpy(0, 1, 923.15), mag.enthalpy(0, 1, T500), 1e-12);
        check("a step's enthalpy is the sum of its parts (650 degC)",
            tiny.enthalpy(0, 0.1, 923.15) + tiny.enthalpy(0.1, 0.6, 923.15),
            tiny.enthalpy(0, 0.6, 923.15), 1e-12);
        check("the hematite stage is exothermic (-6.03 kJ/mol O)",
            tiny.enthalpy(0, tiny.hematiteEnd(), T500)
           /(tiny.hematiteEnd()*tiny.oxygen()), -6.026e3, 1e-3);

        // The iron on the surface: magnetite half reduced at 500 degC
        // holds Fe and Fe3O4 with equal iron, by volume (hand, densities
        // 7874 and 5180 kg/m^3) 0.322505; with s = 0.21 the surface
        // shows 0.322505^0.21 = 0.788484
        check("magnetite at X 0.5, 500 degC: iron volume fraction (hand 0.322505)",
            mag.ironVolumeFraction(0.5, T500), 0.322505, 1e-5);
        check("... surface iron, s = 1 (Delesse): the volume fraction",
            surfaceIron(mag, 1).fraction(0.5, T500),
            mag.ironVolumeFraction(0.5, T500), 0);
        check("... surface iron, s = 0.21 (hand 0.788484)",
            surfaceIron(mag, 0.21).fraction(0.5, T500), 0.788484, 1e-5);
        const surfaceIron tinySurface(tiny, 0.21);
        check("surface iron at X = 0", tinySurface.fraction(0, T500), 0, 0);
        check("surface iron at X = 1", tinySurface.fraction(1, T500), 1, 1e-12);
        check("no surface iron in the wustite stage (650 degC)",
            tinySurface.fraction(0.2, 923.15), 0, 0);
        label rising = 0;
        for (label i = 1; i <= 100; ++i)
        {
            rising +=
                tinySurface.fraction(0.01*i, T500)
             >= tinySurface.fraction(0.01*(i - 1), T500);
        }
        check("surface iron never falls as X rises (100 steps, 500 degC)",
            rising, 100, 0);
    }

    // A parcel's step
    {
        dictionary reduction;
        reduction.add("kinetics", tinyLaw(mK));
        dictionary tiny;
        tiny.add("ironContent", 0.7219);
        const parcelReduction real(reduction, tiny);
        reduction.add("acceleration", 10.0);
        const parcelReduction fast(reduction, tiny);

        const scalar m = 1e-9, X = 0.3, dt = 60;
        const parcelReduction::step s = real.advance(X, T500, m, 1, dt);
        check("parcel: X as the law's", s.X, law.advance(X, T500, 1, dt), 1e-14);
        check("parcel: mass lost = oxygen removed x M_O", m - s.mass,
            s.oxygen*ironOxidePath::MO, 1e-9);
        const scalar m0 = m/(1 - X*(1 - 0.7219));
        check("parcel: oxygen = m0 (1 - W0)/M_O (X' - X)", s.oxygen,
            m0*(1 - 0.7219)/ironOxidePath::MO*(s.X - X), 1e-12);
        check("parcel: heat = m0 dH(X, X')", s.heat,
            m0*real.path().enthalpy(X, s.X, T500), 1e-12);
        const parcelReduction::step f = fast.advance(X, T500, m, 1, dt);
        const parcelReduction::step r10 = real.advance(X, T500, m, 1, 10*dt);
        check("acceleration 10 over dt = real time over 10 dt", f.X, r10.X, 1e-14);
        check("... the same oxygen", f.oxygen, r10.oxygen, 1e-14);
    }

    Info<< nl << unitTest::nFailed() << " failed" << endl;
    return unitTest::nFailed() ? 1 : 0;
}
