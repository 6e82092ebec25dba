// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "cohesionModel.H"

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

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "cohesionModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    Info<< "Selecting cohesionModel " << modelType << endl;

    return cstrIter()(dict, law, coarseGrainFactor, slots);
}
