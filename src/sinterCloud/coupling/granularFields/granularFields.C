// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "granularFields.H"
#include "granularTemperature.H"
#include "ZehnerSchlunder.H"

Foam::granularFields::granularFields(const fvMesh& mesh)
:
    granularTemperature_
    (
        IOobject
        (
            "granularTemperature",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar(sqr(dimVelocity), Zero)
    ),
    kineticConductivity_
    (
        IOobject
        (
            "solidKineticConductivity",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar(dimPower/dimLength/dimTemperature, Zero)
    )
{}


void Foam::granularFields::update
(
    const labelUList& cell,
    const UList<vector>& U,
    const UList<scalar>& rhoCpd
)
{
    const label nCells = granularTemperature_.mesh().nCells();
    scalarField sumRhoCpd(nCells, scalar(0));
    labelList n(nCells, 0);
    forAll(cell, i)
    {
        sumRhoCpd[cell[i]] += rhoCpd[i];
        ++n[cell[i]];
    }

    scalarField& Theta = granularTemperature_.primitiveFieldRef();
    Theta = granularTemperature::cells(nCells, cell, U);
    scalarField& kKinetic = kineticConductivity_.primitiveFieldRef();
    forAll(kKinetic, c)
    {
        kKinetic[c] =
            n[c]
          ? ZehnerSchlunder::solidKinetic(sumRhoCpd[c]/n[c], 1, 1, Theta[c])
          : scalar(0);
    }
    granularTemperature_.correctBoundaryConditions();
    kineticConductivity_.correctBoundaryConditions();
}
