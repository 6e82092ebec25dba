// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "contactMaterial.H"
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
    poissonsRatio_(dict.get<scalar>("poissonsRatio"))
{
    if (!(poissonsRatio_ > -1 && poissonsRatio_ < 0.5))
    {
        FatalIOErrorInKeyword(dict, "poissonsRatio")
            << "Keyword poissonsRatio in " << dict.name()
            << " must lie in (-1, 0.5), not " << poissonsRatio_
            << exit(FatalIOError);
    }
}


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
    if (!(restitution_ > 0 && restitution_ <= 1))
    {
        FatalIOErrorInKeyword(dict, "restitution")
            << "Keyword restitution in " << dict.name()
            << " must lie in (0, 1], not " << restitution_
            << exit(FatalIOError);
    }
    if (!(friction_ >= 0))
    {
        FatalIOErrorInKeyword(dict, "friction")
            << "Keyword friction in " << dict.name()
            << " must not be negative, not " << friction_
            << exit(FatalIOError);
    }
    if (!(rollingFriction_ >= 0))
    {
        FatalIOErrorInKeyword(dict, "rollingFriction")
            << "Keyword rollingFriction in " << dict.name()
            << " must not be negative, not " << rollingFriction_
            << exit(FatalIOError);
    }
}


Foam::contactProperties::contactProperties(scalar e, scalar mu, scalar muR)
:
    restitution_(e),
    friction_(mu),
    rollingFriction_(muR)
{}
