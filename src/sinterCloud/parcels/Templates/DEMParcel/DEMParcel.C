// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "DEMParcel.H"

template<class ParcelType>
template<class TrackCloudType>
Foam::scalar Foam::DEMParcel<ParcelType>::calcGasHeat
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar dt,
    scalar& dhsTrans,
    scalar& hAdt
)
{
    dhsTrans = 0;
    hAdt = 0;
    if (!cloud.convection())
    {
        return this->T();
    }

    scalar Ts, rhos, mus, Pr, kappas;
    this->calcSurfaceValues(cloud, td, this->T(), Ts, rhos, mus, Pr, kappas);
    const scalar hA =
        cloud.convection()->conductance
        (
            this->cell(), this->d(), mag(td.Uc() - this->U()),
            rhos, mus, kappas, Pr
        );

    // m c_p dT/dt = h A (T_g - T), T_g held: analytically
    const scalar mCp = this->mass()*this->Cp();
    const scalar b = hA/mCp;
    const scalar deltaT =
        cloud.TIntegrator().delta(this->T(), dt, b*td.Tc(), b);
    const scalar Tnew =
        min
        (
            max(this->T() + deltaT, cloud.constProps().TMin()),
            cloud.constProps().TMax()
        );

    dhsTrans = -mCp*deltaT;
    hAdt = dt*hA;
    return Tnew;
}


template<class ParcelType>
template<class TrackCloudType>
bool Foam::DEMParcel<ParcelType>::move
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar trackTime
)
{
    typename TrackCloudType::parcelType& p =
        static_cast<typename TrackCloudType::parcelType&>(*this);
    typename TrackCloudType::parcelType::trackingData& ttd =
        static_cast<typename TrackCloudType::parcelType::trackingData&>(td);

    ttd.switchProcessor = false;
    ttd.keepParticle = true;

    while (ttd.keepParticle && !ttd.switchProcessor && p.stepFraction() < 1)
    {
        const point start = p.position();
        const scalar sfrac = p.stepFraction();
        const scalar f = 1 - sfrac;

        // The rest of the step's displacement
        p.trackToFace(f*displacement_, f);

        const scalar dt = (p.stepFraction() - sfrac)*trackTime;
        p.age() += dt;

        if (p.onFace())
        {
            cloud.functions().postFace(p, ttd.keepParticle);
        }
        cloud.functions().postMove(p, dt, start, ttd.keepParticle);

        if (p.onFace() && ttd.keepParticle)
        {
            // A patch that is not a DEM wall (e.g. a rebound outlet) may
            // change the velocity: the rest of the step then follows it
            const vector U0 = p.U();
            p.hitFace(displacement_, cloud, ttd);
            if (p.U() != U0)
            {
                displacement_ = trackTime*p.U();
            }
        }
    }

    if (!ttd.keepParticle || ttd.switchProcessor)
    {
        cloud.parcelLeaves(p, ttd.keepParticle);
    }

    return ttd.keepParticle;
}


template<class ParcelType>
void Foam::DEMParcel<ParcelType>::transformProperties(const tensor& T)
{
    ParcelType::transformProperties(T);
    displacement_ = transform(T, displacement_);
    if (state_.valid())
    {
        state_->transform(T);
    }
}


#include "DEMParcelIO.C"
