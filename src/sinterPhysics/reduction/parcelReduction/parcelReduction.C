// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "parcelReduction.H"
#include "keywordRange.H"
#include "knownKeywords.H"

// * * * * * * * * * * * * * * * Local functions * * * * * * * * * * * * * //

namespace
{

//- The keywords of the reduction dictionary and of its reader
Foam::wordList validKeywords(const Foam::wordList& readerKeywords)
{
    Foam::wordList valid({"kinetics", "acceleration"});
    valid.append(readerKeywords);
    return valid;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::parcelReduction::parcelReduction
(
    const dictionary& dict,
    autoPtr<ironOxidePath>&& own,
    const ironOxidePath* given,
    const wordList& readerKeywords
)
:
    law_
    (
        reductionLaw::New
        (
            knownKeywords::checked(dict, validKeywords(readerKeywords))
           .subDict("kinetics")
        )
    ),
    ownPath_(std::move(own)),
    path_(given ? *given : ownPath_()),
    acceleration_
    (
        keywordRange::getOrDefault
        (
            dict, "acceleration", 1, 1, 1e6,
            "the chemistry's time-acceleration factor (1: real time)"
        )
    )
{}


Foam::parcelReduction::parcelReduction
(
    const dictionary& dict,
    const dictionary& material,
    const wordList& readerKeywords
)
:
    parcelReduction
    (
        dict,
        autoPtr<ironOxidePath>(new ironOxidePath(material)),
        nullptr,
        readerKeywords
    )
{}


Foam::parcelReduction::parcelReduction
(
    const dictionary& dict,
    const ironOxidePath& path,
    const wordList& readerKeywords
)
:
    parcelReduction(dict, autoPtr<ironOxidePath>(), &path, readerKeywords)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::parcelReduction::step Foam::parcelReduction::advance
(
    const scalar X,
    const scalar T,
    const scalar m,
    const scalar yH2,
    const scalar dt
) const
{
    const scalar X1 = law_->advance(X, T, yH2, acceleration_*dt);
    const scalar m0 = m/path_.massRatio(X);
    return
    {
        X1,
        m0*path_.oxygen()*(X1 - X),
        m0*path_.enthalpy(X, X1, T),
        m0*path_.massRatio(X1)
    };
}
