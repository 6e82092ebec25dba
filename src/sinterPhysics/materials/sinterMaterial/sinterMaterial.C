// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "sinterMaterial.H"
#include "knownKeywords.H"
#include "TableBase.H"
#include "IOmanip.H"
#include "keywordSource.H"
#include "keywordRange.H"


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
        keywordRange::get
        (
            dict, "density", densityMin(), densityMax(),
            "the particles' density [kg/m^3]", true, true
        )
    ),
    Y_
    (
        keywordRange::get
        (
            dict, "youngsModulus", modulusMin(), modulusMax(),
            "Young's modulus [Pa] (hematite 359e9, Table 2.4)", true, true
        )
    ),
    nu_
    (
        keywordRange::get
        (
            dict, "poissonsRatio", -1, 0.5, "Poisson's ratio", true, true
        )
    ),
    gamma_(keywordRange::positive(dict, "surfaceTension", "[N/m]")),
    delta_(keywordRange::positive(dict, "latticeConstant", "[m]")),
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
