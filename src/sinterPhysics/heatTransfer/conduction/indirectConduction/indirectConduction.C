// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "indirectConduction.H"
#include "selectedConstructor.H"
#include "addToRunTimeSelectionTable.H"
#include "error.H"

namespace Foam
{
    defineTypeNameAndDebug(indirectConduction, 0);
    defineRunTimeSelectionTable(indirectConduction, dictionary);
    addToRunTimeSelectionTable
    (
        indirectConduction,
        indirectConduction,
        dictionary
    );
}


Foam::autoPtr<Foam::indirectConduction> Foam::indirectConduction::New
(
    const dictionary& dict,
    const scalar ks
)
{
    const word name(dict.get<word>("indirect"));

    const auto cstr = selectedConstructor
    (
        dict, "indirect", name, *dictionaryConstructorTablePtr_
    );

    return autoPtr<indirectConduction>(cstr(dict, ks));
}
