// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "solidBridgeCohesion.H"
#include "keywordRange.H"
#include "knownKeywords.H"
#include "keywordSource.H"
#include "contactLaw.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace cohesionModels
{
    defineTypeNameAndDebug(solidBridge, 0);
    addToRunTimeSelectionTable(cohesionModel, solidBridge, dictionary);
}
}


const Foam::Enum
<
    Foam::cohesionModels::solidBridge::wallTemperatureModel
>
Foam::cohesionModels::solidBridge::wallTemperatureModelNames
({
    { wallTemperatureModel::wall, "wall" },
    { wallTemperatureModel::particle, "particle" },
});


const Foam::Enum
<
    Foam::cohesionModels::solidBridge::neckIntegrationModel
>
Foam::cohesionModels::solidBridge::neckIntegrationModelNames
({
    { neckIntegrationModel::exact, "exact" },
    { neckIntegrationModel::stepCount, "stepCount" },
});


const Foam::Enum
<
    Foam::cohesionModels::solidBridge::coarseGrainingRule
>
Foam::cohesionModels::solidBridge::coarseGrainingRuleNames
({
    { coarseGrainingRule::contactTime, "contactTime" },
    { coarseGrainingRule::stress, "stress" },
    { coarseGrainingRule::bondNumber, "bondNumber" },
});


Foam::scalar Foam::cohesionModels::solidBridge::forceExponent
(
    const coarseGrainingRule rule
)
{
    switch (rule)
    {
        case coarseGrainingRule::stress: return 2;
        case coarseGrainingRule::bondNumber: return 3;
        default: return 12.0/7.0;
    }
}


namespace
{

//- c = (Y*_DEM/Y*_real)^(2/5) of two contact materials (eq 5.14, with the
//  effective moduli of eq 5.15)
Foam::scalar timeCorrection
(
    const Foam::contactMaterial& a,
    const Foam::contactMaterial& b
)
{
    return std::pow(a.effectiveModulus(b)/a.effectiveRealModulus(b), 0.4);
}

//- The material in the model's settings is an old layout: fatal
void checkKeywords(const Foam::dictionary& coeffs)
{
    if (coeffs.found("material"))
    {
        FatalIOErrorInKeyword(coeffs, "material")
            << "Keyword material in " << coeffs.name()
            << " is no longer read: the sintering data are those of the"
            << " particles' material in constant/materialProperties"
            << Foam::exit(Foam::FatalIOError);
    }
    Foam::knownKeywords::check
    (
        coeffs,
        {
            "C", "curvatureRadius", "activationTime", "wallTemperature",
            "neckIntegration", "coarseGraining", "wallBridges"
        }
    );
}

//- The choice named by an optional keyword (its default if absent);
//  fatal, listing the valid names, if unknown
template<class EnumType>
EnumType readChoice
(
    const Foam::dictionary& coeffs,
    const Foam::word& key,
    const Foam::Enum<EnumType>& names,
    const EnumType deflt
)
{
    const Foam::word name
    (
        coeffs.lookupOrDefault<Foam::word>(key, names[deflt])
    );
    if (!names.found(name))
    {
        FatalIOErrorInKeyword(coeffs, key)
            << "Unknown " << key << " " << name << " in " << coeffs.name()
            << Foam::nl << "Valid " << key << " values are " << names
            << Foam::exit(Foam::FatalIOError);
    }
    return names[name];
}

//- A yes/no keyword (its default if absent); fatal, listing the valid
//  words, if it is not one
bool readSwitch
(
    const Foam::dictionary& coeffs,
    const Foam::word& key,
    const bool deflt
)
{
    if (!coeffs.found(key))
    {
        return deflt;
    }
    const Foam::word name(coeffs.get<Foam::word>(key));
    const Foam::Switch sw(name, true);
    if (!sw.valid())
    {
        FatalIOErrorInKeyword(coeffs, key)
            << "Unknown " << key << " " << name << " in " << coeffs.name()
            << Foam::nl << "Valid " << key << " values are"
            << " (yes no true false on off)"
            << Foam::exit(Foam::FatalIOError);
    }
    return bool(sw);
}

} // End anonymous namespace


void Foam::cohesionModels::solidBridge::Factors::evaluate(const scalar T)
{
    if (!(T >= 200))
    {
        FatalErrorInFunction
            << "contact temperature " << T << " K is below 200 K: the"
               " temperature of a particle or, for a particle-wall contact"
               " with wallTemperature wall, of the wall face (the gas"
               " temperature's boundary value there); temperatures are in"
               " kelvin" << exit(FatalError);
    }
    rate_ = law_.neckGrowthRate(1, T);
    strength_ = scale_*law_.forceFromNeck(1, T);
    T_ = T;
}


void Foam::cohesionModels::solidBridge::Factors::evaluateIron(const scalar T)
{
    // T was checked by evaluate: the oxide's factors come first
    ironRate_ = ironLaw_->neckGrowthRate(1, T);
    ironStrength_ = scale_*ironLaw_->forceFromNeck(1, T);
    ironT_ = T;
}


Foam::cohesionModels::solidBridge::solidBridge
(
    const dictionary& dict,
    const contactLaw& law,
    const scalar coarseGrainFactor,
    contactSlots& slots
)
:
    coeffs_(dict.subDict("solidBridgeCoeffs")),
    material_((checkKeywords(coeffs_), law.materials().particleDict())),
    law_(material_, coeffs_),
    activationTime_(coeffs_.lookupOrDefault<scalar>("activationTime", 0)),
    K_(coarseGrainFactor),
    coarseGraining_
    (
        readChoice
        (
            coeffs_, "coarseGraining", coarseGrainingRuleNames,
            coarseGrainingRule::stress
        )
    ),
    forceScale_(std::pow(K_, forceExponent(coarseGraining_))),
    wallBridges_(readSwitch(coeffs_, "wallBridges", true)),
    cPair_(timeCorrection(law.particleMaterial(), law.particleMaterial())),
    cWall_(law.materials().nWalls()),
    wallTemperature_
    (
        readChoice
        (
            coeffs_, "wallTemperature", wallTemperatureModelNames,
            wallTemperatureModel::wall
        )
    ),
    neckIntegration_
    (
        readChoice
        (
            coeffs_, "neckIntegration", neckIntegrationModelNames,
            neckIntegrationModel::exact
        )
    ),
    bridgeSlot_(slots.addScalar("bridge", typeName, false)),
    bridgeSquareSlot_(slots.addScalar("bridgeSquare", typeName, false)),
    ironBridgeSlot_(-1),
    ironBridgeSquareSlot_(-1)
{
    const dictionary* ironDict = law.materials().reducedSurfaceDict();
    if (ironDict)
    {
        ironMaterial_.reset(new sinterMaterial(*ironDict));
        ironLaw_.reset(new Foam::solidBridge(ironMaterial_(), coeffs_));
        ironBridgeSlot_ = slots.addScalar("ironBridge", typeName, false);
        ironBridgeSquareSlot_ =
            slots.addScalar("ironBridgeSquare", typeName, false);
        Info<< "    solid bridges of reduced surfaces: the iron-iron"
            << " micro-contacts grow with the data of material "
            << ironMaterial_().name() << " (reducedSurface), the share"
            << " f_i f_j of the surface iron fractions" << endl;
    }

    forAll(cWall_, m)
    {
        cWall_[m] =
            timeCorrection(law.particleMaterial(), law.materials().wall(m));
    }

    keywordRange::check
    (
        coeffs_, "activationTime", activationTime_, 0, GREAT,
        "the time the bridges begin to grow [s]"
    );

    Info<< "    solid bridges: C " << law_.C() << ", activation at "
        << activationTime_ << " s, contact-time correction c = " << cPair_
        << " (pairs), " << cWall_ << " (walls: "
        << law.materials().wallNames() << "), coarse graining "
        << coarseGrainingRuleNames[coarseGraining_] << ": force scale K^"
        << forceExponent(coarseGraining_) << " = " << forceScale_
        << ", wall bridges " << (wallBridges_ ? "yes" : "no")
        << ", wall contacts at the "
        << wallTemperatureModelNames[wallTemperature_] << "'s temperature"
        << ", neck integration "
        << neckIntegrationModelNames[neckIntegration_] << endl;
}
