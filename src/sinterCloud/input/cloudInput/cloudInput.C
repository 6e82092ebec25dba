// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "cloudInput.H"
#include "IOdictionary.H"
#include "coarseGrainFactor.H"
#include "knownKeywords.H"
#include "keywordRange.H"
#include "keywordSource.H"
#include "patchInteractionDataList.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// A size [m] and, for coarse-grained parcels, the primary size [um]
std::string sizes(const scalar d, const scalar K)
{
    OStringStream os;
    os.precision(6);
    os << d << " m";
    if (K != 1)
    {
        os << " (primary " << d/K*1e6 << " um)";
    }
    return os.str();
}


void checkConstantProperties(const dictionary& constProps)
{
    // Stock keywords of other parcel layers, not read by this cloud
    const string moduli
    (
        "the DEM engine's moduli are set per material in"
        " constant/materialProperties"
    );
    const HashTable<string> unread
    {
        {"youngsModulus", moduli},
        {"poissonsRatio", moduli},
        {"constantVolume", "a reacting parcel's setting; these parcels do"
            " not react"},
        {"alphaMax", "a packing limit of OpenFOAM's MPPIC parcels; the"
            " voidage bound is voidageMin in constant/couplingProperties"}
    };
    for (const entry& e : constProps)
    {
        const auto iter = unread.cfind(e.keyword());
        if (iter.found())
        {
            FatalIOErrorInKeyword(constProps, e.keyword())
                << "Keyword " << e.keyword() << " in " << constProps.name()
                << " is not read by this cloud: " << *iter
                << exit(FatalIOError);
        }
    }
    knownKeywords::check
    (
        constProps,
        {
            "rho0", "T0", "Cp0", "epsilon0", "f0", "coarseGrainFactor",
            "parcelTypeId", "rhoMin", "minParcelMass", "TMin", "TMax",
            "reductionDegree0"
        }
    );
    keywordRange::getOrDefault
    (
        constProps, "reductionDegree0", 0, 0, 1,
        "the reduction degree of injected parcels (0: the oxide, 1: iron)"
    );
}


//- constant/<cloudName>Properties, read, not registered
IOobject propertiesIO(const fvMesh& mesh, const word& cloudName)
{
    return IOobject
    (
        cloudName + "Properties",
        mesh.time().constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions  * * * * * * * * * * * * * * * //

void Foam::cloudInput::checkSizeDistribution
(
    const dictionary& sizeDict,
    const scalar K
)
{
    const word type(sizeDict.get<word>("type"));
    const dictionary& coeffs = sizeDict.optionalSubDict(type + "Distribution");

    // An optional size, > 0 (0 without it)
    auto optionalSize = [&](const word& key)
    {
        scalar v = 0;
        if (coeffs.readIfPresent(key, v))
        {
            keywordRange::check
            (
                coeffs, key, v, 0, GREAT,
                "size " + sizes(v, K) + " (sizes in metres)", true
            );
        }
        return v;
    };
    const scalar dMin = optionalSize("minValue");
    const scalar dMax = optionalSize("maxValue");
    const bool range = coeffs.found("minValue") && coeffs.found("maxValue");
    if (range && !(dMin < dMax))
    {
        FatalIOErrorInKeyword(coeffs, "minValue")
            << "Size range of " << coeffs.name() << ": minValue "
            << sizes(dMin, K).c_str() << " is not below maxValue "
            << sizes(dMax, K).c_str()
            << exit(FatalIOError);
    }
    optionalSize("d");  // RosinRammler's size scale
    for (const word key : {"expectation", "value"})
    {
        const scalar d = optionalSize(key);
        if (range && coeffs.found(key) && (d < dMin || d > dMax))
        {
            FatalIOErrorInKeyword(coeffs, key)
                << "Size " << key << ' ' << sizes(d, K).c_str() << " in "
                << coeffs.name() << " lies outside [minValue, maxValue] = ["
                << sizes(dMin, K).c_str() << ", " << sizes(dMax, K).c_str()
                << ']'
                << exit(FatalIOError);
        }
    }
}


void Foam::cloudInput::check(const fvMesh& mesh, const word& cloudName)
{
    const IOdictionary props(propertiesIO(mesh, cloudName));

    const dictionary& constProps = props.subDict("constantProperties");
    checkConstantProperties(constProps);
    const scalar K = coarseGrainFactor(constProps);

    const dictionary* injectors =
        props.subDict("subModels").findDict("injectionModels");
    if (injectors)
    {
        for (const entry& e : *injectors)
        {
            if (e.isDict() && e.dict().isDict("sizeDistribution"))
            {
                checkSizeDistribution(e.dict().subDict("sizeDistribution"), K);
            }
        }
    }
}


void Foam::cloudInput::checkSubModels
(
    const fvMesh& mesh,
    const dictionary& subModels
)
{
    const dictionary* localPtr = subModels.findDict("localInteractionCoeffs");
    if
    (
        localPtr
     && subModels.get<word>("patchInteractionModel") == "localInteraction"
    )
    {
        const patchInteractionDataList patches(mesh, *localPtr);
        for (const patchInteractionData& pd : patches)
        {
            const std::string of(" of patch " + pd.patchName());
            keywordRange::checkElement
            (
                *localPtr, "patches", "e" + of, pd.e(), 0, 1,
                "the restitution coefficient e of the normal velocity [-]"
            );
            keywordRange::checkElement
            (
                *localPtr, "patches", "mu" + of, pd.mu(), 0, GREAT,
                "the share mu of the tangential velocity the patch takes [-]"
            );
        }
    }

    const dictionary* injectorsPtr = subModels.findDict("injectionModels");
    if (injectorsPtr)
    {
        for (const entry& e : *injectorsPtr)
        {
            if
            (
                e.isDict()
             && e.dict().lookupOrDefault<word>("parcelBasisType", "")
             == "fixed"
             && !(e.dict().get<scalar>("nParticle") > 0)
            )
            {
                FatalIOErrorInKeyword(e.dict(), "nParticle")
                    << "Keyword nParticle of injector " << e.keyword()
                    << " in " << e.dict().name() << " must be > 0, not "
                    << e.dict().get<scalar>("nParticle")
                    << " (with 0 it injects nothing)" << exit(FatalIOError);
            }
        }
    }
}



bool Foam::cloudInput::transportsHydrogen
(
    const fvMesh& mesh,
    const word& cloudName
)
{
    const IOdictionary props(propertiesIO(mesh, cloudName));
    const dictionary* reduction = props.findDict("reduction");
    return
        reduction
     && reduction->lookupOrDefault<word>("gas", "uniform") == "transported";
}
