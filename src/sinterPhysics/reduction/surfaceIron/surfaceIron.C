// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "surfaceIron.H"
#include "keywordRange.H"

Foam::surfaceIron::surfaceIron(const dictionary& dict)
:
    path_(dict),
    s_
    (
        keywordRange::getOrDefault
        (
            dict, "surfaceIronExponent", 1, 0, 1,
            "the exponent s of the surface iron fraction phi^s (1: the"
            " iron's volume fraction, towards 0: an iron shell)", true
        )
    )
{}


Foam::surfaceIron::surfaceIron(const ironOxidePath& path, const scalar s)
:
    path_(path),
    s_(s)
{}
