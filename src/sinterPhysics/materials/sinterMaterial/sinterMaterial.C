// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "sinterMaterial.H"
#include "knownKeywords.H"
#include "TableBase.H"
#include "IOmanip.H"
#include "keywordSource.H"

namespace
{

// A required positive (or in-range) scalar, fatal naming the keyword
Foam::scalar readRange
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Foam::scalar lower,
    const Foam::scalar upper,
    const char* what
)
{
    const Foam::scalar value(dict.get<Foam::scalar>(key));

    if (!(value > lower && value < upper))
    {
        FatalIOErrorInKeyword(dict, key)
            << key << " " << value << " invalid: " << what
            << Foam::exit(Foam::FatalIOError);
    }

    return value;
}

} // End anonymous namespace


const Foam::wordList& Foam::sinterMaterial::keywords()
{
    static const wordList names
    {
        "density", "specificHeat", "youngsModulus", "demYoungsModulus",
        "poissonsRatio", "thermalConductivity", "surfaceTension",
        "latticeConstant", "surfaceDiffusion", "tensileStrength",
        "tensileStrengthCoeffs", "ironContent", "surfaceIronExponent"
    };
    return names;
}


Foam::sinterMaterial::sinterMaterial(const dictionary& dict)
:
    name_(dict.dictName()),
    rho_
    (
        readRange
        (
            dict, "density", densityMin(), densityMax(),
            "must lie in (10, 3e4) kg/m^3"
        )
    ),
    Y_
    (
        readRange
        (
            dict, "youngsModulus", modulusMin(), modulusMax(),
            "must lie in (1e3, 1e13) Pa (hematite 359e9, Table 2.4)"
        )
    ),
    nu_(readRange(dict, "poissonsRatio", -SMALL, 0.5, "must lie in [0, 0.5)")),
    gamma_(readRange(dict, "surfaceTension", 0, GREAT, "must be > 0 [N/m]")),
    delta_(readRange(dict, "latticeConstant", 0, GREAT, "must be > 0 [m]")),
    Ds_(dict),
    sigma_(Function1<scalar>::New("tensileStrength", dict)),
    sigmaTlow_(-GREAT),
    sigmaThigh_(GREAT),
    dict_(dict)
{
    knownKeywords::check(dict, keywords());

    // A table holds sigma only over the temperatures it lists
    typedef Function1Types::TableBase<scalar> tableType;
    if (isA<tableType>(sigma_()))
    {
        const scalarField T(refCast<const tableType>(sigma_()).x());
        sigmaTlow_ = min(T);
        sigmaThigh_ = max(T);
    }
}


Foam::scalar Foam::sinterMaterial::sigma(const scalar T) const
{
    if (T < sigmaTlow_ || T > sigmaThigh_)
    {
        FatalIOErrorInFunction(dict_)
            << setprecision(6)
            << "The tensileStrength table covers "
            << sigmaTlow_ << " to " << sigmaThigh_ << " K, not the temperature "
            << T << " K; extend tensileStrength in " << dict_.name()
            << " (temperatures in kelvin)" << exit(FatalIOError);
    }
    const scalar s = sigma_->value(T);

    if (!(s > 0))
    {
        FatalErrorInFunction
            << "Material " << name_ << ": tensileStrength(" << T << " K) = "
            << s << " Pa is not positive; check the tensileStrength entry"
            << exit(FatalError);
    }

    return s;
}


void Foam::sinterMaterial::checkTemperature(const scalar T) const
{
    sigma(T);
    Ds(T);
}
