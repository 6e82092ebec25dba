// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "BeetstraDragForce.H"
#include "volFields.H"
#include "coarseGrainFactor.H"

template<class CloudType>
Foam::BeetstraDragForce<CloudType>::BeetstraDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    // Coefficients optional: `BeetstraDrag;` or `BeetstraDrag { ... }`
    ParticleForce<CloudType>(owner, mesh, dict, typeName, false),
    voidage_
    (
        mesh.lookupObject<volScalarField>
        (
            dict.template lookupOrDefault<word>("voidage", "voidage")
        )
    ),
    K_(coarseGrainFactor(owner.constProps().dict()))
{}


template<class CloudType>
Foam::BeetstraDragForce<CloudType>::BeetstraDragForce
(
    const BeetstraDragForce<CloudType>& df
)
:
    ParticleForce<CloudType>(df),
    voidage_(df.voidage_),
    K_(df.K_)
{}


template<class CloudType>
Foam::scalar Foam::BeetstraDragForce<CloudType>::F
(
    const scalar eps,
    const scalar Re
)
{
    const scalar phi = 1 - eps;
    const scalar a = 0.5*(1 + 4*phi);

    // Inertial term written with Re^a multiplied through, finite at Re = 0:
    // 0.413 Re/(24 eps^2) N/(1 + 10^(3 phi) Re^-a)
    //   = 0.413/(24 eps^2) (Re N) Re^a/(Re^a + 10^(3 phi))
    const scalar ReN = Re/eps + 3*eps*phi*Re + 8.4*pow(Re, 0.657);
    const scalar Rea = pow(Re, a);

    return
        10*phi/sqr(eps)
      + sqr(eps)*(1 + 1.5*sqrt(phi))
      + 0.413/(24*sqr(eps))*ReN*Rea/(Rea + pow(10.0, 3*phi));
}


template<class CloudType>
Foam::forceSuSp Foam::BeetstraDragForce<CloudType>::calcCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    const scalar eps = voidage_[p.cell()];
    const scalar dp = p.d()/K_;
    const scalar ReP = eps*td.rhoc()*dp*mag(td.Uc() - p.U())/muc;

    // K^3 primaries of diameter dp: 3 pi mu dp eps F K^3
    return forceSuSp
    (
        Zero,
        3*constant::mathematical::pi*muc*dp*eps*F(eps, ReP)*pow3(K_)
    );
}
