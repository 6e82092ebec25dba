// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "DEMCloud.H"
#include "DEMCollision.H"
#include "HashTable.H"
#include "globalIndex.H"
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


namespace Foam
{
namespace DEMCloudDetail
{

//- A parcel's temperature [K] if it has one (thermo parcels), else 0
template<class ParcelType>
inline auto temperature(const ParcelType& p, int) -> decltype(p.T())
{
    return p.T();
}

template<class ParcelType>
inline scalar temperature(const ParcelType&, long)
{
    return 0;
}

} // End namespace DEMCloudDetail
} // End namespace Foam


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

    // 1. Fluid forces and heat over the step, at the start positions. The
    //    drag (coupled, Sp (U_c - v)) is handed to the DEM with the gas
    //    velocity, to act on the parcel's actual velocity in every sub-step;
    //    the other forces become the external force. calc() does the heat
    //    and the gas's implicit drag coefficient; its momentum transfer,
    //    which assumes free flight over the step, is replaced by the DEM's
    //    drag impulse (step 3).
    DynamicList<parcelType*> parcels(this->size());
    DynamicList<label> startCells(this->size());
    const globalIndex identities(this->size());
    const bool coupled = this->solution().coupled();

    for (parcelType& p : cloud)
    {
        const vector U0 = p.U();

        p.setCellValues(cloud, td);
        p.calcDispersion(cloud, td, dt);
        if (correctSource)
        {
            p.cellValueSourceCorrection(cloud, td, dt);
        }

        const scalar m0 = p.mass();
        const scalar Re = p.Re(td);
        const forceSuSp Fcp =
            cloud.forces().calcCoupled(p, td, dt, m0, Re, td.muc());
        const forceSuSp Fncp =
            cloud.forces().calcNonCoupled(p, td, dt, m0, Re, td.muc());

        const label celli = p.cell();
        const vector UTrans0 = this->UTrans()[celli];
        p.calc(cloud, td, dt);
        this->UTrans()[celli] = UTrans0;

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
            identities.toGlobal(parcels.size())
        );
        P.origin[i] = labelPair(p.origProc(), p.origId());
        P.mass[i] = m;
        P.inertia[i] = I;
        P.temperature[i] = DEMCloudDetail::temperature(p, 0);
        P.externalForce[i] = Fcp.Su() + Fncp.Su();
        P.dragCoeff[i] = Fcp.Sp();
        P.fluidVelocity[i] = td.Uc();

        p.U() = U0;
        parcels.append(&p);
        startCells.append(celli);
    }

    // Ghosts of the neighbouring processors (decomposed runs)
    engine.exchange();
    const label nLocal = parcels.size();

    HashTable<label, labelPair, labelPair::Hash<>> index(2*P.size());
    forAll(P.origin, i)
    {
        index.insert(P.origin[i], i);
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

    if (engine.cohesion().active())
    {
        dem.setWallTemperature();
    }
    engine.setTime(this->db().time().value() - dt);
    engine.initialise();
    for (label k = 0; k < nSub; ++k)
    {
        engine.step(dtDEM);
    }

    // 3. Results onto the parcels, histories of the active contacts; the
    //    gas loses the momentum the drag gave the parcels
    forAll(parcels, i)
    {
        parcelType& p = *parcels[i];
        if (coupled)
        {
            this->UTrans()[startCells[i]] -= p.nParticle()*P.dragImpulse[i];
        }
        p.displacement() = P.position[i] - p.position();
        p.U() = P.velocity[i];
        p.angularMomentum() = P.inertia[i]*P.angularVelocity[i];
        p.f() = P.force[i] - P.externalForce[i];
        p.torque() = P.torque[i];
    }

    // A pair with a ghost is stored on the local parcel only (the ghost's
    // owner keeps its own copy)
    labelList nContacts(nLocal, 0);
    for (const contactPair& c : engine.pairs())
    {
        if (c.history.active())
        {
            ++nContacts[c.i];
            if (c.j < nLocal)
            {
                ++nContacts[c.j];
            }
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
            demContactRecord& ri = parcels[c.i]->contacts()[nContacts[c.i]++];
            ri.proc = P.origin[c.j].first();
            ri.id = P.origin[c.j].second();
            ri.history = c.history;

            if (c.j < nLocal)
            {
                demContactRecord& rj =
                    parcels[c.j]->contacts()[nContacts[c.j]++];
                rj.proc = P.origin[c.i].first();
                rj.id = P.origin[c.i].second();
                rj.history = c.history;
                rj.history.tangentialSpring = -c.history.tangentialSpring;
            }
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
        << " particle-wall contacts";
    if (engine.cohesion().active())
    {
        Info<< ", " << returnReduce(engine.nBridgedContacts(), sumOp<label>())
            << " bridged";
    }
    Info<< endl;

    // 4. One track per parcel along its DEM displacement
    demActive_ = true;
    CloudType::move(cloud, td, dt);
    demActive_ = false;
}
