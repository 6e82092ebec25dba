// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "solidBridge.H"
#include "mathematicalConstants.H"

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
    model_(model),
    C_(coefficient(model))
{}


Foam::solidBridge::solidBridge
(
    const sinterMaterial& material,
    const dictionary& dict
)
:
    solidBridge(material, surfaceModelNames.get("bridgeModel", dict))
{}


Foam::scalar Foam::solidBridge::neckRadius
(
    const scalar a,
    const scalar T,
    const scalar t
) const
{
    const scalar delta = material_.delta();

    return pow
    (
        56*material_.gamma()*pow4(delta)*material_.Ds(T)*pow3(a)*t/(kB*T),
        1.0/7.0
    );
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
    // C pi x^2 with the curvature radius a = r_p (eq 2.4)
    return C_*constant::mathematical::pi*sqr(neckRadius(rp, T, t));
}
