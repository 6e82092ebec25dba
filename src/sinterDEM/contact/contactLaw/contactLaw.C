// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "contactLaw.H"
#include "selectedConstructor.H"
#include "keywordSource.H"

namespace Foam
{
    defineTypeNameAndDebug(contactLaw, 0);
    defineRunTimeSelectionTable(contactLaw, dictionary);
}


namespace
{

//- Elastic data in the law's settings are an old layout: fatal
void checkNoMaterials(const Foam::dictionary& dict)
{
    for (const char* key : {"particle", "wall"})
    {
        if (dict.found(key))
        {
            FatalIOErrorInKeyword(dict, key)
                << "Keyword " << key << " in " << dict.name()
                << " is no longer read: the elastic data of the particles"
                << " and walls are in constant/materialProperties"
                << " (youngsModulus, demYoungsModulus, poissonsRatio of"
                << " the materials named by particle and walls)"
                << Foam::exit(Foam::FatalIOError);
        }
    }
}

} // End anonymous namespace


Foam::contactLaw::contactLaw
(
    const dictionary& dict,
    const contactMaterials& materials,
    const scalar coarseGrainFactor,
    contactSlots& slots,
    const bool restitution
)
:
    materials_((checkNoMaterials(dict), materials)),
    particleParticle_(dict.subDict("particleParticle"), restitution),
    particleWall_(dict.subDict("particleWall"), restitution),
    coarseGrainFactor_(coarseGrainFactor),
    springSlot_(slots.addVector("spring", "contactLaw", true))
{}


Foam::autoPtr<Foam::contactLaw> Foam::contactLaw::New
(
    const dictionary& dict,
    const contactMaterials& materials,
    const scalar coarseGrainFactor,
    contactSlots& slots
)
{
    const word lawType(dict.get<word>("contactLaw"));

    const auto cstr = selectedConstructor
    (
        dict, "contactLaw", lawType, *dictionaryConstructorTablePtr_
    );

    return cstr(dict, materials, coarseGrainFactor, slots);
}
