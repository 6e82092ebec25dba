// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "volumeFractionModel.H"
#include "selectedConstructor.H"

namespace Foam
{
    defineTypeNameAndDebug(volumeFractionModel, 0);
    defineRunTimeSelectionTable(volumeFractionModel, dictionary);
}


Foam::volumeFractionModel::volumeFractionModel
(
    const fvMesh& mesh,
    const dictionary&
)
:
    mesh_(mesh)
{}


Foam::autoPtr<Foam::volumeFractionModel> Foam::volumeFractionModel::New
(
    const fvMesh& mesh,
    const dictionary& dict
)
{
    const word methodName(dict.get<word>("volumeFraction"));

    const auto cstr = selectedConstructor
    (
        dict, "volumeFraction", methodName, *dictionaryConstructorTablePtr_
    );

    Info<< "Selecting volumeFraction " << methodName << endl;

    return autoPtr<volumeFractionModel>(cstr(mesh, dict));
}


Foam::tmp<Foam::vectorField> Foam::volumeFractionModel::pointValues
(
    const vectorField& cellValues
) const
{
    return tmp<vectorField>::New();
}
