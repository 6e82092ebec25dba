// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "reductionLaw.H"
#include "selectedConstructor.H"
#include "error.H"

namespace Foam
{
    defineTypeNameAndDebug(reductionLaw, 0);
    defineRunTimeSelectionTable(reductionLaw, dictionary);
}


Foam::autoPtr<Foam::reductionLaw> Foam::reductionLaw::New
(
    const dictionary& dict
)
{
    const word lawName(dict.get<word>("law"));

    const auto cstr = selectedConstructor
    (
        dict, "law", lawName, *dictionaryConstructorTablePtr_
    );

    return autoPtr<reductionLaw>(cstr(dict));
}
