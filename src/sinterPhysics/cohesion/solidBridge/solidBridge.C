// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "solidBridge.H"
#include "keywordRange.H"
#include "mathematicalConstants.H"
#include "keywordSource.H"

namespace
{
    // Boltzmann constant [J/K] (SI 2019, exact)
    constexpr Foam::scalar kB = 1.380649e-23;
}


const Foam::Enum<Foam::solidBridge::surfaceModel>
Foam::solidBridge::surfaceModelNames
({
    { surfaceModel::threeMicroContacts, "threeMicroContacts" },
    { surfaceModel::smooth, "smooth" },
    { surfaceModel::nineMicroContacts, "nineMicroContacts" },
});


Foam::scalar Foam::solidBridge::coefficient(const surfaceModel model)
{
    switch (model)
    {
        case surfaceModel::threeMicroContacts: return 0.417;
        case surfaceModel::smooth: return 1;
        case surfaceModel::nineMicroContacts: return 1.251;
    }
    return 0;
}


Foam::solidBridge::solidBridge
(
    const sinterMaterial& material,
    const surfaceModel model
)
:
    material_(material),
    C_(coefficient(model)),
    a_(0)
{}


Foam::solidBridge::solidBridge
(
    const sinterMaterial& material,
    const dictionary& dict
)
:
    material_(material),
    C_(0),
    a_(0)
{
    // C: a surface model's name or a value
    ITstream& is = dict.lookup("C");
    const token t(is);
    if (t.isWord())
    {
        if (!surfaceModelNames.found(t.wordToken()))
        {
            FatalIOErrorInKeyword(dict, "C")
                << "Unknown C " << t.wordToken() << nl
                << "Valid names are " << surfaceModelNames
                << " (or a value >= 0)" << exit(FatalIOError);
        }
        C_ = coefficient(surfaceModelNames[t.wordToken()]);
    }
    else if (t.isNumber())
    {
        C_ = t.number();
        keywordRange::check
        (
            dict, "C", C_, 0, GREAT,
            "the surface model's coefficient C of eq 2.4 [-] (or one of "
          + std::string("threeMicroContacts, smooth, nineMicroContacts)")
        );
    }
    else
    {
        FatalIOErrorInKeyword(dict, "C")
            << "C must be a surface model " << surfaceModelNames
            << " or a value >= 0, not " << t << exit(FatalIOError);
    }

    // Curvature radius: the particle radius or a roughness length
    if (dict.found("curvatureRadius"))
    {
        ITstream& as = dict.lookup("curvatureRadius");
        const token at(as);
        if (at.isWord() && at.wordToken() == "particleRadius")
        {
            a_ = 0;
        }
        else if (at.isNumber() && at.number() > 0)
        {
            a_ = at.number();
        }
        else
        {
            FatalIOErrorInKeyword(dict, "curvatureRadius")
                << "curvatureRadius must be particleRadius or a length > 0"
                   " [m], not " << at << exit(FatalIOError);
        }
    }
}


Foam::scalar Foam::solidBridge::neckGrowthRate
(
    const scalar a,
    const scalar T
) const
{
    return
        56*material_.gamma()*pow4(material_.delta())*material_.Ds(T)
       *pow3(a)/(kB*T);
}


Foam::scalar Foam::solidBridge::forceFromNeck
(
    const scalar x7,
    const scalar T
) const
{
    return C_*constant::mathematical::pi*material_.sigma(T)*pow(x7, 2.0/7.0);
}


Foam::scalar Foam::solidBridge::neckRadius
(
    const scalar a,
    const scalar T,
    const scalar t
) const
{
    return pow(neckGrowthRate(a, T)*t, 1.0/7.0);
}


Foam::scalar Foam::solidBridge::force
(
    const scalar rp,
    const scalar T,
    const scalar t
) const
{
    return material_.sigma(T)*forcePerStrength(rp, T, t);
}


Foam::scalar Foam::solidBridge::forcePerStrength
(
    const scalar rp,
    const scalar T,
    const scalar t
) const
{
    // C pi x^2 with the curvature radius a (r_p for smooth particles, eq 2.4)
    return C_*constant::mathematical::pi*sqr(neckRadius(curvatureRadius(rp), T, t));
}
