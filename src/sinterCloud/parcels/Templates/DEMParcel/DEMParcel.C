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
    scalar Ts, rhos, mus, Pr, kappas;
    this->calcSurfaceValues(cloud, td, this->T(), Ts, rhos, mus, Pr, kappas);
    const scalar Re = this->Re(rhos, this->U(), td.Uc(), this->d(), mus);

    dhsTrans = 0;
    hAdt = 0;
    return this->calcHeatTransfer
    (
        cloud, td, dt, Re, Pr, kappas, 0, 0, dhsTrans, hAdt
    );
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
