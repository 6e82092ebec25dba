// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "diffusionSmoother.H"

Foam::diffusionSmoother::diffusionSmoother
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    mesh_(mesh),
    length_(dict.get<scalar>("smoothingLength")),
    solverControls_()
{
    if (length_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "smoothingLength " << length_ << " must be > 0 [m]"
            << exit(FatalIOError);
    }

    solverControls_.add("solver", "PCG");
    solverControls_.add("preconditioner", "DIC");
    solverControls_.add("tolerance", 1e-12);
    solverControls_.add("relTol", 0.0);
    solverControls_.add("maxIter", 1000);
}
