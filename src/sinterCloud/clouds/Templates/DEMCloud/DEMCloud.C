// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "DEMCloud.H"
#include "DEMCollision.H"
#include "HashTable.H"
#include "demContactRecord.H"

template<class CloudType>
template<class TrackCloudType>
void Foam::DEMCloud<CloudType>::motion
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td
)
{
    if (isA<demCollisionType>(this->collision()))
    {
        demMotion(cloud, td, refCast<demCollisionType>(this->collision()));
    }
    else
    {
        CloudType::motion(cloud, td);
    }
}


template<class CloudType>
template<class TrackCloudType>
void Foam::DEMCloud<CloudType>::demMotion
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td,
    demCollisionType& dem
)
{
    const scalar dt = this->db().time().deltaTValue();
    const bool correctSource = this->solution().cellValueSourceCorrection();

    demEngine& engine = dem.engine();
    demParticles& P = engine.particles();
    P.clear();

    // 1. Fluid forces and heat over the step, at the start positions; the
    //    parcels' velocity change becomes the external force of the DEM
    DynamicList<parcelType*> parcels(this->size());
    HashTable<label, labelPair, labelPair::Hash<>> index(2*this->size());

    for (parcelType& p : cloud)
    {
        const vector U0 = p.U();

        p.setCellValues(cloud, td);
        p.calcDispersion(cloud, td, dt);
        if (correctSource)
        {
            p.cellValueSourceCorrection(cloud, td, dt);
        }
        p.calc(cloud, td, dt);

        const scalar m = p.mass();
        const scalar r = 0.5*p.d();
        const scalar I = 0.4*m*r*r;

        const label i = P.append
        (
            p.position(),
            U0,
            p.angularMomentum()/I,
            r,
            p.rho(),
            parcels.size()
        );
        P.mass[i] = m;
        P.inertia[i] = I;
        P.externalForce[i] = m*(p.U() - U0)/dt;

        p.U() = U0;
        index.insert(labelPair(p.origProc(), p.origId()), i);
        parcels.append(&p);
    }

    // Histories stored on the parcels: each pair from its lower index
    DynamicList<contactPair> pairs;
    DynamicList<wallContactRecord> walls;
    forAll(parcels, i)
    {
        for (const demContactRecord& r : parcels[i]->contacts())
        {
            if (r.wall())
            {
                walls.append(wallContactRecord{i, r.faceCentre, r.history});
            }
            else
            {
                const auto iter = index.cfind(labelPair(r.proc, r.id));
                if (iter.found() && i < *iter)
                {
                    pairs.append(contactPair{i, *iter, r.history});
                }
            }
        }
    }
    engine.restoreHistory(pairs, walls);

    // 2. DEM sub-steps
    const label nSub = dem.nSubSteps(dt);
    const scalar dtDEM = dt/nSub;

    engine.initialise();
    for (label k = 0; k < nSub; ++k)
    {
        engine.step(dtDEM);
    }

    // 3. Results onto the parcels, histories of the active contacts
    forAll(parcels, i)
    {
        parcelType& p = *parcels[i];
        p.displacement() = P.position[i] - p.position();
        p.U() = P.velocity[i];
        p.angularMomentum() = P.inertia[i]*P.angularVelocity[i];
        p.f() = P.force[i] - P.externalForce[i];
        p.torque() = P.torque[i];
    }

    labelList nContacts(parcels.size(), 0);
    for (const contactPair& c : engine.pairs())
    {
        if (c.history.active())
        {
            ++nContacts[c.i];
            ++nContacts[c.j];
        }
    }
    for (const wallContact& c : engine.wallContacts())
    {
        if (c.history.active())
        {
            ++nContacts[c.i];
        }
    }
    forAll(parcels, i)
    {
        parcels[i]->contacts().setSize(nContacts[i]);
        nContacts[i] = 0;
    }
    for (const contactPair& c : engine.pairs())
    {
        if (c.history.active())
        {
            const parcelType& pi = *parcels[c.i];
            const parcelType& pj = *parcels[c.j];

            demContactRecord& ri = parcels[c.i]->contacts()[nContacts[c.i]++];
            ri.proc = pj.origProc();
            ri.id = pj.origId();
            ri.history = c.history;

            demContactRecord& rj = parcels[c.j]->contacts()[nContacts[c.j]++];
            rj.proc = pi.origProc();
            rj.id = pi.origId();
            rj.history = c.history;
            rj.history.tangentialSpring = -c.history.tangentialSpring;
        }
    }
    for (const wallContact& c : engine.wallContacts())
    {
        if (c.history.active())
        {
            demContactRecord& r = parcels[c.i]->contacts()[nContacts[c.i]++];
            r.proc = -1;
            r.id = -1;
            r.faceCentre = engine.walls().centre(c.face);
            r.history = c.history;
        }
    }

    Info<< "    DEM: " << nSub << " sub-steps of " << dtDEM << " s, "
        << returnReduce(engine.nPairContacts(), sumOp<label>())
        << " particle-particle and "
        << returnReduce(engine.nWallContacts(), sumOp<label>())
        << " particle-wall contacts" << endl;

    // 4. One track per parcel along its DEM displacement
    demActive_ = true;
    CloudType::move(cloud, td, dt);
    demActive_ = false;
}
