// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    Test-keywordSource

Description
    keywordSource finds the file and line where a dictionary entry's value
    was written, which OpenFOAM v1912 does not keep for included files.
    A top file includes a settings file (by a name built from a variable)
    and a second one; its entries take values from them ($K, $name), are
    written in the top file, or are computed (#eval). Each source is
    checked by file and line; a value that two included files hold on the
    same line, and a missing keyword, have no source (the dictionary's
    own range is reported then). With -fatal, FatalIOErrorInKeyword names
    the settings file and its line.
*/

#include "argList.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "keywordSource.H"
#include "unitCheck.H"

using namespace Foam;

namespace
{

void write(const fileName& f, const char* text)
{
    OFstream os(f);
    os  << text;
}


//- The source of key in dict must be file:line (empty file: no source)
void expect
(
    const dictionary& dict,
    const word& key,
    const fileName& file,
    const label line,
    const bool elsewhere
)
{
    const keywordSource src(dict, key);
    const bool pass =
        src.file() == file
     && (file.empty() || (src.line() == line && src.elsewhere() == elsewhere));
    Info<< (pass ? "ok   " : "FAIL ") << key << ": "
        << (src.file().empty() ? string("(no source)") : string(src.file()))
        << " line " << src.line() << (src.elsewhere() ? " (elsewhere)" : "")
        << ", expected "
        << (file.empty() ? string("(no source)") : string(file)) << " line "
        << line << nl;
    if (!pass)
    {
        ++unitTest::nFailed();
    }
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList::addBoolOption("fatal", "a fatal error for a value set elsewhere");
    argList args(argc, argv, false, false, false);

    const fileName dir(cwd());
    const fileName top(dir/"keywordSource.top");
    const fileName settings(dir/"keywordSource.settings");
    const fileName other(dir/"keywordSource.other");

    write
    (
        settings,
        "// settings, as a case's system/caseSettings\n"
        "\n"
        "K           0;      // line 3\n"
        "x           7;      // line 4: 7 also on line 4 of other\n"
        "name        fine;\n"
        "mass        5e-3;\n"
    );
    write
    (
        other,
        "/* a block comment\n"
        "   over two lines */\n"
        "y           1;\n"
        "z           7;\n"
    );
    write
    (
        top,
        "FoamFile { version 2.0; format ascii; class dictionary; }\n"
        "which       settings;\n"
        "#include \"keywordSource.$which\"\n"
        "#include \"keywordSource.other\"\n"
        "sub\n"
        "{\n"
        "    coarse      $K;\n"
        "    own         -2;         // line 8\n"
        "    computed    #eval{ 2*$mass };   // line 9\n"
        "    label       $name;\n"
        "    ambiguous   $x;\n"
        "}\n"
    );

    IFstream is(top);
    const dictionary dict(is);
    const dictionary& sub = dict.subDict("sub");

    expect(sub, "coarse", settings, 3, true);
    expect(sub, "label", settings, 5, true);
    expect(sub, "own", top, 8, false);
    expect(sub, "computed", top, 9, false);
    expect(sub, "ambiguous", fileName(), -1, false);
    expect(sub, "missing", fileName(), -1, false);
    expect(dict, "y", other, 3, true);

    const fileName own(keywordSource::ownFile(sub));
    const bool ownOk = own == top;
    Info<< (ownOk ? "ok   " : "FAIL ") << "own file of " << sub.name()
        << ": " << own << nl;
    if (!ownOk)
    {
        ++unitTest::nFailed();
    }

    if (args.found("fatal"))
    {
        FatalIOErrorInKeyword(sub, "coarse")
            << "coarse " << sub.get<scalar>("coarse") << " must be >= 1"
            << exit(FatalIOError);
    }

    Info<< nl << unitTest::nFailed() << " failed" << endl;
    return unitTest::nFailed() ? 1 : 0;
}
