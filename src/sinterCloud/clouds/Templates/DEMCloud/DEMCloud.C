// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "DEMCloud.H"
#include "coarseGrainFactor.H"
#include "cloudInput.H"
#include "LatticeBedInjection.H"
#include "profiling.H"

template<class CloudType>
Foam::DEMCloud<CloudType>::DEMCloud
(
    const word& cloudName,
    const volScalarField& rho,
    const volVectorField& U,
    const dimensionedVector& g,
    const SLGThermo& thermo,
    bool readFields
)
:
    CloudType(cloudName, rho, U, g, thermo, false),
    placedBed_(false),
    convection_(nullptr)
{
    if (this->solution().active())
    {
        if (this->heatTransfer().active())
        {
            convection_ =
                dynamic_cast<const convectionType*>(&this->heatTransfer());
            if (!convection_)
            {
                FatalIOErrorInFunction(this->subModelProperties())
                    << "heatTransferModel " << this->heatTransfer().type()
                    << " in " << this->subModelProperties().name()
                    << ": the DEM cloud takes none or "
                    << convectionType::typeName << exit(FatalIOError);
            }
        }
        if
        (
            this->solution().coupled()
         && this->solution().semiImplicit("h")
         && this->solution().relaxCoeff("h") != 1
        )
        {
            FatalIOErrorInFunction(this->particleProperties())
                << "h semiImplicit " << this->solution().relaxCoeff("h")
                << " in " << this->particleProperties().name()
                << ": the implicit heat exchange conserves enthalpy only"
                   " with the coefficient 1" << exit(FatalIOError);
        }
        if (this->radiation())
        {
            FatalIOErrorInFunction(this->particleProperties())
                << "radiation on in " << this->particleProperties().name()
                << ": the DEM cloud does not take particle radiation"
                << exit(FatalIOError);
        }

        // The stock patch interaction's and injectors' entries
        cloudInput::checkSubModels(this->mesh(), this->subModelProperties());

        gas_.reset(new DEMGasCoupling<DEMCloud<CloudType>>(*this));
        collision_.reset
        (
            new DEMCollision<DEMCloud<CloudType>>
            (
                this->subModelProperties(),
                *this
            )
        );

        // The engine exists: the particles' material is known
        chemistry_.reset
        (
            new parcelChemistry
            (
                this->mesh(),
                this->particleProperties(),
                this->constProps().dict(),
                this->constProps().reductionDegree0(),
                collision_->engine().materials()
            )
        );

        // The engine exists: the contact fields can be read
        if (readFields)
        {
            parcelType::readFields(*this);
            this->deleteLostParticles();
        }

        granular_.reset(new granularFields(this->mesh()));
        updateBedFields();
    }

    // A run started from a written time draws from that time's stream (a
    // fresh start, index 0, keeps OpenFOAM's own)
    const label startIndex = this->db().time().timeIndex();
    if (startIndex > 0)
    {
        restartRandomStream(startIndex);
    }
}


template<class CloudType>
Foam::tmp<Foam::volScalarField::Internal>
Foam::DEMCloud<CloudType>::oxygenSource() const
{
    const word name(this->name() + ":oxygenSource");
    return
        chemistry_.valid()
      ? chemistry_->oxygenSource(this->mesh(), name)
      : parcelChemistry::noOxygenSource(this->mesh(), name);
}


template<class CloudType>
void Foam::DEMCloud<CloudType>::evolve()
{
    if (this->solution().canEvolve())
    {
        // The parcels injected and lost in the step, counted from the
        // totals (the cloud's "Parcel fate: escape" also counts rebounds)
        const label n0 = returnReduce(this->size(), sumOp<label>());
        const label added0 = parcelsInjected();
        const label placed0 = parcelsPlaced();

        typename parcelType::trackingData td(*this);
        this->solve(*this, td);
        addProfiling(bedFields, "DEMCloud::bedFields");
        updateBedFields();
        endProfiling(bedFields);

        const label n1 = returnReduce(this->size(), sumOp<label>());
        const label added = parcelsInjected() - added0;
        placedBed_ = parcelsPlaced() > placed0;

        // This step is written: the next one draws from its time's stream
        if (this->db().time().writeTime())
        {
            restartRandomStream(this->db().time().timeIndex());
        }
        Info<< "    Parcels: " << n1 << " (" << added << " injected, "
            << n0 + added - n1 << " left the domain in this step)" << endl;
    }
}


template<class CloudType>
void Foam::DEMCloud<CloudType>::restartRandomStream(const label writtenIndex)
{
    // A 31-bit seed: the index modulo a prime below 2^21, times 1024,
    // plus the processor number modulo 1024
    const label seed =
        (writtenIndex % 2097143)*1024 + Pstream::myProcNo() % 1024;
    this->rndGen() = Random(seed);
}


template<class CloudType>
Foam::label Foam::DEMCloud<CloudType>::parcelsInjected() const
{
    label n = 0;
    forAll(this->injectors(), i)
    {
        n += this->injectors()[i].parcelsAddedTotal();
    }
    return returnReduce(n, sumOp<label>());
}


template<class CloudType>
Foam::label Foam::DEMCloud<CloudType>::parcelsPlaced() const
{
    typedef LatticeBedInjection<typename CloudType::kinematicCloudType>
        placement;
    label n = 0;
    forAll(this->injectors(), i)
    {
        if (isA<placement>(this->injectors()[i]))
        {
            n += this->injectors()[i].parcelsAddedTotal();
        }
    }
    return returnReduce(n, sumOp<label>());
}


template<class CloudType>
void Foam::DEMCloud<CloudType>::updateBedFields()
{
    const scalar K = coarseGrainFactor(this->constProps().dict());
    labelList cell(this->size());
    vectorField U(this->size());
    scalarField rhoCpd(this->size());
    label i = 0;
    const scalar Cp = this->constProps().Cp0();
    for (const parcelType& p : *this)
    {
        cell[i] = p.cell();
        U[i] = velocity(p);
        rhoCpd[i] = density(p)*Cp*p.d()/K;
        ++i;
    }
    granular_->update(cell, U, rhoCpd);
}


template<class CloudType>
template<class TrackCloudType>
void Foam::DEMCloud<CloudType>::motion
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td
)
{
    const scalar dt = this->db().time().deltaTValue();
    demEngine& engine = collision_->engine();

    // 1. The engine's particles follow the parcels
    addProfiling(sync, "DEMCloud::syncParticles");
    collision_->syncParticles();
    endProfiling(sync);

    // 1b. The hydrogen reduction, from the state at the start of the step
    if (chemistry_->reduction())
    {
        chemistry_->reduce
        (
            cloud,
            engine,
            chemistry_->hydrogenTransported()
          ? scalarField(1e-3*this->thermo().thermo().W()().primitiveField())
          : scalarField(),
            dt
        );
    }

    // 1c. The iron on the particles' surfaces
    if (chemistry_->surfaceIronActive())
    {
        chemistry_->updateSurfaceIron(cloud, engine);
    }

    // 2. Fluid forces and heat, once per parcel, at the start position
    addProfiling(gasStart, "DEMCloud::gasExchange");
    gas_->start(cloud, td, dt, engine);
    endProfiling(gasStart);

    // 3. The DEM sub-steps
    addProfiling(collide, "DEMCloud::collide");
    collision_->collide(dt);
    endProfiling(collide);

    // The engine sorted its particles: the parcels and their sources follow
    if (engine.moved())
    {
        const labelList& newIndex = engine.newIndex();
        for (parcelType& p : cloud)
        {
            p.demIndex() = newIndex[p.demIndex()];
        }
        gas_->reorder(newIndex);
    }

    // 4. The gas loses the drag impulse; each parcel's displacement to
    // its particle's end position, for the track
    addProfiling(finish, "DEMCloud::gasImpulse");
    const demParticles& P = engine.particles();
    for (parcelType& p : cloud)
    {
        gas_->finish(p, P);
        p.displacement() =
            P.position[p.demIndex()] - gas_->startPosition(p.demIndex());
    }

    // OpenFOAM's cloud function objects read the parcels' own fields
    if (this->functions().size())
    {
        parcelsFromEngine();
    }

    // A time to be written: the lists are built again from the written
    // state, as a restart from it builds them (bit-identical restart)
    if (this->db().time().writeTime())
    {
        engine.invalidateLists();
    }

    endProfiling(finish);

    // 5. One track per parcel along its displacement
    addProfiling(track, "DEMCloud::track");
    CloudType::move(cloud, td, dt);
    this->updateCellOccupancy();
}


template<class CloudType>
void Foam::DEMCloud<CloudType>::parcelLeaves
(
    parcelType& p,
    const bool transfer
)
{
    // Leaving in the step: the heat exchange explicit, and the particle's
    // state into the parcel (with a transfer, its contacts too)
    if (engineIndex(p) < 0 || !gas_.valid())
    {
        return;
    }
    gas_->leaves(p, collision_->engine().particles());
    parcelFromEngine(p);
    if (transfer)
    {
        p.statePtr().reset(new demParcelState());
        collision_->stateOf(p.demIndex(), p.statePtr()());
    }
    p.demIndex() = -1;
}


template<class CloudType>
Foam::tmp<Foam::fvScalarMatrix> Foam::DEMCloud<CloudType>::Sh
(
    volScalarField& hs
) const
{
    if (!gas_.valid())
    {
        return tmp<fvScalarMatrix>(new fvScalarMatrix(hs, dimEnergy/dimTime));
    }
    return gas_->Sh(hs);
}


template<class CloudType>
void Foam::DEMCloud<CloudType>::correctHeatExchange()
{
    if (gas_.valid())
    {
        gas_->correctHeatExchange(collision_->engine().particles());
    }
}


#include "DEMCloudIO.C"
