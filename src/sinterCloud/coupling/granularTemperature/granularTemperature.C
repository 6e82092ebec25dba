// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "granularTemperature.H"
#include "error.H"

Foam::tmp<Foam::scalarField> Foam::granularTemperature::cells
(
    const label nCells,
    const labelUList& cell,
    const UList<vector>& U
)
{
    if (cell.size() != U.size())
    {
        FatalErrorInFunction
            << cell.size() << " cells for " << U.size() << " velocities"
            << abort(FatalError);
    }

    labelList n(nCells, 0);
    vectorField mean(nCells, Zero);
    forAll(cell, i)
    {
        const label c = cell[i];
        if (c < 0 || c >= nCells)
        {
            FatalErrorInFunction
                << "Particle " << i << " in cell " << c << " of " << nCells
                << abort(FatalError);
        }
        ++n[c];
        mean[c] += U[i];
    }
    forAll(mean, c)
    {
        if (n[c])
        {
            mean[c] /= n[c];
        }
    }

    tmp<scalarField> tTheta(new scalarField(nCells, scalar(0)));
    scalarField& Theta = tTheta.ref();
    forAll(cell, i)
    {
        Theta[cell[i]] += magSqr(U[i] - mean[cell[i]]);
    }
    forAll(Theta, c)
    {
        Theta[c] = n[c] > 1 ? Theta[c]/(3*n[c]) : scalar(0);
    }

    return tTheta;
}
