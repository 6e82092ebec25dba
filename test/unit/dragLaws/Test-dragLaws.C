// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    Test-dragLaws

Description
    Every drag law of src/sinterPhysics/drag against values computed by hand
    (a separate Python evaluation of each law in its published dimensional
    form: beta of Wen-Yu, Ergun and Koch-Hill (Benyahia et al. 2006), the
    force of Di Felice, converted with
    F = d^2 beta/(18 mu eps (1 - eps)) or F = F_d/(3 pi mu d eps |u - v|);
    Beetstra as published in F), at five (eps, Re) points from packed
    (0.4) to dilute (0.95) and Re 0.5-500; the Gidaspow switch at
    eps = 0.8; the Stokes limits. Relative tolerance 1e-9 (the references
    have 11 significant digits).
    Run with -law NAME -bad to check the selection error instead.
*/

#include "argList.H"
#include "dragLaw.H"
#include "IOstreams.H"

using namespace Foam;

static label nFailed = 0;

void check(const word& what, const scalar value, const scalar reference)
{
    const scalar tol = 1e-9;
    const scalar rel = mag(value - reference)/mag(reference);
    const bool ok = rel <= tol;
    Info<< (ok ? "ok   " : "FAIL ") << what << ": " << value
        << " (reference " << reference << ", rel. error " << rel
        << ", tolerance " << tol << ")" << nl;
    if (!ok)
    {
        ++nFailed;
    }
}


autoPtr<dragLaw> law(const word& name)
{
    dictionary dict;
    dict.add("law", name);
    return dragLaw::New(dict);
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

    const scalar eps[5] = {0.4, 0.5, 0.7, 0.9, 0.95};
    const scalar Re[5] = {0.5, 10, 100, 1, 500};

    const wordList names({"Beetstra", "WenYu", "DiFelice", "Gidaspow", "KochHill"});
    const scalar reference[5][5] =
    {
        {3.7849525142e+01, 2.2773968590e+01, 1.9688225480e+01, 2.4981602959e+00, 2.1969024899e+01},
        {3.0986275685e+01, 2.1712402175e+01, 1.6722322348e+01, 1.6893229452e+00, 1.4135713594e+01},
        {3.0244260893e+01, 1.6786007557e+01, 1.5657291707e+01, 1.7743332829e+00, 1.7680362218e+01},
        {3.1553819444e+01, 2.0555555556e+01, 2.4943310658e+01, 1.6893229452e+00, 1.4135713594e+01},
        {3.7516183828e+01, 2.2289250000e+01, 1.6908814476e+01, 2.6568372902e+00, 2.1747430774e+01}
    };

    forAll(names, l)
    {
        const autoPtr<dragLaw> drag(law(names[l]));
        for (label k = 0; k < 5; ++k)
        {
            check
            (
                names[l] + "(eps " + name(eps[k]) + ", Re " + name(Re[k]) + ")",
                drag->F(eps[k], Re[k]),
                reference[l][k]
            );
        }
    }

    // Ergun at all voidages (beta of Ergun converted to F, as above)
    {
        const autoPtr<dragLaw> ergun(law("Ergun"));
        const scalar ergunRef[5] =
            {3.1553819444e+01, 2.0555555556e+01, 2.4943310658e+01,
             1.1488340192e+00, 5.4324407510e+01};
        for (label k = 0; k < 5; ++k)
        {
            check
            (
                "Ergun(eps " + name(eps[k]) + ", Re " + name(Re[k]) + ")",
                ergun->F(eps[k], Re[k]),
                ergunRef[k]
            );
        }
    }

    // Beetstra's polydisperse correction: (eps y + phi y^2 + 0.064 eps y^3)
    // times the monodisperse F at Re of the Sauter mean, y = d_i/<d>
    {
        dictionary dict;
        dict.add("law", "Beetstra");
        dict.add("polydisperse", true);
        const autoPtr<dragLaw> poly(dragLaw::New(dict));
        if (!poly->polydisperse() || law("Beetstra")->polydisperse())
        {
            Info<< "FAIL Beetstra: polydisperse switch not honoured" << nl;
            ++nFailed;
        }
        check("Beetstra poly(eps 0.4, Re 0.5, y 1.4)", poly->Fpolydisperse(0.4, 0.5, 1.4), 6.8365568530e+01);
        check("Beetstra poly(eps 0.5, Re 10, y 0.7)", poly->Fpolydisperse(0.5, 10, 0.7), 1.3800478390e+01);
        check("Beetstra poly(eps 0.7, Re 100, y 1) = (1 + 0.064 eps) F", poly->Fpolydisperse(0.7, 100, 1), 2.0570257982e+01);
        // a law without a size correction ignores y
        check("WenYu Fpolydisperse = F", law("WenYu")->Fpolydisperse(0.7, 100, 1.5), reference[1][2]);
    }

    // Gidaspow: Ergun just below eps = 0.8, Wen-Yu from 0.8 on
    const autoPtr<dragLaw> gidaspow(law("Gidaspow"));
    check("Gidaspow(eps 0.7999999, Re 1): Ergun", gidaspow->F(0.7999999, 1), 2.7560783800e+00);
    check("Gidaspow(eps 0.8, Re 1): Wen-Yu", gidaspow->F(0.8, 1), 2.5966857093e+00);

    // Koch-Hill: the dilute branches (phi <= 0.01) and the low-Re one
    const autoPtr<dragLaw> kochHill(law("KochHill"));
    check("KochHill(eps 0.995, Re 0.5): 1 + 3/8 Re'", kochHill->F(0.995, 0.5), 1.0882812500e+00);
    check("KochHill(eps 0.995, Re 200): F2 + F3 Re'", kochHill->F(0.995, 200), 5.2878527882e+00);
    check("KochHill(eps 0.95, Re 5): F0 + F1 Re'^2", kochHill->F(0.95, 5), 2.1321276493e+00);

    // Wen-Yu above Re = 1000: Cd = 0.44
    check("WenYu(eps 0.9, Re 2000)", law("WenYu")->F(0.9, 2000), 5.3862470717e+01);

    // Stokes limits of a single sphere (eps = 1, Re -> 0)
    check("Beetstra(1, 0) = 1 (Stokes)", law("Beetstra")->F(1, 0), 1);
    check("WenYu(1, 0) = 1 (Stokes)", law("WenYu")->F(1, 0), 1);
    check("DiFelice(1, 0) = 0.96 (Dallavalle)", law("DiFelice")->F(1, 0), 0.96);

    if (nFailed)
    {
        FatalErrorInFunction
            << nFailed << " drag-law checks failed" << exit(FatalError);
    }

    Info<< "all drag-law checks passed" << nl;
    return 0;
}
