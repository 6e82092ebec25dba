// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "contactMaterials.H"
#include "keywordRange.H"
#include "knownKeywords.H"
#include "sinterMaterial.H"
#include "DynamicList.H"
#include "IOdictionary.H"
#include "Time.H"
#include "StringStream.H"
#include "keywordSource.H"

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
        FatalIOErrorInKeyword(walls, e.keyword())
            << "Entry " << e.keyword() << " of " << walls.name()
            << " must name a material of the file, not give a dictionary"
            << Foam::exit(Foam::FatalIOError);
    }
    Foam::word name;
    e.stream() >> name;
    return name;
}

//- Fatal: keyword key of dict has a value outside range (a physical
//  range, with its unit: outside it the value is a typing or unit error)
void outOfRange
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Foam::scalar value,
    const Foam::string& range,
    const char* hint = ""
)
{
    FatalIOErrorInKeyword(dict, key)
        << "Keyword " << key << " in " << dict.name() << " must lie in "
        << range.c_str() << ", not " << value << hint
        << Foam::exit(Foam::FatalIOError);
}

//- If dict has key, fatal unless its value lies in [lo, hi] unit
void optionalInRange
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Foam::scalar lo,
    const Foam::scalar hi,
    const char* unit
)
{
    if (!dict.found(key))
    {
        return;
    }
    const Foam::scalar value = dict.get<Foam::scalar>(key);
    if (!(value >= lo && value <= hi))
    {
        Foam::OStringStream range;
        range << '[' << lo << ", " << hi << "] " << unit;
        outOfRange(dict, key, value, range.str());
    }
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
        FatalIOErrorInKeyword(from, key)
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
    particle_(material(particleName_, dict, "particle")),
    heatCapacityScale_(1)
{
    // Materials (every dictionary but walls), particle and walls only
    const wordList names(materialNames(dict_));
    for (const word& name : names)
    {
        const dictionary& mat = dict_.subDict(name);
        knownKeywords::check(mat, sinterMaterial::keywords());
        optionalInRange
        (
            mat, "density", sinterMaterial::densityMin(),
            sinterMaterial::densityMax(), "kg/m^3"
        );
        optionalInRange(mat, "specificHeat", 10, 1e5, "J/(kg K)");
        optionalInRange(mat, "thermalConductivity", 1e-3, 1e4, "W/(m K)");
    }
    wordList valid(names);
    valid.append(word("particle"));
    valid.append(word("reducedSurface"));
    valid.append(word("walls"));
    valid.append(word("heatCapacityScale"));
    knownKeywords::check(dict_, valid);

    if (dict_.found("heatCapacityScale"))
    {
        heatCapacityScale_ = dict_.get<scalar>("heatCapacityScale");
        if (!(heatCapacityScale_ > 0 && heatCapacityScale_ <= 1))
        {
            outOfRange
            (
                dict_, "heatCapacityScale", heatCapacityScale_, "(0, 1]",
                ": it divides the particles' thermal inertia (a steady-state"
                " acceleration), it never raises it"
            );
        }
        Info<< "Particle heat capacity scaled by heatCapacityScale "
            << heatCapacityScale_ << " (" << dict_.name()
            << "): thermal transients are that much faster; only steady"
            << " states are physical" << endl;
    }

    // The material is checked here, where the file is read
    reducedSurfaceDict();

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


const Foam::dictionary* Foam::contactMaterials::reducedSurfaceDict() const
{
    if (!dict_.found("reducedSurface"))
    {
        return nullptr;
    }
    const word name(dict_.get<word>("reducedSurface"));
    return &material(name, dict_, "reducedSurface");
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


Foam::scalar Foam::contactMaterials::particleHeatCapacity() const
{
    return
        heatCapacityScale_
       *keywordRange::positive
        (
            particleDict(), "specificHeat", "specific heat [J/(kg K)]"
        );
}


void Foam::contactMaterials::checkHeatCapacity
(
    const dictionary& dict,
    const word& key,
    const scalar value
) const
{
    if (heatCapacityScale_ == 1)
    {
        checkSame(dict, key, value, "specificHeat");
        return;
    }
    const scalar expected = particleHeatCapacity();
    if (mag(value - expected) > 1e-12*mag(expected))
    {
        FatalIOErrorInKeyword(dict, key)
            << "Keyword " << key << " " << value << " in " << dict.name()
            << " is not the particles' scaled heat capacity " << expected
            << " (specificHeat times heatCapacityScale of " << dict_.name()
            << ')' << nl
            << "Write cp $materials/" << particleName_ << "/specificHeat;"
            << " cpScale $materials/heatCapacityScale; at the top of the"
            << " file and " << key << " #eval{ $cp*$cpScale };"
            << exit(FatalIOError);
    }
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
        FatalIOErrorInKeyword(dict, key)
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
    const IOdictionary io
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
    // A copy made in the return slot, its sub-dictionaries' parent pointer
    // on it (a dictionary moved from the IOdictionary would leave them on
    // the destroyed one, which an error message walks)
    return dictionary(io);
}


Foam::scalar Foam::contactMaterials::modulus
(
    const dictionary& dict,
    const word& key
)
{
    const scalar value = dict.get<scalar>(key);
    if
    (
        !(value >= sinterMaterial::modulusMin()
       && value <= sinterMaterial::modulusMax())
    )
    {
        outOfRange
        (
            dict, key, value, "[1e3, 1e13] Pa",
            "\nA Young's modulus in Pa: hematite 359e9 (Table 2.4), the"
            " thesis's DEM value 1e6 (Table 5.1)"
        );
    }
    return value;
}
