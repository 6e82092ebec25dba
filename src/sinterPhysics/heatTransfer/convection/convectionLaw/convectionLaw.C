// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "convectionLaw.H"
#include "selectedConstructor.H"
#include "error.H"
#include "mathematicalConstants.H"

namespace Foam
{
    defineTypeNameAndDebug(convectionLaw, 0);
    defineRunTimeSelectionTable(convectionLaw, dictionary);
}


Foam::autoPtr<Foam::convectionLaw> Foam::convectionLaw::New
(
    const dictionary& dict
)
{
    const word lawName(dict.get<word>("law"));

    const auto cstr = selectedConstructor
    (
        dict, "law", lawName, *dictionaryConstructorTablePtr_
    );

    return autoPtr<convectionLaw>(cstr(dict));
}


Foam::scalar Foam::convectionLaw::parcelConductance
(
    const scalar K,
    const scalar dParcel,
    const scalar eps,
    const scalar slip,
    const scalar rho,
    const scalar mu,
    const scalar kappa,
    const scalar Pr
) const
{
    const scalar dp = dParcel/K;
    const scalar Re = eps*rho*dp*slip/mu;
    return K*K*K*constant::mathematical::pi*kappa*dp*Nu(eps, Re, Pr);
}
