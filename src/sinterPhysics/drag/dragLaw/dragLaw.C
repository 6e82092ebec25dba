// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "dragLaw.H"
#include "error.H"

namespace Foam
{
    defineTypeNameAndDebug(dragLaw, 0);
    defineRunTimeSelectionTable(dragLaw, dictionary);
}


Foam::autoPtr<Foam::dragLaw> Foam::dragLaw::New(const dictionary& dict)
{
    const word lawName(dict.get<word>("law"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(lawName);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "law",
            lawName,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<dragLaw>(cstrIter()(dict));
}


Foam::scalar Foam::dragLaw::CdRe24SchillerNaumann(const scalar Re)
{
    return Re < 1000 ? 1 + 0.15*std::pow(Re, 0.687) : 0.44*Re/24;
}
