// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "diffusionSmoother.H"
#include "keywordSource.H"

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
    if (!(length_ > 0))
    {
        FatalIOErrorInKeyword(dict, "smoothingLength")
            << "smoothingLength " << length_ << " must be > 0 [m]"
            << exit(FatalIOError);
    }
    // Longer than the domain's diagonal smooths the whole domain to its
    // mean: a length in other units than metres, or a slip
    const scalar diagonal = mesh.bounds().mag();
    if (length_ > diagonal)
    {
        FatalIOErrorInKeyword(dict, "smoothingLength")
            << "smoothingLength " << length_ << " [m] is longer than the"
            << " domain's diagonal " << diagonal << " m" << nl
            << "It would spread every source over the whole domain (lengths"
            << " are in metres)" << exit(FatalIOError);
    }

    solverControls_.add("solver", "PCG");
    solverControls_.add("preconditioner", "DIC");
    solverControls_.add("tolerance", 1e-12);
    solverControls_.add("relTol", 0.0);
    solverControls_.add("maxIter", 1000);
}
