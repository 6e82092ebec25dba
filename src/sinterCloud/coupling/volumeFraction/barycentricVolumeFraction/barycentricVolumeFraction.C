// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "barycentricVolumeFraction.H"
#include "addToRunTimeSelectionTable.H"
#include "syncTools.H"

namespace Foam
{
namespace volumeFractionModels
{
    defineTypeNameAndDebug(barycentricVolumeFraction, 0);
    addToRunTimeSelectionTable
    (
        volumeFractionModel,
        barycentricVolumeFraction,
        dictionary
    );
}
}


Foam::volumeFractionModels::barycentricVolumeFraction::barycentricVolumeFraction
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    volumeFractionModel(mesh, dict),
    pointCellVolume_(mesh.nPoints(), Zero)
{
    const labelListList& pointCells = mesh.pointCells();
    const scalarField& V = mesh.V();

    forAll(pointCells, pointi)
    {
        for (const label celli : pointCells[pointi])
        {
            pointCellVolume_[pointi] += V[celli];
        }
    }

    syncTools::syncPointList
    (
        mesh,
        pointCellVolume_,
        plusEqOp<scalar>(),
        scalar(0)
    );
}


Foam::tmp<Foam::scalarField>
Foam::volumeFractionModels::barycentricVolumeFraction::theta
(
    const UPtrList<const particle>& particles,
    const scalarField& solidVolume
) const
{
    const scalarField& V = mesh_.V();

    // Solid volume at cell centres and at mesh points
    auto tTheta = tmp<scalarField>::New(mesh_.nCells(), Zero);
    scalarField& cellSolid = tTheta.ref();
    scalarField pointSolid(mesh_.nPoints(), Zero);

    forAll(particles, i)
    {
        const particle& p = particles[i];
        const scalar Vp = solidVolume[i];
        const barycentric& b = p.coordinates();
        const triFace tri(p.currentTetIndices().faceTriIs(mesh_));

        cellSolid[p.cell()] += b[0]*Vp;
        pointSolid[tri[0]] += b[1]*Vp;
        pointSolid[tri[1]] += b[2]*Vp;
        pointSolid[tri[2]] += b[3]*Vp;
    }

    // A point on a processor boundary collects the shares of every side
    syncTools::syncPointList
    (
        mesh_,
        pointSolid,
        plusEqOp<scalar>(),
        scalar(0)
    );

    // Each point passes its solid on to the cells around it by volume
    const labelListList& pointCells = mesh_.pointCells();

    forAll(pointCells, pointi)
    {
        if (pointSolid[pointi] != 0)
        {
            const scalar perVolume = pointSolid[pointi]/pointCellVolume_[pointi];

            for (const label celli : pointCells[pointi])
            {
                cellSolid[celli] += perVolume*V[celli];
            }
        }
    }

    cellSolid /= V;

    return tTheta;
}


Foam::tmp<Foam::vectorField>
Foam::volumeFractionModels::barycentricVolumeFraction::pointValues
(
    const vectorField& cellValues
) const
{
    // The transpose of theta()'s point step: each point averages the cells
    // around it (on every processor) by volume
    const scalarField& V = mesh_.V();
    const labelListList& pointCells = mesh_.pointCells();

    auto tValues = tmp<vectorField>::New(mesh_.nPoints(), Zero);
    vectorField& values = tValues.ref();

    forAll(pointCells, pointi)
    {
        for (const label celli : pointCells[pointi])
        {
            values[pointi] += V[celli]*cellValues[celli];
        }
    }

    syncTools::syncPointList
    (
        mesh_,
        values,
        plusEqOp<vector>(),
        vector::zero
    );

    values /= pointCellVolume_;

    return tValues;
}


Foam::vector Foam::volumeFractionModels::barycentricVolumeFraction::gather
(
    const particle& p,
    const vectorField& cellValues,
    const vectorField& pointValues
) const
{
    const barycentric& b = p.coordinates();
    const triFace tri(p.currentTetIndices().faceTriIs(mesh_));

    return
        b[0]*cellValues[p.cell()]
      + b[1]*pointValues[tri[0]]
      + b[2]*pointValues[tri[1]]
      + b[3]*pointValues[tri[2]];
}
