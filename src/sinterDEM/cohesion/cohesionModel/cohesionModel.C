// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "cohesionModel.H"
#include "selectedConstructor.H"

namespace Foam
{
    defineTypeNameAndDebug(cohesionModel, 0);
    defineRunTimeSelectionTable(cohesionModel, dictionary);
}


Foam::autoPtr<Foam::cohesionModel> Foam::cohesionModel::New
(
    const dictionary& dict,
    const contactLaw& law,
    const scalar coarseGrainFactor,
    contactSlots& slots
)
{
    const word modelType(dict.lookupOrDefault<word>("cohesionModel", "none"));

    const auto cstr = selectedConstructor
    (
        dict, "cohesionModel", modelType, *dictionaryConstructorTablePtr_
    );

    Info<< "Selecting cohesionModel " << modelType << endl;

    return cstr(dict, law, coarseGrainFactor, slots);
}
