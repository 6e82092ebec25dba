// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "VoidageDragForce.H"
#include "volFields.H"
#include "coarseGrainFactor.H"
#include "mathematicalConstants.H"

template<class CloudType>
Foam::VoidageDragForce<CloudType>::VoidageDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    // A dictionary: `drag { law ...; }`
    ParticleForce<CloudType>(owner, mesh, dict, typeName, true),
    dict_(this->coeffs()),
    law_(dragLaw::New(dict_)),
    voidage_
    (
        mesh.lookupObject<volScalarField>
        (
            dict_.template lookupOrDefault<word>("voidage", "voidage")
        )
    ),
    K_(coarseGrainFactor(owner.constProps().dict()))
{}


template<class CloudType>
Foam::VoidageDragForce<CloudType>::VoidageDragForce
(
    const VoidageDragForce<CloudType>& df
)
:
    ParticleForce<CloudType>(df),
    dict_(df.dict_),
    law_(dragLaw::New(dict_)),
    voidage_(df.voidage_),
    K_(df.K_)
{}


template<class CloudType>
Foam::forceSuSp Foam::VoidageDragForce<CloudType>::calcCoupled
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
        3*constant::mathematical::pi*muc*dp*eps*law_->F(eps, ReP)*pow3(K_)
    );
}
