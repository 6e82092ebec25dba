// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "GasPressureGradientForce.H"
#include "fvcGrad.H"
#include "IOdictionary.H"


template<class CloudType>
void Foam::GasPressureGradientForce<CloudType>::readCoupling()
{
    const fvMesh& mesh = this->mesh();
    const word dictName("couplingProperties");

    if (!mesh.template foundObject<IOdictionary>(dictName))
    {
        FatalErrorInFunction
            << "The " << typeName << " force gathers grad(p) with the "
            << "voidage's operators, read from constant/" << dictName
            << ", which the solver has not read"
            << exit(FatalError);
    }

    const IOdictionary& dict =
        mesh.template lookupObject<IOdictionary>(dictName);

    volumeFraction_ = volumeFractionModel::New(mesh, dict);
    smoother_.reset(new diffusionSmoother(mesh, dict));
}

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
{
    readCoupling();
}


template<class CloudType>
Foam::GasPressureGradientForce<CloudType>::GasPressureGradientForce
(
    const GasPressureGradientForce& f
)
:
    ParticleForce<CloudType>(f),
    pName_(f.pName_)
{
    readCoupling();
}


template<class CloudType>
void Foam::GasPressureGradientForce<CloudType>::cacheFields(const bool store)
{
    if (store)
    {
        const volScalarField& p =
            this->mesh().template lookupObject<volScalarField>(pName_);

        gradpCells_ =
            smoother_->smooth<vector>
            (
                fvc::grad(p)().primitiveField(),
                "gasPressureGradient"
            );
        gradpPoints_ = volumeFraction_->pointValues(gradpCells_);
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
    const vector gradp = volumeFraction_->gather(p, gradpCells_, gradpPoints_);

    return forceSuSp(-p.volume()*gradp, 0);
}
