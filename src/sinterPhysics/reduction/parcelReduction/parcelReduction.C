// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "parcelReduction.H"
#include "keywordSource.H"
#include "knownKeywords.H"

// * * * * * * * * * * * * * * * Local functions * * * * * * * * * * * * * //

namespace
{

//- dict, its keywords checked first
const Foam::dictionary& checked
(
    const Foam::dictionary& dict,
    const Foam::wordList& readerKeywords
)
{
    Foam::wordList valid({"kinetics", "acceleration"});
    valid.append(readerKeywords);
    Foam::knownKeywords::check(dict, valid);
    return dict;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::parcelReduction::parcelReduction
(
    const dictionary& dict,
    const dictionary& material,
    const wordList& readerKeywords
)
:
    law_(reductionLaw::New(checked(dict, readerKeywords).subDict("kinetics"))),
    path_(material),
    acceleration_(dict.lookupOrDefault<scalar>("acceleration", 1))
{
    if (!(acceleration_ >= 1 && acceleration_ <= 1e6))
    {
        FatalIOErrorInKeyword(dict, "acceleration")
            << "Keyword acceleration in " << dict.name() << " is the"
            << " chemistry's time-acceleration factor and must lie in"
            << " [1, 1e6] (1: real time), not " << acceleration_
            << exit(FatalIOError);
    }
}


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
