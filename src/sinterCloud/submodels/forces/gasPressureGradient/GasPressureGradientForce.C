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
    pName_(dict.template lookupOrDefault<word>("p", "p")),
    coupling_(cloudCoupling::New(mesh))
{}


template<class CloudType>
Foam::GasPressureGradientForce<CloudType>::GasPressureGradientForce
(
    const GasPressureGradientForce& f
)
:
    ParticleForce<CloudType>(f),
    pName_(f.pName_),
    coupling_(f.coupling_)
{}


template<class CloudType>
void Foam::GasPressureGradientForce<CloudType>::cacheFields(const bool store)
{
    if (store)
    {
        const volScalarField& p =
            this->mesh().template lookupObject<volScalarField>(pName_);

        gradpCells_ =
            coupling_.smoother().smooth<vector>
            (
                fvc::grad(p)().primitiveField(),
                "gasPressureGradient"
            );
        gradpPoints_ = coupling_.volumeFraction().pointValues(gradpCells_);
    }
    else
    {
        gradpCells_.clear();
        gradpPoints_.clear();
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
        coupling_.volumeFraction().gather(p, gradpCells_, gradpPoints_);

    return forceSuSp(-p.volume()*gradp, 0);
}
