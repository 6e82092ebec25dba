// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
// DEMCloud: the parcels as the engine's copy of the particles' state for
// OpenFOAM (written fields, patches, leaving parcels), and the cloud's
// summary in the log from the engine.

#include "DEMCloud.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::DEMCloud<CloudType>::parcelFromEngine(parcelType& p) const
{
    const label n = engineIndex(p);
    if (n < 0)
    {
        return;
    }
    const demParticles& P = held();
    p.U() = P.velocity[n];
    p.T() = P.temperature[n];
    p.rho() = P.density[n];
    p.reductionDegree() = P.reductionDegree[n];
}


template<class CloudType>
void Foam::DEMCloud<CloudType>::parcelsFromEngine() const
{
    // The parcels are the state's copy for I/O: filling them changes no
    // physics
    for (parcelType& p : const_cast<DEMCloud<CloudType>&>(*this))
    {
        parcelFromEngine(p);
    }
}


template<class CloudType>
void Foam::DEMCloud<CloudType>::info()
{
    // KinematicCloud's and ThermoCloud's summary, the sums in the parcels'
    // order
    scalar mass = 0, particles = 0, kinetic = 0;
    vector momentum(Zero);
    scalar Tmin = GREAT, Tmax = -GREAT;
    for (const parcelType& p : *this)
    {
        const scalar m = this->mass(p);
        const vector& U = velocity(p);
        const scalar T = temperature(p);
        mass += p.nParticle()*m;
        momentum += p.nParticle()*m*U;
        particles += p.nParticle();
        kinetic += p.nParticle()*0.5*m*(U & U);
        Tmin = min(Tmin, T);
        Tmax = max(Tmax, T);
    }
    reduce(mass, sumOp<scalar>());
    reduce(momentum, sumOp<vector>());
    reduce(particles, sumOp<scalar>());
    reduce(kinetic, sumOp<scalar>());
    reduce(Tmin, minOp<scalar>());
    reduce(Tmax, maxOp<scalar>());
    const label n = returnReduce(this->size(), sumOp<label>());

    Info<< "Cloud: " << this->name() << nl
        << "    Current number of parcels       = " << n << nl
        << "    Current mass in system          = " << mass << nl
        << "    Linear momentum                 = " << momentum << nl
        << "   |Linear momentum|                = " << mag(momentum) << nl
        << "    Linear kinetic energy           = " << kinetic << nl
        << "    Average particle per parcel     = "
        << (n ? particles/n : 0) << nl;
    this->injectors().info(Info);
    this->surfaceFilm().info(Info);
    this->patchInteraction().info(Info);
    Info<< "    Temperature min/max             = "
        << (n ? Tmin : 0) << ", " << (n ? Tmax : 0) << endl;
}


template<class CloudType>
void Foam::DEMCloud<CloudType>::writeFields() const
{
    // On every processor, parcels or not (collated writes are collective)
    if (collision_.valid())
    {
        parcelsFromEngine();
        parcelType::writeFields(*this);
    }
}


template<class CloudType>
void Foam::DEMCloud<CloudType>::writeObjects(objectRegistry& obr) const
{
    parcelsFromEngine();
    CloudType::writeObjects(obr);
}
