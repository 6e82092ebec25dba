// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "dragLaw.H"
#include "selectedConstructor.H"
#include "error.H"
#include "knownKeywords.H"
#include "keywordSource.H"

namespace Foam
{
    defineTypeNameAndDebug(dragLaw, 0);
    defineRunTimeSelectionTable(dragLaw, dictionary);
}


Foam::autoPtr<Foam::dragLaw> Foam::dragLaw::New
(
    const dictionary& dict,
    const wordList& readerKeywords
)
{
    const word lawName(dict.get<word>("law"));

    const auto cstr = selectedConstructor
    (
        dict, "law", lawName, *dictionaryConstructorTablePtr_
    );

    autoPtr<dragLaw> law(cstr(dict));

    wordList valid(law->keywords());

    // "polydisperse false" is true of every law; "true" for a law without
    // a size correction would be ignored, so it is fatal and names the
    // laws that have one
    if (!valid.found("polydisperse") && dict.found("polydisperse"))
    {
        if (dict.get<bool>("polydisperse"))
        {
            wordList withCorrection;
            for (const word& name : dictionaryConstructorTablePtr_->sortedToc())
            {
                dictionary probe;
                probe.add("law", name);
                if
                (
                    (*dictionaryConstructorTablePtr_)[name](probe)
                   ->keywords().found("polydisperse")
                )
                {
                    withCorrection.append(name);
                }
            }
            FatalIOErrorInKeyword(dict, "polydisperse")
                << "Keyword polydisperse true in " << dict.name()
                << ": drag law " << lawName
                << " has no polydisperse correction" << nl
                << "Laws with one are " << withCorrection
                << exit(FatalIOError);
        }
        valid.append(word("polydisperse"));
    }
    valid.append(word("law"));
    valid.append(readerKeywords);
    knownKeywords::check(dict, valid);

    return law;
}


Foam::scalar Foam::dragLaw::CdRe24SchillerNaumann(const scalar Re)
{
    return Re < 1000 ? 1 + 0.15*std::pow(Re, 0.687) : 0.44*Re/24;
}
