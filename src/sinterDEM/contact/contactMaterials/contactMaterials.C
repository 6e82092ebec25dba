// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "contactMaterials.H"
#include "DynamicList.H"
#include "IOdictionary.H"
#include "Time.H"

namespace
{

//- The names of the materials of the file (every dictionary entry)
Foam::wordList materialNames(const Foam::dictionary& dict)
{
    Foam::DynamicList<Foam::word> names;
    for (const Foam::entry& e : dict)
    {
        if (e.isDict() && e.keyword() != "walls")
        {
            names.append(e.keyword());
        }
    }
    return Foam::wordList(std::move(names));
}

//- The material name of an entry of walls
Foam::word materialName(const Foam::entry& e, const Foam::dictionary& walls)
{
    if (e.isDict())
    {
        FatalIOErrorInFunction(walls)
            << "Entry " << e.keyword() << " of " << walls.name()
            << " must name a material of the file, not give a dictionary"
            << Foam::exit(Foam::FatalIOError);
    }
    Foam::word name;
    e.stream() >> name;
    return name;
}

} // End anonymous namespace


const Foam::dictionary& Foam::contactMaterials::material
(
    const word& name,
    const dictionary& from,
    const word& key
) const
{
    const dictionary* matPtr = dict_.findDict(name, keyType::LITERAL);
    if (!matPtr || name == "walls")
    {
        FatalIOErrorInFunction(from)
            << "Unknown material " << name << " for keyword " << key
            << " in " << from.name() << nl
            << "Valid materials are " << materialNames(dict_)
            << exit(FatalIOError);
    }
    return *matPtr;
}


Foam::contactMaterials::contactMaterials(const dictionary& dict)
:
    dict_(dict),
    particleName_(dict.get<word>("particle")),
    particle_(material(particleName_, dict, "particle"))
{
    const dictionary& walls = dict_.subDict("walls");
    for (const entry& e : walls)
    {
        const word name(materialName(e, walls));
        if (!wallNames_.found(name))
        {
            walls_.append
            (
                new contactMaterial(material(name, walls, e.keyword()))
            );
            wallNames_.append(name);
        }
    }
}


Foam::label Foam::contactMaterials::wallMaterial(const word& patchName) const
{
    const dictionary& walls = dict_.subDict("walls");
    const entry* ePtr = walls.findEntry(patchName, keyType::REGEX);
    if (!ePtr)
    {
        FatalIOErrorInFunction(walls)
            << "No entry of " << walls.name() << " matches the wall patch "
            << patchName << ": give the material of every DEM wall patch"
            << exit(FatalIOError);
    }
    return wallNames_.find(materialName(*ePtr, walls));
}


void Foam::contactMaterials::checkSame
(
    const dictionary& dict,
    const word& key,
    const scalar value,
    const word& materialKey
) const
{
    const dictionary& mat = particleDict();
    const scalar expected = mat.get<scalar>(materialKey);
    if (mag(value - expected) > 1e-12*mag(expected))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword " << key << " " << value << " in " << dict.name()
            << " is not the " << materialKey << " " << expected
            << " of the particles' material in " << mat.name() << nl
            << "A material constant has one source: write " << key
            << " $/materials/" << particleName_ << '/' << materialKey
            << "; with materials { #include \"materialProperties\" }"
            << exit(FatalIOError);
    }
}


Foam::dictionary Foam::contactMaterials::read(const objectRegistry& db)
{
    return IOdictionary
    (
        IOobject
        (
            "materialProperties",
            db.time().constant(),
            db,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
}


Foam::scalar Foam::contactMaterials::positive
(
    const dictionary& dict,
    const word& key
)
{
    const scalar value = dict.get<scalar>(key);
    if (!(value > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword " << key << " in " << dict.name()
            << " must be positive, not " << value << exit(FatalIOError);
    }
    return value;
}
