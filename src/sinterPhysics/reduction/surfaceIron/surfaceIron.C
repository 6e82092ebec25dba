// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "surfaceIron.H"
#include "keywordRange.H"

namespace
{

Foam::scalar readExponent(const Foam::dictionary& dict)
{
    return Foam::keywordRange::getOrDefault
    (
        dict, "surfaceIronExponent", 1, 0, 1,
        "the exponent s of the surface iron fraction phi^s (1: the"
        " iron's volume fraction, towards 0: an iron shell)", true
    );
}

} // End anonymous namespace


Foam::surfaceIron::surfaceIron(const dictionary& dict)
:
    ownPath_(new ironOxidePath(dict)),
    path_(ownPath_()),
    s_(readExponent(dict))
{}


Foam::surfaceIron::surfaceIron
(
    const ironOxidePath& path,
    const dictionary& dict
)
:
    ownPath_(),
    path_(path),
    s_(readExponent(dict))
{}


Foam::surfaceIron::surfaceIron(const ironOxidePath& path, const scalar s)
:
    ownPath_(),
    path_(path),
    s_(s)
{}
