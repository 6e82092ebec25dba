// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    minimumFluidizationVelocity

Group
    sinterFoam/utilities

Description
    Theoretical minimum fluidization velocity u_mf of a powder with a size
    distribution, for each drag law listed (thesis §2.3, Table 2.1, and
    §5.4.1: Ergun and Beetstra with eps_mf = 0.4).

    At u_mf the gas carries the bed: with the drag laws' normalisation
    (dragLaw: F_d = 3 pi mu d eps F (u - v), superficial U = eps (u - v))
    and the momentum form of the solver (-eps grad p in the gas), the
    pressure gradient of a fixed bed is sum_i n_i F_d,i/eps, and it equals
    the buoyant weight (1 - eps) (rho_p - rho_g) g when

        U sum_i x_i 18 mu F_i(eps, Re_i)/(eps d_i^2) = (rho_p - rho_g) g

    x_i is the solid volume fraction of size class i (sum x_i = 1). For a
    single size and Ergun's law at low Re this is Ergun's
    u_mf = eps^3 d^2 (rho_p - rho_g) g/(150 mu (1 - eps)). Re_i = rho_g d_i
    U/mu, or with the Sauter mean <d> = 1/sum(x_i/d_i) for a polydisperse
    law (Beetstra), whose F_i then carries d_i/<d>. U is found by bisection
    (the left side grows with U).

    Also printed: u_mf of each law for a single size d50, as the thesis's
    Table 2.1 evaluates Ergun.

Usage
    minimumFluidizationVelocity [-dict file] [-epsilonMf value]

    system/minimumFluidizationVelocityDict:
    \table
        Property         | Description                                | Required | Default
        gas/rho          | gas density [kg/m^3]                       | yes      |
        gas/mu           | gas viscosity [Pa s]                       | yes      |
        particles/rho    | particle density [kg/m^3]                  | yes      |
        g                | magnitude of gravity [m/s^2]               | no       | 9.81
        epsilonMf        | voidage at minimum fluidization, (0, 1)    | no       | 0.4
        sizeDistribution | normal or classes (below)                  | yes      |
        laws             | one sub-dictionary per law, as for drag    | yes      |
    \endtable

    sizeDistribution type normal: a number-based normal distribution of
    the diameter truncated to [min, max], as OpenFOAM's injection draws it
    (keys mean, standardDeviation, min, max [m]; nClasses, default 400).
    Type classes: classes ((d1 x1) (d2 x2) ...) with the diameters [m] and
    their solid volume fractions (normalised here). d50 is the median of
    the number distribution for normal, the volume median for classes.

    \verbatim
    gas         { rho 1.1646; mu 1.76e-5; }     // N2 at 293.15 K
    particles   { rho 5240; }
    epsilonMf   0.4;
    sizeDistribution
    {
        type normal; mean 58e-6; standardDeviation 8e-6; min 45e-6; max 75e-6;
    }
    laws
    {
        Ergun       { law Ergun; }
        Beetstra    { law Beetstra; polydisperse true; }
    }
    \endverbatim

    Output: a table, and one line `umf <law> <value>` per law.
*/

#include "keywordRange.H"
#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "dragLaw.H"
#include "mathematicalConstants.H"
#include "IOmanip.H"
#include "numberLiterals.H"

using namespace Foam;

namespace
{

//- Size classes: diameters [m] and solid volume fractions (sum 1)
struct sizeClasses
{
    scalarField d;
    scalarField x;
    scalar d50;
};


//- A particle diameter [m] of a fluidized bed: in [0.1 um, 5 cm]
void checkSize(const dictionary& dict, const word& key, const scalar d)
{
    keywordRange::check
    (
        dict, key, d, 1e-7, 0.05,
        std::string("a particle diameter [m]")
      + (d > 0.05 ? " (micrometres? 58 um is 58e-6)" : "")
    );
}


scalar size(const dictionary& dict, const word& key)
{
    const scalar d = dict.get<scalar>(key);
    checkSize(dict, key, d);
    return d;
}


sizeClasses readSizeDistribution(const dictionary& dict)
{
    const word type(dict.get<word>("type"));
    sizeClasses s;

    if (type == "normal")
    {
        const scalar mean = size(dict, "mean");
        const scalar sigma =
            keywordRange::positive(dict, "standardDeviation", "[m]");
        const scalar dMin = size(dict, "min");
        const scalar dMax = size(dict, "max");
        const label n = dict.lookupOrDefault<label>("nClasses", 400);
        if (dMax <= dMin || n < 2)
        {
            FatalIOErrorInFunction(dict)
                << "need min < max and nClasses >= 2 (min " << dMin
                << ", max " << dMax << ", nClasses " << n << ')'
                << exit(FatalIOError);
        }
        if (!(mean > dMin && mean < dMax))
        {
            // Far outside, every class had a number density of 0
            FatalIOErrorInFunction(dict)
                << "Keyword mean " << mean << " in " << dict.name()
                << " must lie inside [min, max] = [" << dMin << ", "
                << dMax << "] m" << exit(FatalIOError);
        }

        // Midpoint classes of the number density, volume weight d^3
        s.d.setSize(n);
        s.x.setSize(n);
        scalarField number(n);
        const scalar w = (dMax - dMin)/n;
        forAll(s.d, i)
        {
            s.d[i] = dMin + (i + 0.5)*w;
            number[i] = std::exp(-0.5*sqr((s.d[i] - mean)/sigma));
            s.x[i] = number[i]*pow3(s.d[i]);
        }

        // Number median
        const scalar total = sum(number);
        scalar cumulative = 0;
        s.d50 = s.d.last();
        forAll(number, i)
        {
            if (cumulative + number[i] >= 0.5*total)
            {
                s.d50 = dMin + w*(i + (0.5*total - cumulative)/number[i]);
                break;
            }
            cumulative += number[i];
        }
    }
    else if (type == "classes")
    {
        const List<Tuple2<scalar, scalar>> classes
        (
            dict.get<List<Tuple2<scalar, scalar>>>("classes")
        );
        if (classes.empty())
        {
            FatalIOErrorInFunction(dict)
                << "classes is empty" << exit(FatalIOError);
        }
        s.d.setSize(classes.size());
        s.x.setSize(classes.size());
        forAll(classes, i)
        {
            s.d[i] = classes[i].first();
            s.x[i] = classes[i].second();
            if (!(s.d[i] > 0) || !(s.x[i] >= 0))
            {
                FatalIOErrorInFunction(dict)
                    << "classes: entry " << i << " (" << s.d[i] << ' '
                    << s.x[i] << ") needs d > 0 and a volume fraction >= 0"
                    << exit(FatalIOError);
            }
            checkSize(dict, "classes", s.d[i]);
        }

        // Volume median, classes in the order given (ascending d)
        const scalar total = sum(s.x);
        scalar cumulative = 0;
        s.d50 = s.d.last();
        forAll(s.x, i)
        {
            cumulative += s.x[i];
            if (cumulative >= 0.5*total)
            {
                s.d50 = s.d[i];
                break;
            }
        }
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Unknown sizeDistribution type " << type << nl
            << "Valid types are: 2(normal classes)" << exit(FatalIOError);
    }

    const scalar total = sum(s.x);
    if (!(total > 0))
    {
        FatalIOErrorInFunction(dict)
            << "the size distribution has no volume" << exit(FatalIOError);
    }
    s.x /= total;
    return s;
}


//- Left side of the force balance per unit U: sum_i x_i 18 mu F_i/(eps d_i^2)
scalar dragPerVelocity
(
    const dragLaw& law,
    const sizeClasses& s,
    const scalar eps,
    const scalar rho,
    const scalar mu,
    const scalar U
)
{
    const scalar dMean = 1/sum(s.x/s.d);
    scalar sum = 0;
    forAll(s.d, i)
    {
        // Re = eps rho |u - v| d/mu = rho U d/mu
        const scalar F = law.particleF(eps, s.d[i], dMean, rho*U/mu);
        sum += s.x[i]*18*mu*F/(eps*sqr(s.d[i]));
    }
    return sum;
}


//- u_mf: U with U dragPerVelocity(U) = (rho_p - rho_g) g
scalar umf
(
    const dragLaw& law,
    const sizeClasses& s,
    const scalar eps,
    const scalar rho,
    const scalar mu,
    const scalar buoyantWeight
)
{
    auto residual = [&](const scalar U)
    {
        return U*dragPerVelocity(law, s, eps, rho, mu, U) - buoyantWeight;
    };

    scalar lo = 0;
    scalar hi = 1e-3;
    while (residual(hi) < 0)
    {
        lo = hi;
        hi *= 2;
        if (hi > 1e4)
        {
            FatalErrorInFunction
                << "no minimum fluidization velocity below 1e4 m/s"
                << exit(FatalError);
        }
    }
    for (label iter = 0; iter < 200 && (hi - lo) > 1e-14*hi; ++iter)
    {
        const scalar mid = 0.5*(lo + hi);
        (residual(mid) < 0 ? lo : hi) = mid;
    }
    return 0.5*(lo + hi);
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Theoretical minimum fluidization velocity of a size distribution"
        " for each listed drag law (eps_mf = 0.4 by default)"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    argList::addOption
    (
        "dict",
        "file",
        "Use alternative minimumFluidizationVelocityDict"
    );
    argList::addOption
    (
        "epsilonMf",
        "value",
        "Voidage at minimum fluidization, instead of the dictionary's"
    );

    #include "setRootCase.H"
    numberLiterals::checkCase(args);
    #include "createTime.H"

    IOdictionary dict
    (
        IOobject
        (
            args.lookupOrDefault<fileName>
            (
                "dict",
                runTime.system()/"minimumFluidizationVelocityDict"
            ),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        ),
        nullptr
    );

    const dictionary& gas = dict.subDict("gas");
    const scalar rhoGas = keywordRange::positive(gas, "rho", "[kg/m^3]");
    const scalar mu = keywordRange::positive(gas, "mu", "dynamic [Pa s]");
    const scalar rhoP =
        keywordRange::positive(dict.subDict("particles"), "rho", "[kg/m^3]");
    const scalar g = dict.lookupOrDefault<scalar>("g", 9.81);
    const char* epsWhat = "the bed voidage at minimum fluidization [-]";
    scalar eps = 0;
    if (args.found("epsilonMf"))
    {
        eps = args.get<scalar>("epsilonMf");
        if (!(eps > 0 && eps < 1))
        {
            FatalErrorInFunction
                << "Option -epsilonMf must lie in (0, 1), not " << eps << ": "
                << epsWhat << exit(FatalError);
        }
    }
    else
    {
        eps = keywordRange::getOrDefault
        (
            dict, "epsilonMf", 0.4, 0, 1, epsWhat, true, true
        );
    }
    if (!(g > 0) || !(rhoP > rhoGas))
    {
        FatalIOErrorInFunction(dict)
            << "need g > 0 and particles/rho > gas/rho (g " << g
            << ", rho " << rhoP << " and " << rhoGas << ')'
            << exit(FatalIOError);
    }

    const sizeClasses sizes(readSizeDistribution(dict.subDict("sizeDistribution")));
    sizeClasses single;
    single.d = scalarField(1, sizes.d50);
    single.x = scalarField(1, 1.0);
    single.d50 = sizes.d50;

    const scalar buoyantWeight = (rhoP - rhoGas)*g;
    const dictionary& laws = dict.subDict("laws");
    if (laws.empty())
    {
        FatalIOErrorInFunction(laws)
            << "laws is empty: give e.g. Ergun { law Ergun; }"
            << exit(FatalIOError);
    }

    Info<< nl << "eps_mf " << eps << ", rho_p " << rhoP << " kg/m3, gas rho "
        << rhoGas << " kg/m3, mu " << mu << " Pa s" << nl
        << "size classes " << sizes.d.size() << ", d50 " << sizes.d50
        << " m, Sauter mean " << 1/sum(sizes.x/sizes.d) << " m" << nl << nl
        << "law            u_mf [m/s]    u_mf(d50 only) [m/s]" << nl;

    DynamicList<Tuple2<word, scalar>> results;
    for (const entry& e : laws)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(laws)
                << "laws: " << e.keyword() << " must be a sub-dictionary"
                   " such as { law Ergun; }" << exit(FatalIOError);
        }
        const autoPtr<dragLaw> law(dragLaw::New(e.dict()));
        const scalar u = umf(law(), sizes, eps, rhoGas, mu, buoyantWeight);
        const scalar u50 = umf(law(), single, eps, rhoGas, mu, buoyantWeight);
        Info<< setw(14) << e.keyword() << ' ' << setw(12) << u << "  "
            << setw(12) << u50 << nl;
        results.append(Tuple2<word, scalar>(e.keyword(), u));
    }

    Info<< nl;
    for (const auto& r : results)
    {
        Info<< "umf " << r.first() << ' ' << r.second() << nl;
    }
    Info<< nl << "End" << nl;
    return 0;
}
