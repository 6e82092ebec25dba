// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    reductionDegree

Group
    sinterFoam/utilities

Description
    The hydrogen reduction of a well-mixed bed of iron-oxide powder (0-D):
    every particle at the same temperature and hydrogen mole fraction, the
    reduction degree X (thesis eq 3.1) against time from a reduction law
    (reductionLaw: HancockSharp, eq 3.2-3.4) and the powder's oxide path
    (ironOxidePath: phases, mass, hydrogen taken, reaction heat).

    Each run writes postProcessing/reductionDegree/<run>.dat (time [s],
    [min], X, dX/dt [1/s], metallic iron fraction, phase mass fractions
    Fe2O3 Fe3O4 FeO Fe, m/m0, H2 taken [mol per kg of oxide], reaction heat
    [J per kg of oxide]) and the log gives X at the run's end next to the
    measured value when a run has one (e.g. Table 3.2, 3.3).

    Each step advances X by the law exactly over the write interval, so the
    curve does not depend on the interval.

    -fit FILE: the law's parameters fitted to measured curves instead
    (HancockSharpFit: the file's format, the least squares): k0, E_a, n
    (-exponent perTemperature, linear or constant) and the hydrogen order
    m, each with its standard error, the correlation of ln k0 and E_a and
    the residual per curve; parameters listed in -hold stay at the values
    of kinetics, which also start the others. Writes, in
    postProcessing/reductionDegree/fit/: kinetics (the entry to paste),
    points.dat (each point with its fitted X) and curves.dat (the fitted
    curves, for validation/reduction/plotReductionFit).

Usage
    reductionDegree [-dict FILE] [-fit FILE [-exponent MODEL] [-hold '(...)']]

    system/reductionDegreeDict (temperatures in kelvin):
    \table
        Property      | Description                                       | Required
        kinetics      | a reductionLaw dictionary (law HancockSharp, ...)  | yes
        powders       | per powder: ironContent W0(TFe) [-] (ironOxidePath) | yes
        writeInterval | time between written points [s], > 0               | yes
        runs          | per run: powder; T [K] >= 200; H2 mole fraction [-] in [0, 1]; duration [s] > 0; X0 initial reduction degree [-] in [0, 1] (default 0); measured X [-] in [0, 1] and source (optional) | yes
    \endtable
*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "IOmanip.H"
#include "numberLiterals.H"
#include "knownKeywords.H"
#include "keywordSource.H"
#include "keywordRange.H"
#include "reductionLaw.H"
#include "ironOxidePath.H"
#include "HancockSharpFit.H"

using namespace Foam;

namespace
{

//- -fit: the law fitted to the curves of a file, printed and written
void fitCurves
(
    const argList& args,
    const dictionary& dict,
    const reductionLaw& law
)
{
    const auto* hs = isA<reductionLaws::HancockSharp>(law);
    if (!hs)
    {
        FatalIOErrorInKeyword(dict, "kinetics")
            << "-fit fits the HancockSharp law: kinetics in " << dict.name()
            << " is " << law.type() << nl << "Valid laws for -fit are"
            << " (HancockSharp)" << exit(FatalIOError);
    }

    const fileName file(args.get<fileName>("fit").expand());
    const word modelName
    (
        args.lookupOrDefault<word>("exponent", "perTemperature")
    );
    if (!HancockSharpFit::exponentModelNames.found(modelName))
    {
        FatalErrorInFunction
            << "Unknown -exponent " << modelName << nl
            << "Valid exponent models are "
            << HancockSharpFit::exponentModelNames.sortedToc()
            << exit(FatalError);
    }
    const wordList hold
    (
        args.found("hold") ? args.get<wordList>("hold") : wordList()
    );

    const List<HancockSharpFit::curve> curves
    (
        HancockSharpFit::readCurves(file)
    );
    const HancockSharpFit fit
    (
        curves,
        file,
        *hs,
        HancockSharpFit::exponentModelNames[modelName],
        hold
    );
    const levenbergMarquardt::solution& s = fit.solution();

    Info<< nl << "Hancock-Sharp law (eq 3.2-3.4) fitted to " << curves.size()
        << " curves, " << fit.nPoints() << " points (t > 0) of " << file
        << nl << "    " << fit.nFree() << " free parameters, "
        << s.degreesOfFreedom << " degrees of freedom, "
        << s.iterations << " iterations ("
        << (s.converged ? "converged" : "NOT converged") << "), sum of"
        << " squares " << s.sumOfSquares << ", condition number "
        << s.conditionNumber << nl;
    if (!fit.hasErrors())
    {
        Info<< "    as many points as parameters: solved exactly, no"
            << " residual left to estimate standard errors" << nl;
    }
    Info<< nl << "parameter" << tab << "value" << tab << "standard error"
        << tab << "relative" << tab << "unit" << nl;
    for (const HancockSharpFit::parameter& q : fit.parameters())
    {
        Info<< q.name << tab << setprecision(8) << q.value << tab;
        if (!q.fitted)
        {
            Info<< "held" << tab << "-";
        }
        else if (!fit.hasErrors())
        {
            Info<< "-" << tab << "-";
        }
        else
        {
            Info<< setprecision(4) << q.standardError << tab
                << (q.value != 0 ? mag(q.standardError/q.value) : scalar(0));
        }
        Info<< tab << q.unit << nl;
    }
    Info<< setprecision(6);
    if (fit.hasErrors() && !hold.found("activationEnergy"))
    {
        Info<< "correlation of ln(k0) and E_a: " << setprecision(6)
            << fit.correlationLnK0Ea() << nl;
    }

    Info<< nl << "curve" << tab << "T [K]" << tab << "H2" << tab << "points"
        << tab << "RMS residual" << tab << "max |residual|" << nl;
    forAll(curves, ci)
    {
        const HancockSharpFit::curve& c = curves[ci];
        Info<< c.name << tab << c.T << tab << c.yH2 << tab << c.t.size()
            << tab << setprecision(4) << fit.rms(ci) << tab
            << fit.maxResidual(ci) << setprecision(6) << nl;
    }
    const scalar rmsAll =
        std::sqrt(s.sumOfSquares/max(fit.nPoints(), label(1)));
    Info<< "all" << tab << "-" << tab << "-" << tab << fit.nPoints() << tab
        << setprecision(4) << rmsAll << setprecision(6) << nl;

    // Written: the entry, the points, the curves
    const fileName outDir
    (
        args.rootPath()/args.globalCaseName()/"postProcessing"
       /"reductionDegree"/"fit"
    );
    mkDir(outDir);
    {
        OFstream os(outDir/"kinetics");
        os  << "// The Hancock-Sharp law fitted by reductionDegree -fit to "
            << file << nl << "// (" << curves.size() << " curves, "
            << fit.nPoints() << " points; held: " << hold
            << "; -exponent " << modelName << "). Temperatures in kelvin."
            << nl;
        fit.writeKinetics(os);
        Info<< nl;
        fit.writeKinetics(Info());
    }
    {
        OFstream os(outDir/"points.dat");
        os  << "# curve T[K] H2 t[s] X Xfit" << nl << setprecision(10);
        forAll(curves, ci)
        {
            const HancockSharpFit::curve& c = curves[ci];
            forAll(c.t, k)
            {
                os  << c.name << ' ' << c.T << ' ' << c.yH2 << ' '
                    << c.t[k] << ' ' << c.X[k] << ' ' << fit.X(ci, c.t[k])
                    << nl;
            }
        }
    }
    {
        OFstream os(outDir/"curves.dat");
        os  << "# curve T[K] H2 t[s] Xfit (200 points to 1.2 times the"
            << " last measured time)" << nl << setprecision(10);
        forAll(curves, ci)
        {
            const HancockSharpFit::curve& c = curves[ci];
            const scalar tEnd = 1.2*c.t.last();
            for (label k = 0; k <= 200; ++k)
            {
                const scalar t = tEnd*k/200;
                os  << c.name << ' ' << c.T << ' ' << c.yH2 << ' ' << t
                    << ' ' << fit.X(ci, t) << nl;
            }
        }
    }
    Info<< nl << "Written to " << outDir << nl;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Reduction degree against time of a well-mixed bed of iron-oxide"
        " powder in hydrogen (thesis Ch. 3)"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    argList::addOption("dict", "file", "Use alternative reductionDegreeDict");
    argList::addOption
    (
        "fit",
        "file",
        "Fit the Hancock-Sharp law's parameters to the measured curves of"
        " the file (format: the class HancockSharpFit)"
    );
    argList::addOption
    (
        "exponent",
        "model",
        "With -fit: the Avrami exponent n per temperature (perTemperature,"
        " the default), linear in T (linear) or one value (constant)"
    );
    argList::addOption
    (
        "hold",
        "list",
        "With -fit: parameters held at the values of kinetics, from"
        " (activationEnergy n hydrogenOrder)"
    );

    #include "setRootCase.H"
    numberLiterals::checkCase(args);
    #include "createTime.H"

    const fileName dictPath
    (
        args.lookupOrDefault<fileName>
        (
            "dict",
            runTime.system()/"reductionDegreeDict"
        )
    );

    IOdictionary dict
    (
        IOobject
        (
            dictPath,
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        ),
        nullptr
    );
    knownKeywords::check
    (
        dict,
        wordList({"kinetics", "powders", "writeInterval", "runs"})
    );

    const autoPtr<reductionLaw> law
    (
        reductionLaw::New(dict.subDict("kinetics"))
    );

    if (args.found("fit"))
    {
        fitCurves(args, dict, *law);
        Info<< "End" << endl;
        return 0;
    }
    for (const word opt : {"exponent", "hold"})
    {
        if (args.found(opt))
        {
            FatalErrorInFunction
                << "Option -" << opt << " is for -fit only"
                << exit(FatalError);
        }
    }
    const scalar interval =
        keywordRange::get(dict, "writeInterval", 0, GREAT, "a time [s]", true);

    const dictionary& powders = dict.subDict("powders");
    const dictionary& runs = dict.subDict("runs");
    if (runs.toc().empty())
    {
        FatalIOErrorInKeyword(dict, "runs")
            << "runs in " << dict.name() << " lists no run"
            << exit(FatalIOError);
    }

    const fileName outDir(runTime.globalPath()/"postProcessing"/"reductionDegree");
    mkDir(outDir);

    Info<< nl << "run" << tab << "powder" << tab << "T [K]" << tab << "H2"
        << tab << "t [min]" << tab << "X" << tab << "measured" << tab
        << "difference" << tab << "source" << nl;

    for (const entry& e : runs)
    {
        if (!e.isDict())
        {
            FatalIOErrorInKeyword(runs, e.keyword())
                << "Entry " << e.keyword() << " of " << runs.name()
                << " must be a run's dictionary" << exit(FatalIOError);
        }
        const dictionary& run = e.dict();
        knownKeywords::check
        (
            run,
            wordList
            ({
                "powder", "T", "H2", "duration", "X0", "measured", "source"
            })
        );

        const word powderName(run.get<word>("powder"));
        if (!powders.isDict(powderName))
        {
            FatalIOErrorInKeyword(run, "powder")
                << "Unknown powder " << powderName << " in " << run.name()
                << nl << "Valid powders are " << powders.sortedToc()
                << exit(FatalIOError);
        }
        const dictionary& powderDict = powders.subDict(powderName);
        knownKeywords::check(powderDict, wordList({"ironContent"}));
        const ironOxidePath path(powderDict);

        const scalar T = keywordRange::get
        (
            run, "T", 200, 3000, "the bed temperature in kelvin"
        );
        const scalar yH2 = keywordRange::get
        (
            run, "H2", 0, 1, "the hydrogen mole fraction"
        );
        const scalar duration = keywordRange::get
        (
            run, "duration", 0, GREAT, "a time [s]", true
        );
        const scalar X0 = keywordRange::getOrDefault
        (
            run, "X0", 0, 0, 1, "the initial reduction degree"
        );
        const bool measured = run.found("measured");
        const scalar Xm =
            measured
          ? keywordRange::get(run, "measured", 0, 1, "a reduction degree")
          : -1;
        const string source(run.lookupOrDefault<string>("source", ""));

        OFstream os(outDir/(e.keyword() + ".dat"));
        os  << "# reductionDegree: powder " << powderName << " (W0 "
            << path.ironContent() << "), T " << T << " K, H2 " << yH2
            << ", X0 " << X0 << ", measured "
            << (measured ? Xm : scalar(-1)) << " at " << duration/60
            << " min" << (source.empty() ? "" : " (") << source.c_str()
            << (source.empty() ? "" : ")") << nl
            << "# t[s] t[min] X dXdt[1/s] metallicIron w_Fe2O3 w_Fe3O4"
               " w_FeO w_Fe m/m0 H2[mol/kg] heat[J/kg]" << nl;

        scalar X = X0;
        scalar t = 0;
        auto write = [&]()
        {
            const FixedList<scalar, 4> w = path.phases(X, T);
            os  << setprecision(8) << t << ' ' << t/60 << ' ' << X << ' '
                << law->rate(X, T, yH2) << ' ' << path.metallicIron(X, T)
                << ' ' << w[0] << ' ' << w[1] << ' ' << w[2] << ' ' << w[3]
                << ' ' << path.massRatio(X) << ' '
                << (X - X0)*path.oxygen() << ' ' << path.enthalpy(X0, X, T)
                << nl;
        };
        write();
        while (t < duration*(1 - 1e-12))
        {
            const scalar dt = min(interval, duration - t);
            X = law->advance(X, T, yH2, dt);
            t += dt;
            write();
        }

        Info<< e.keyword() << tab << powderName << tab << T << tab << yH2
            << tab << duration/60 << tab << setprecision(4) << X;
        if (measured)
        {
            Info<< tab << Xm << tab << setprecision(3)
                << (Xm > 0 ? 100*(X - Xm)/Xm : scalar(0)) << " %";
        }
        else
        {
            Info<< tab << "-" << tab << "-";
        }
        Info<< tab << source.c_str() << setprecision(6) << nl;
    }

    Info<< nl << "Written to " << outDir << nl << "End" << endl;
    return 0;
}
