// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "cellVolumeFraction.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace volumeFractionModels
{
    defineTypeNameAndDebug(cellVolumeFraction, 0);
    addToRunTimeSelectionTable
    (
        volumeFractionModel,
        cellVolumeFraction,
        dictionary
    );
}
}


Foam::volumeFractionModels::cellVolumeFraction::cellVolumeFraction
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    volumeFractionModel(mesh, dict)
{}


Foam::tmp<Foam::scalarField>
Foam::volumeFractionModels::cellVolumeFraction::theta
(
    const UPtrList<const particle>& particles,
    const scalarField& solidVolume
) const
{
    auto tTheta = tmp<scalarField>::New(mesh_.nCells(), Zero);
    scalarField& theta = tTheta.ref();

    forAll(particles, i)
    {
        theta[particles[i].cell()] += solidVolume[i];
    }

    theta /= mesh_.V().field();

    return tTheta;
}


Foam::vector Foam::volumeFractionModels::cellVolumeFraction::gather
(
    const particle& p,
    const vectorField& cellValues,
    const vectorField&
) const
{
    return cellValues[p.cell()];
}
