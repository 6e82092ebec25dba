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
    const scalar T,
    const vector& U,
    const scalar mCp,
    scalar& dhsTrans,
    scalar& hAdt
) const
{
    dhsTrans = 0;
    hAdt = 0;
    if (!cloud.convection())
    {
        return T;
    }

    scalar Ts, rhos, mus, Pr, kappas;
    this->calcSurfaceValues(cloud, td, T, Ts, rhos, mus, Pr, kappas);
    const scalar hA =
        cloud.convection()->conductance
        (
            this->cell(), this->d(), mag(td.Uc() - U),
            rhos, mus, kappas, Pr
        );

    // m c_p dT/dt = h A (T_g - T), T_g held: analytically
    const scalar b = hA/mCp;
    const scalar deltaT = cloud.TIntegrator().delta(T, dt, b*td.Tc(), b);
    const scalar Tnew =
        min
        (
            max(T + deltaT, cloud.constProps().TMin()),
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
        // The start of the move, for the cloud's function objects only
        const point start =
            cloud.functions().size() ? p.position() : point::zero;
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
            // A patch that is not a DEM wall (e.g. a rebound outlet) reads
            // the parcel's fields and may change its velocity: the rest of
            // the step, and the engine's particle, then follow it
            if (p.onBoundaryFace())
            {
                cloud.parcelFromEngine(p);
            }
            const vector U0 = p.U();
            p.hitFace(displacement_, cloud, ttd);
            if (p.U() != U0)
            {
                displacement_ = trackTime*p.U();
                cloud.parcelVelocityToEngine(p);
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
