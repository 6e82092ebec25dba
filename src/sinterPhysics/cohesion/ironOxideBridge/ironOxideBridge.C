// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "ironOxideBridge.H"

Foam::ironOxideBridge::ironOxideBridge
(
    const sinterMaterial& oxide,
    const sinterMaterial& iron,
    const dictionary& dict
)
:
    oxide_(oxide, dict),
    iron_(iron, dict)
{}


Foam::ironOxideBridge::ironOxideBridge
(
    const sinterMaterial& oxide,
    const sinterMaterial& iron,
    const solidBridge::surfaceModel model
)
:
    oxide_(oxide, model),
    iron_(iron, model)
{}


Foam::scalar Foam::ironOxideBridge::force
(
    const scalar rp,
    const scalar T,
    const scalar t,
    const scalar fi,
    const scalar fj
) const
{
    const scalar p = ironShare(fi, fj);
    const scalar Fox = p < 1 ? oxide_.force(rp, T, t) : 0;
    const scalar FFe = p > 0 ? iron_.force(rp, T, t) : 0;
    return blend(Fox, FFe, p);
}
