// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "directConduction.H"
#include "selectedConstructor.H"
#include "addToRunTimeSelectionTable.H"
#include "error.H"

namespace Foam
{
    defineTypeNameAndDebug(directConduction, 0);
    defineRunTimeSelectionTable(directConduction, dictionary);
    addToRunTimeSelectionTable(directConduction, directConduction, dictionary);
}


Foam::autoPtr<Foam::directConduction> Foam::directConduction::New
(
    const dictionary& dict
)
{
    const word name(dict.get<word>("direct"));

    const auto cstr = selectedConstructor
    (
        dict, "direct", name, *dictionaryConstructorTablePtr_
    );

    return autoPtr<directConduction>(cstr(dict));
}
