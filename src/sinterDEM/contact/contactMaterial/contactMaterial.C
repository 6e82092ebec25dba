// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "contactMaterial.H"
#include "keywordRange.H"
#include "effectiveProperties.H"
#include "contactMaterials.H"
#include "knownKeywords.H"
#include "keywordSource.H"


Foam::contactMaterial::contactMaterial(const dictionary& dict)
:
    youngsModulus_
    (
        dict.found("demYoungsModulus")
      ? contactMaterials::modulus(dict, "demYoungsModulus")
      : contactMaterials::modulus(dict, "youngsModulus")
    ),
    realYoungsModulus_(contactMaterials::modulus(dict, "youngsModulus")),
    poissonsRatio_
    (
        keywordRange::get
        (
            dict, "poissonsRatio", -1, 0.5, "Poisson's ratio", true, true
        )
    )
{}


Foam::contactMaterial::contactMaterial(scalar Y, scalar Y0, scalar nu)
:
    youngsModulus_(Y),
    realYoungsModulus_(Y0),
    poissonsRatio_(nu)
{}


Foam::scalar Foam::contactMaterial::effectiveModulus
(
    const contactMaterial& other
) const
{
    return effective::modulus
    (
        youngsModulus_, poissonsRatio_,
        other.youngsModulus_, other.poissonsRatio_
    );
}


Foam::scalar Foam::contactMaterial::effectiveRealModulus
(
    const contactMaterial& other
) const
{
    return effective::modulus
    (
        realYoungsModulus_, poissonsRatio_,
        other.realYoungsModulus_, other.poissonsRatio_
    );
}


Foam::scalar Foam::contactMaterial::effectiveShearModulus
(
    const contactMaterial& other
) const
{
    return effective::shearModulus
    (
        youngsModulus_, poissonsRatio_,
        other.youngsModulus_, other.poissonsRatio_
    );
}


Foam::contactProperties::contactProperties
(
    const dictionary& dict,
    const bool restitution
)
:
    restitution_(restitution ? dict.get<scalar>("restitution") : 1),
    friction_(dict.get<scalar>("friction")),
    rollingFriction_(dict.lookupOrDefault<scalar>("rollingFriction", 0))
{
    knownKeywords::check(dict, {"restitution", "friction", "rollingFriction"});
    keywordRange::check
    (
        dict, "restitution", restitution_, 0, 1,
        "the coefficient of restitution", true
    );
    keywordRange::check
    (
        dict, "friction", friction_, 0, GREAT, "the sliding friction coefficient"
    );
    keywordRange::check
    (
        dict, "rollingFriction", rollingFriction_, 0, GREAT,
        "the rolling friction coefficient"
    );
}


Foam::contactProperties::contactProperties(scalar e, scalar mu, scalar muR)
:
    restitution_(e),
    friction_(mu),
    rollingFriction_(muR)
{}
