// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    defluidizationMap

Group
    sinterFoam/utilities

Description
    The force-balance predictor of thesis Ch. 2 (§2.4.2): for each powder,
    the temperature at which the solid-bridge force (eq 2.4, contact time
    of eq 2.11) equals the maximum Hertz collision force (eq 2.5-2.8) of
    two identical particles of the powder's d50 colliding at v_n:

        v_n = first of collisionVelocities (1e-4 m/s): transition T_t
        v_n = last  of collisionVelocities (5e-4 m/s): defluidization T_d

    Writes, per powder, postProcessing/defluidizationMap/<powder>.dat: the
    forces normalised by the particle weight m g against temperature (the
    content of Fig 2.11): solid bridge for the three surface models and
    the collision force at every v_n, and the Ergun drag (eq 2.9-2.10) at
    the powder's lowest and highest superficial gas velocity.

    Reduced powders (thesis App. A): with reductionDegrees, the same balance
    for particles reduced to each X: their mass m0 (1 - X (1 - W0)) (the
    diameter kept, ironOxidePath with the powder's ironContent W0), their
    surfaces part iron (surfaceIron) with the bridges
    of ironOxideBridge (the iron's data: the material named by
    reducedSurface). The collision keeps the oxide's elastic constants.

    -calibrate: the tensile strength sigma(T) is the one input the thesis
    does not tabulate. Given measured (or reference) T_t and T_d
    (sub-dictionary calibration), prints sigma(T) = a + b T^n (exponent n
    given) as a tensileStrength entry: with two temperatures (one powder's
    T_t and T_d) the curve through the sigma that puts both crossings
    there, solved exactly; with more (several powders, or conditions, in
    points), the a and b whose crossings lie closest to the measured
    temperatures in the least-squares sense (levenbergMarquardt, residual
    in kelvin: the temperature at which sigma(T) meets the strength the
    balance needs, nearest the measured one, minus the measured one),
    with standard errors from the residuals' scatter.

Usage
    defluidizationMap [-dict FILE] [-calibrate]

    system/defluidizationMapDict (temperatures in kelvin):
    \table
        Property            | Description                                | Required
        material            | name of a sub-dictionary of materials      | yes
        materials           | material dictionaries (sinterMaterial)     | yes
        C                   | threeMicroContacts, smooth, nineMicroContacts or a value: C of eq 2.4 for T_t, T_d | yes
        collisionVelocities | v_n list [m/s], > 0, at least one           | yes
        Tmin, Tmax          | temperature range [K], 0 < Tmin < Tmax      | yes
        nTemperatures       | points of the written curves, >= 2          | yes
        gravity             | |g| [m/s^2], > 0                            | yes
        gas                 | viscosity [Pa s], density [kg/m^3], voidage [-] of the Ergun drag | yes
        powders             | per powder: d50 [m] > 0; superficialVelocities (u_min u_max) [m/s] of the drag band | yes
        calibration         | exponent n [-] > 0; powder, Tt, Td [K] in [200, 3000] (Tt < Td), or points ({powder; Tt; Td} ...) with Tt, Td or both each, two temperatures or more in all (only with -calibrate) | -calibrate
        reductionDegrees    | list of X in [0, 1] of the reduced powders   | no (none)
        reducedSurface      | material (in materials) of the iron on reduced surfaces | with reductionDegrees
        surfaceIronExponent | s of the surface iron fraction phi^s (surfaceIron), in (0, 1], default 1 | no
        ironCalibration     | strength {powder reductionDegree Td} and surface {powder reductionDegree Td}: -calibrate also prints the iron's constant tensile strength and s that put both T_d there | no
    \endtable
    and in each powder ironContent, W0(TFe) of Table 3.1 (with
    reductionDegrees).
*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "IOmanip.H"
#include "mathematicalConstants.H"
#include "sinterMaterial.H"
#include "solidBridge.H"
#include "ironOxideBridge.H"
#include "surfaceIron.H"
#include "keywordRange.H"
#include "HertzCollision.H"
#include "ErgunDrag.H"
#include "numberLiterals.H"
#include "levenbergMarquardt.H"
#include "linearLeastSquares.H"
#include "keywordSource.H"

using namespace Foam;

namespace
{

const scalar degC = 273.15;

// One powder: identical spheres of the powder's d50
struct powder
{
    word name;
    scalar d;
    scalar m;
    scalarList uSuperficial;
    //- W0(TFe), with reductionDegrees (else 0)
    scalar ironContent;
};


// The lowest temperature of [Tmin, Tmax] at which f(T) = F_sb - F_n turns
// from negative to non-negative; -1 if it does not
template<class Func>
scalar crossing(const Func& f, const scalar Tmin, const scalar Tmax)
{
    const label nScan = 4000;
    scalar Tlow = Tmin;
    scalar fLow = f(Tlow);

    if (fLow >= 0)
    {
        return Tmin;
    }

    for (label i = 1; i <= nScan; ++i)
    {
        const scalar Thigh = Tmin + (Tmax - Tmin)*i/nScan;
        if (f(Thigh) >= 0)
        {
            // Bisection to round-off of the temperature
            scalar a = Tlow, b = Thigh;
            for (label iter = 0; iter < 100 && b - a > 1e-9; ++iter)
            {
                const scalar c = 0.5*(a + b);
                (f(c) < 0 ? a : b) = c;
            }
            return 0.5*(a + b);
        }
        Tlow = Thigh;
    }

    return -1;
}


void printTemperature(const scalar T)
{
    if (T < 0)
    {
        Info<< "      none in range";
    }
    else
    {
        Info<< "  " << setw(8) << T << " K (" << setw(7) << T - degC << " C)";
    }
}

#include "calibrateTensileStrength.H"

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Force-balance prediction of the transition and defluidization"
        " temperatures of a sintering powder (thesis Ch. 2)"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    argList::addOption("dict", "file", "Use alternative defluidizationMapDict");
    argList::addBoolOption
    (
        "calibrate",
        "Print the tensileStrength a + b T^n that reproduces the calibration"
        " powder's Tt and Td"
    );

    #include "setRootCase.H"
    numberLiterals::checkCase(args);
    #include "createTime.H"

    const fileName dictPath
    (
        args.lookupOrDefault<fileName>
        (
            "dict",
            runTime.system()/"defluidizationMapDict"
        )
    );

    IOdictionary mapDict
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

    // Material and laws
    const word materialName(mapDict.get<word>("material"));
    const dictionary& materials = mapDict.subDict("materials");
    if (!materials.isDict(materialName))
    {
        FatalIOErrorInFunction(mapDict)
            << "material " << materialName << " is not a sub-dictionary of"
               " materials" << nl << "Valid materials are: "
            << materials.toc() << exit(FatalIOError);
    }
    const sinterMaterial material(materials.subDict(materialName));
    const solidBridge bridge(material, mapDict);

    const scalarList vn(mapDict.get<scalarList>("collisionVelocities"));
    if (vn.empty())
    {
        FatalIOErrorInFunction(mapDict)
            << "collisionVelocities is empty: give at least one v_n [m/s]"
            << exit(FatalIOError);
    }
    forAll(vn, i)
    {
        keywordRange::checkElement
        (
            mapDict, "collisionVelocities", "element " + std::to_string(i),
            vn[i], 0, GREAT, "a normal collision velocity v_n [m/s]", true
        );
    }

    const scalar Tmin(keywordRange::positive(mapDict, "Tmin", "[K]"));
    const scalar Tmax
    (
        keywordRange::above<scalar>
        (
            mapDict, "Tmax", Tmin, false, "above Tmin [K]"
        )
    );
    const label nT
    (
        keywordRange::above<label>(mapDict, "nTemperatures", 2, true)
    );
    const scalar g(keywordRange::positive(mapDict, "gravity", "[m/s^2]"));

    const dictionary& gasDict = mapDict.subDict("gas");
    const scalar muGas
    (
        keywordRange::positive(gasDict, "viscosity", "dynamic [Pa s]")
    );
    const scalar rhoGas
    (
        keywordRange::positive(gasDict, "density", "[kg/m^3]")
    );
    const scalar epsGas
    (
        keywordRange::get(gasDict, "voidage", 0, 1, "[-]", true, true)
    );

    // Powders
    const dictionary& powdersDict = mapDict.subDict("powders");
    List<powder> powders;
    for (const entry& e : powdersDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(powdersDict)
                << "powders: entry " << e.keyword() << " is not a dictionary"
                << exit(FatalIOError);
        }
        const dictionary& pd = e.dict();
        powder p;
        p.name = e.keyword();
        p.ironContent = 0;
        p.d = keywordRange::positive(pd, "d50", "[m]");
        p.m = material.rho()*constant::mathematical::pi/6*pow3(p.d);
        p.uSuperficial = pd.get<scalarList>("superficialVelocities");
        if (p.uSuperficial.empty() || min(p.uSuperficial) <= 0)
        {
            FatalIOErrorInFunction(pd)
                << "superficialVelocities " << p.uSuperficial
                << " must hold velocities > 0 [m/s]" << exit(FatalIOError);
        }
        if (pd.found("ironContent"))
        {
            p.ironContent = ironOxidePath(pd).ironContent();
        }
        powders.append(p);
    }
    if (powders.empty())
    {
        FatalIOErrorInFunction(powdersDict)
            << "powders is empty" << exit(FatalIOError);
    }

    Info<< nl << "Material " << material.name() << ", rho " << material.rho()
        << " kg/m^3, Y " << material.Y() << " Pa, nu " << material.nu()
        << "; solid bridge C = " << bridge.C() << nl
        << "v_n for T_t: " << vn.first() << " m/s, for T_d: " << vn.last()
        << " m/s" << nl << endl;

    // Calibration of sigma(T) on measured transition and defluidization
    // temperatures
    if (args.found("calibrate"))
    {
        calibrate
        (
            mapDict.subDict("calibration"), powders, material, bridge, vn
        );
    }

    // The three surface models of the curves, in the column order
    const wordList modelNames(solidBridge::surfaceModelNames.sortedToc());
    PtrList<solidBridge> bridges(modelNames.size());
    forAll(modelNames, i)
    {
        bridges.set
        (
            i,
            new solidBridge(material, solidBridge::surfaceModelNames[modelNames[i]])
        );
    }

    // Temperatures and curves per powder
    const fileName outDir(runTime.path()/"postProcessing"/"defluidizationMap");
    mkDir(outDir);

    Info<< "powder      d50 [m]      T_t                         T_d" << nl;

    for (const powder& p : powders)
    {
        const scalar rp = p.d/2;
        const scalar weight = p.m*g;
        const HertzCollision hertz(rp, p.m, material.Y(), material.nu());

        const auto balance = [&](const scalar v)
        {
            const scalar Fn = hertz.maxNormalForce(v);
            const scalar tc = hertz.contactTime(v);
            return [&bridge, rp, Fn, tc](const scalar T)
            {
                return bridge.force(rp, T, tc) - Fn;
            };
        };

        const scalar Tt = crossing(balance(vn.first()), Tmin, Tmax);
        const scalar Td = crossing(balance(vn.last()), Tmin, Tmax);

        Info<< setw(8) << p.name << "  " << setw(10) << p.d;
        printTemperature(Tt);
        printTemperature(Td);
        Info<< nl;

        // Curves: F/(m g) against T
        OFstream os(outDir/(p.name + ".dat"));
        os.precision(8);
        os  << "# " << p.name << ": d50 " << p.d << " m, m " << p.m
            << " kg, m g " << weight << " N; material " << material.name()
            << "; forces / (m g)" << nl
            << "# T_t " << Tt << " K, T_d " << Td << " K (solid bridge C = "
            << bridge.C() << ")" << nl
            << "# T[K] T[C]";
        for (const scalar v : vn)
        {
            os  << " Fn(vn=" << v << ")";
            for (const word& name : modelNames)
            {
                os  << " Fsb_" << name << "(vn=" << v << ")";
            }
        }
        os  << " Fd(u=" << min(p.uSuperficial) << ")"
            << " Fd(u=" << max(p.uSuperficial) << ")" << nl;

        // Drag on a particle at rest in the interstitial gas u_0/eps
        const scalar FdMin = ErgunDrag::particleForce
        (
            epsGas, muGas, rhoGas, p.d, min(p.uSuperficial)/epsGas
        );
        const scalar FdMax = ErgunDrag::particleForce
        (
            epsGas, muGas, rhoGas, p.d, max(p.uSuperficial)/epsGas
        );

        for (label i = 0; i < nT; ++i)
        {
            const scalar T = Tmin + (Tmax - Tmin)*i/(nT - 1);
            os  << T << ' ' << T - degC;
            for (const scalar v : vn)
            {
                const scalar tc = hertz.contactTime(v);
                os  << ' ' << hertz.maxNormalForce(v)/weight;
                for (const solidBridge& sb : bridges)
                {
                    os  << ' ' << sb.force(rp, T, tc)/weight;
                }
            }
            os  << ' ' << FdMin/weight << ' ' << FdMax/weight << nl;
        }
    }


    // Reduced powders
    const scalarList Xs
    (
        mapDict.lookupOrDefault<scalarList>("reductionDegrees", scalarList())
    );
    if (Xs.size() || mapDict.found("ironCalibration"))
    {
        for (const scalar X : Xs)
        {
            keywordRange::check
            (
                mapDict, "reductionDegrees", X, 0, 1,
                "every reduction degree is a fraction of the oxygen removed"
            );
        }
        const word ironName(mapDict.get<word>("reducedSurface"));
        if (!materials.isDict(ironName))
        {
            FatalIOErrorInFunction(mapDict)
                << "reducedSurface " << ironName << " is not a sub-dictionary"
                << " of materials" << nl << "Valid materials are: "
                << materials.toc() << exit(FatalIOError);
        }
        const sinterMaterial iron(materials.subDict(ironName));
        const ironOxideBridge reducedBridge(material, iron, mapDict);
        const scalar sExponent = keywordRange::getOrDefault
        (
            mapDict, "surfaceIronExponent", 1, 0, 1,
            "the exponent s of the surface iron fraction phi^s", true
        );

        for (const powder& p : powders)
        {
            if (p.ironContent <= 0)
            {
                FatalIOErrorInFunction(powdersDict)
                    << "powder " << p.name << " in " << powdersDict.name()
                    << " needs its ironContent, W0(TFe) of Table 3.1, for"
                    << " the reduced powders (reductionDegrees)"
                    << exit(FatalIOError);
            }
        }

        // F_sb - F_n at T of a powder reduced to X colliding at v, with
        // surface exponent s; the iron's tensile strength the material's,
        // or sigmaFe with fixedStrength
        const auto balance = [&]
        (
            const powder& p,
            const scalar X,
            const scalar v,
            const scalar s,
            const bool fixedStrength = false,
            const scalar sigmaFe = 0
        )
        {
            const ironOxidePath path(p.ironContent);
            const HertzCollision hertz
            (
                p.d/2, p.m*path.massRatio(X), material.Y(), material.nu()
            );
            const scalar Fn = hertz.maxNormalForce(v);
            const scalar tc = hertz.contactTime(v);
            const scalar rp = p.d/2;
            return
            [&reducedBridge, path, s, X, rp, Fn, tc, fixedStrength, sigmaFe]
            (
                const scalar T
            )
            {
                const scalar f = surfaceIron(path, s).fraction(X, T);
                if (!fixedStrength)
                {
                    return reducedBridge.force(rp, T, tc, f, f) - Fn;
                }
                return
                    ironOxideBridge::blend
                    (
                        reducedBridge.oxide().force(rp, T, tc),
                        sigmaFe*reducedBridge.iron().forcePerStrength(rp, T, tc),
                        ironOxideBridge::ironShare(f, f)
                    )
                  - Fn;
            };
        };

        const auto findPowder = [&](const dictionary& dict) -> const powder&
        {
            const word which(dict.get<word>("powder"));
            forAll(powders, i)
            {
                if (powders[i].name == which) return powders[i];
            }
            FatalIOErrorInFunction(dict)
                << "powder " << which << " is not in powders"
                << exit(FatalIOError);
            return powders[0];
        };

        if (args.found("calibrate") && mapDict.found("ironCalibration"))
        {
            // Two conditions, two unknowns: strength {powder, X, Td} sets
            // sigma_Fe for a given s (the force is linear in it); surface
            // {powder, X, Td} then sets s (bisection: a smaller s, more
            // iron on the surface, a lower T_d)
            const dictionary& cal = mapDict.subDict("ironCalibration");
            const dictionary& strength = cal.subDict("strength");
            const dictionary& surfaceCal = cal.subDict("surface");
            const powder& ps = findPowder(strength);
            const powder& pf = findPowder(surfaceCal);
            const scalar Xs0 = keywordRange::get
            (
                strength, "reductionDegree", 0, 1, "a reduction degree", true
            );
            const scalar Ts0 = keywordRange::get
            (
                strength, "Td", 200, 5000, "a temperature in kelvin"
            );
            const scalar Xf0 = keywordRange::get
            (
                surfaceCal, "reductionDegree", 0, 1, "a reduction degree",
                true
            );
            const scalar Tf0 = keywordRange::get
            (
                surfaceCal, "Td", 200, 5000, "a temperature in kelvin"
            );

            // F(T_s) = A + sigma B at the strength point; sigma > 0 needs
            // iron on the surface there (B > 0) and an oxide that alone
            // does not stick (A < 0)
            const auto sigmaFor = [&](const scalar s)
            {
                const scalar A = balance(ps, Xs0, vn.last(), s, true, 0)(Ts0);
                const scalar B =
                    balance(ps, Xs0, vn.last(), s, true, 1)(Ts0) - A;
                if (!(B > 0 && A < 0))
                {
                    FatalIOErrorInFunction(strength)
                        << "ironCalibration/strength in " << strength.name()
                        << ": no iron tensile strength puts " << ps.name
                        << " at reductionDegree " << Xs0 << " at Td " << Ts0
                        << " K: "
                        << (B > 0
                            ? "the oxide alone already sticks there"
                            : "its surface holds no iron there (below the"
                              " first iron, or in the wustite stage above"
                              " 843.15 K)")
                        << exit(FatalIOError);
                }
                return -A/B;
            };
            const auto TdFor = [&](const scalar s)
            {
                return crossing
                (
                    balance(pf, Xf0, vn.last(), s, true, sigmaFor(s)),
                    Tmin, Tmax
                );
            };

            scalar lo = 1e-3, hi = 1;
            const scalar Tlo = TdFor(lo), Thi = TdFor(hi);
            if (!(Tlo > 0 && Thi > 0 && Tlo <= Tf0 && Tf0 <= Thi))
            {
                FatalIOErrorInFunction(surfaceCal)
                    << "No surface exponent s in [1e-3, 1] puts T_d of "
                    << pf.name << " at X = " << Xf0 << " at " << Tf0
                    << " K: it spans " << Tlo << " to " << Thi << " K"
                    << " (-1: no crossing in [Tmin, Tmax])"
                    << exit(FatalIOError);
            }
            for (label iter = 0; iter < 60 && hi - lo > 1e-10; ++iter)
            {
                const scalar mid = 0.5*(lo + hi);
                const scalar Tmid = TdFor(mid);
                if (Tmid < 0)
                {
                    FatalIOErrorInFunction(surfaceCal)
                        << "T_d of " << pf.name << " has no crossing in"
                        << " [Tmin, Tmax] at s = " << mid << ": widen the"
                        << " range" << exit(FatalIOError);
                }
                (Tmid < Tf0 ? lo : hi) = mid;
            }
            const scalar s = 0.5*(lo + hi);
            const scalar sigmaFe = sigmaFor(s);

            const label oldPrecision = Info().precision(10);
            Info<< "Iron calibration: " << ps.name << " at X = " << Xs0
                << " defluidizing at " << Ts0 << " K, " << pf.name
                << " at X = " << Xf0 << " at " << Tf0 << " K:" << nl
                << "    surfaceIronExponent " << s << ";" << nl
                << "    tensileStrength constant " << sigmaFe << ";" << nl
                << endl;
            Info().precision(oldPrecision);
        }

        OFstream os(outDir/"reduced.dat");
        os.precision(8);
        os  << "# Reduced powders: material " << material.name()
            << ", reduced surface " << iron.name() << ", C = "
            << bridge.C() << ", surface iron exponent " << sExponent
            << "; temperatures in kelvin (-1: none in range)" << nl
            << "# powder X T_t T_d surfaceIron(T_d) massRatio" << nl;

        Info<< nl << "Reduced powders (surface iron " << iron.name()
            << ", exponent " << sExponent << "):" << nl;
        for (const powder& p : powders)
        {
            const ironOxidePath path(p.ironContent);
            const surfaceIron surface(path, sExponent);
            for (const scalar X : Xs)
            {
                const scalar Tt = crossing
                (
                    balance(p, X, vn.first(), sExponent), Tmin, Tmax
                );
                const scalar Td = crossing
                (
                    balance(p, X, vn.last(), sExponent), Tmin, Tmax
                );
                const scalar f = Td > 0 ? surface.fraction(X, Td) : -1;
                Info<< "reduced " << setw(6) << p.name << "  X "
                    << setw(5) << X << "  f(T_d) " << setw(8) << f;
                printTemperature(Tt);
                printTemperature(Td);
                Info<< nl;
                os  << p.name << ' ' << X << ' ' << Tt << ' ' << Td << ' '
                    << f << ' ' << surface.path().massRatio(X) << nl;
            }
        }
    }

    Info<< nl << "Curves written to " << outDir << nl << nl << "End" << nl
        << endl;

    return 0;
}
