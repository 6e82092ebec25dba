// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "GasPressureGradientForce.H"
#include "fvcGrad.H"

template<class CloudType>
Foam::GasPressureGradientForce<CloudType>::GasPressureGradientForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    // Coefficients optional: `gasPressureGradient;` or with a dictionary
    ParticleForce<CloudType>(owner, mesh, dict, typeName, false),
    pName_(dict.template lookupOrDefault<word>("p", "p"))
{}


template<class CloudType>
Foam::GasPressureGradientForce<CloudType>::GasPressureGradientForce
(
    const GasPressureGradientForce& f
)
:
    ParticleForce<CloudType>(f),
    pName_(f.pName_)
{}


template<class CloudType>
void Foam::GasPressureGradientForce<CloudType>::cacheFields(const bool store)
{
    if (store)
    {
        const volScalarField& p =
            this->mesh().template lookupObject<volScalarField>(pName_);

        gradp_.reset(new volVectorField("gasPressureGradient", fvc::grad(p)));
        gradpInterp_ = interpolation<vector>::New
        (
            this->owner().solution().interpolationSchemes(),
            gradp_()
        );
    }
    else
    {
        gradpInterp_.clear();
        gradp_.clear();
    }
}


template<class CloudType>
Foam::forceSuSp Foam::GasPressureGradientForce<CloudType>::calcNonCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    const vector gradp =
        gradpInterp_->interpolate(p.coordinates(), p.currentTetIndices());

    return forceSuSp(-p.volume()*gradp, 0);
}
