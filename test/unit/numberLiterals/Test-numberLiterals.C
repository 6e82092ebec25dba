// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    Test-numberLiterals

Description
    numberLiterals decides without converting whether a number written in
    a dictionary overflows a double (OpenFOAM's reader traps on it):
    literals on both sides of the largest double, 1.7976931348623157e308,
    written with their point and exponent in different places; zeros and
    tiny numbers never overflow. Then a file with 1e400 in a comment, a
    string and a word (not numbers) passes, and one with 1e400 as a value
    is fatal naming the keyword and the line.
*/

#include "argList.H"
#include "OFstream.H"
#include "numberLiterals.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::noParallel();
    argList::addBoolOption("fatal", "a file with 1e400 as a value (fatal)");
    argList args(argc, argv, false, false, false);

    struct Case { const char* text; bool beyond; long exponent; };
    const Case cases[] =
    {
        {"1e308", false, 308},
        {"1.7976931348623157e308", false, 308},
        {"17976931348623157e292", false, 308},
        {"0.00017976931348623157e312", false, 308},
        {"1.7976931348623159e308", true, 308},
        {"1.8e308", true, 308},
        {"0.00018e312", true, 308},
        {"180000000000000000000e288", true, 308},
        {"1e309", true, 309},
        {"1e400", true, 400},
        {"-1e400", true, 400},
        {"+2E+400", true, 400},
        {"1e-400", false, -400},
        {"123.45", false, 2},
        {".5", false, -1},
        {"0.0", false, -1000000000L},
        {"0e999", false, -1000000000L},
    };

    label nFail = 0;
    for (const Case& c : cases)
    {
        const std::string t(c.text);
        const long e = numberLiterals::decimalExponent(t, 0, t.size());
        const bool b = numberLiterals::beyondDouble(t, 0, t.size());
        const bool ok = (e == c.exponent && b == c.beyond);
        Info<< (ok ? "ok   " : "FAIL ") << t << ": exponent " << label(e)
            << ", overflows " << b << endl;
        if (!ok) ++nFail;
    }

    const fileName harmless("numberLiterals.harmless");
    {
        OFstream os(harmless);
        os  << "// 1e400 in a comment\n/* and 2e999\n */\n"
            << "name \"1e400 in a string\";\nversion v1e400;\nx 1.5e308;\n";
    }
    numberLiterals::checkFile(harmless);
    Info<< "ok   a file with 1e400 only in a comment, a string and a word"
        << endl;

    if (args.found("fatal"))
    {
        const fileName bad("numberLiterals.bad");
        {
            OFstream os(bad);
            os  << "a 1;\n// a comment\nyoungsModulus   1e400; // [Pa]\n";
        }
        numberLiterals::checkFile(bad);
        FatalErrorInFunction << "1e400 was accepted" << exit(FatalError);
    }

    if (nFail)
    {
        FatalErrorInFunction << nFail << " cases failed" << exit(FatalError);
    }
    Info<< "End" << endl;
    return 0;
}
