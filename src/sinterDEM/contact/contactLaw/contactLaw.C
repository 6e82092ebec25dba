// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "contactLaw.H"

namespace Foam
{
    defineTypeNameAndDebug(contactLaw, 0);
    defineRunTimeSelectionTable(contactLaw, dictionary);
}


Foam::contactLaw::contactLaw
(
    const dictionary& dict,
    const scalar coarseGrainFactor,
    contactSlots& slots,
    const bool restitution
)
:
    particle_(dict.subDict("particle")),
    wall_(dict.subDict("wall")),
    particleParticle_(dict.subDict("particleParticle"), restitution),
    particleWall_(dict.subDict("particleWall"), restitution),
    coarseGrainFactor_(coarseGrainFactor),
    springSlot_(slots.addVector("spring", "contactLaw", true))
{}


Foam::autoPtr<Foam::contactLaw> Foam::contactLaw::New
(
    const dictionary& dict,
    const scalar coarseGrainFactor,
    contactSlots& slots
)
{
    const word lawType(dict.get<word>("contactLaw"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(lawType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "contactLaw",
            lawType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(dict, coarseGrainFactor, slots);
}
