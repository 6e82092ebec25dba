// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "DEMParcel.H"

template<class ParcelType>
template<class TrackCloudType>
bool Foam::DEMParcel<ParcelType>::move
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar trackTime
)
{
    if (!cloud.demActive())
    {
        return ParcelType::move(cloud, td, trackTime);
    }

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

    return ttd.keepParticle;
}


template<class ParcelType>
void Foam::DEMParcel<ParcelType>::transformProperties(const tensor& T)
{
    ParcelType::transformProperties(T);
    displacement_ = transform(T, displacement_);
    for (demContactRecord& r : contacts_)
    {
        r.history.tangentialSpring = transform(T, r.history.tangentialSpring);
    }
}


#include "DEMParcelIO.C"
