// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "DEMCloud.H"
#include "fvmSup.H"
#include "gradScheme.H"
#include "diffusionSmoother.H"
#include "granularTemperature.H"
#include "coarseGrainFactor.H"
#include "patchInteractionDataList.H"
#include "ZehnerSchlunder.H"
#include "LatticeBedInjection.H"
#include "keywordSource.H"

namespace Foam
{
class cloudCoupling;

namespace DEMCloudDetail
{
    //- The smoother of the mesh's coupling (cloudCoupling includes the
    //  cloud's headers: named here, defined where the cloud is used)
    template<class Coupling = cloudCoupling>
    const diffusionSmoother& smoother(const fvMesh& mesh)
    {
        return Coupling::New(mesh).smoother();
    }

    //- Whether parcels exchange heat with the gas where they are
    //  (parcelGasTemperature local)
    template<class Coupling = cloudCoupling>
    bool localGasTemperature(const fvMesh& mesh)
    {
        return Coupling::New(mesh).localGasTemperature();
    }

    //- The gradient of a cell field, limited so that the value it moves
    //  to a cell's faces stays within the cell's and its neighbours' values
    //  (cellLimited Gauss linear 1, whatever fvSchemes says)
    inline vectorField limitedGrad(const volScalarField& f)
    {
        IStringStream scheme("cellLimited Gauss linear 1");
        return
            fv::gradScheme<scalar>::New(f.mesh(), scheme)()
           .grad(f, "limitedGrad(" + f.name() + ')')().primitiveField();
    }
}
}

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
    massChecked_(false),
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

        // OpenFOAM's patch interaction: e in [0, 1], mu >= 0 (a rebound
        // with e = 1.5 gains energy without a word)
        const dictionary* localPtr =
            this->subModelProperties().subDictPtr("localInteractionCoeffs");
        if
        (
            localPtr
         && this->subModelProperties().template get<word>
            (
                "patchInteractionModel"
            ) == "localInteraction"
        )
        {
            const patchInteractionDataList patches(this->mesh(), *localPtr);
            for (const patchInteractionData& pd : patches)
            {
                if (!(pd.e() >= 0 && pd.e() <= 1))
                {
                    FatalIOErrorInFunction(*localPtr)
                        << "Patch interaction " << pd.patchName() << " in "
                        << localPtr->name() << ": e = " << pd.e()
                        << " must be in [0, 1]" << exit(FatalIOError);
                }
                if (!(pd.mu() >= 0))
                {
                    FatalIOErrorInFunction(*localPtr)
                        << "Patch interaction " << pd.patchName() << " in "
                        << localPtr->name() << ": mu = " << pd.mu()
                        << " must be >= 0" << exit(FatalIOError);
                }
            }
        }

        // An injector's fixed number of particles per parcel must be > 0:
        // with 0 it injects nothing, silently
        const dictionary* injectorsPtr =
            this->subModelProperties().subDictPtr("injectionModels");
        if (injectorsPtr)
        {
            for (const entry& e : *injectorsPtr)
            {
                if
                (
                    e.isDict()
                 && e.dict().lookupOrDefault<word>("parcelBasisType", "")
                 == "fixed"
                 && !(e.dict().get<scalar>("nParticle") > 0)
                )
                {
                    FatalIOErrorInKeyword(e.dict(), "nParticle")
                        << "Keyword nParticle of injector " << e.keyword()
                        << " in " << e.dict().name() << " must be > 0, not "
                        << e.dict().get<scalar>("nParticle")
                        << " (with 0 it injects nothing)" << exit(FatalIOError);
                }
            }
        }

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

        const fvMesh& mesh = this->mesh();
        granularTemperature_.reset
        (
            new volScalarField
            (
                IOobject
                (
                    "granularTemperature",
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::AUTO_WRITE
                ),
                mesh,
                dimensionedScalar(sqr(dimVelocity), Zero)
            )
        );
        kineticConductivity_.reset
        (
            new volScalarField
            (
                IOobject
                (
                    "solidKineticConductivity",
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::NO_WRITE
                ),
                mesh,
                dimensionedScalar(dimPower/dimLength/dimTemperature, Zero)
            )
        );
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
    if (chemistry_.valid())
    {
        return chemistry_->oxygenSource
        (
            this->mesh(), this->name() + ":oxygenSource"
        );
    }
    return tmp<volScalarField::Internal>
    (
        new volScalarField::Internal
        (
            IOobject
            (
                this->name() + ":oxygenSource",
                this->mesh().time().timeName(),
                this->mesh(),
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            this->mesh(),
            dimensionedScalar(dimMoles/dimVolume/dimTime, Zero)
        )
    );
}


template<class CloudType>
bool Foam::DEMCloud<CloudType>::heatImplicit() const
{
    return
        this->solution().coupled()
     && this->solution().semiImplicit("h")
     && this->heatTransfer().active();
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
        updateBedFields();

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
    const label nCells = this->mesh().nCells();
    const scalar K = coarseGrainFactor(this->constProps().dict());

    labelList cell(this->size());
    vectorField U(this->size());
    scalarField rhoCpd(nCells, scalar(0));
    labelList n(nCells, 0);
    label i = 0;
    for (const parcelType& p : *this)
    {
        cell[i] = p.cell();
        U[i] = p.U();
        rhoCpd[p.cell()] += p.rho()*p.Cp()*p.d()/K;
        ++n[p.cell()];
        ++i;
    }

    scalarField& Theta = granularTemperature_->primitiveFieldRef();
    Theta = granularTemperature::cells(nCells, cell, U);
    scalarField& kKinetic = kineticConductivity_->primitiveFieldRef();
    forAll(kKinetic, c)
    {
        kKinetic[c] =
            n[c]
          ? ZehnerSchlunder::solidKinetic(rhoCpd[c]/n[c], 1, 1, Theta[c])
          : scalar(0);
    }
    granularTemperature_->correctBoundaryConditions();
    kineticConductivity_->correctBoundaryConditions();
}


template<class CloudType>
template<class TrackCloudType>
void Foam::DEMCloud<CloudType>::syncParticles(TrackCloudType& cloud)
{
    demEngine& engine = collision_->engine();
    const demParticles& P = engine.particles();
    const label nLocal = engine.nLocal();

    // The same particles (in any order: the engine may sort them): each
    // parcel's index is a local particle of its identity, and identities
    // are unique
    bool same = this->size() == nLocal;
    if (same)
    {
        for (const parcelType& p : cloud)
        {
            const label k = p.demIndex();
            if (k < 0 || k >= nLocal || P.identity[k] != p.identity())
            {
                same = false;
                break;
            }
        }
    }
    if (same)
    {
        return;
    }

    // Where each parcel was in the engine, or -1 (new, arrived, read)
    labelList order(this->size());
    label n = 0;
    for (const parcelType& p : cloud)
    {
        const label k = p.demIndex();
        order[n++] =
            (k >= 0 && k < nLocal && P.identity[k] == p.identity()) ? k : -1;
    }

    engine.reorder(order);

    demParticles& Q = engine.particles();
    n = 0;
    for (parcelType& p : cloud)
    {
        if (order[n] < 0)
        {
            Q.position[n] = p.position();
            Q.velocity[n] = p.U();
            Q.setSphere(n, 0.5*p.d(), p.rho());
            Q.identity[n] = p.identity();
            if (const demParcelState* st = p.state())
            {
                Q.angularVelocity[n] = st->angularVelocity;
                Q.force[n] = st->contactForce;
                Q.torque[n] = st->contactTorque;
                engine.addRecords(n, st->contacts);
                p.statePtr().clear();
            }
        }
        p.demIndex() = n;
        ++n;
    }
}


template<class CloudType>
template<class TrackCloudType>
void Foam::DEMCloud<CloudType>::unsupportedForce
(
    TrackCloudType& cloud,
    const parcelType& p,
    typename parcelType::trackingData& td,
    const scalar dt
) const
{
    wordList culprits;
    const scalar m = p.mass();
    const scalar Re = p.Re(td);
    forAll(cloud.forces(), fi)
    {
        const auto& f = cloud.forces()[fi];
        if
        (
            f.massAdd(p, td, m) != 0
         || f.calcNonCoupled(p, td, dt, m, Re, td.muc()).Sp() != 0
        )
        {
            culprits.append(f.type());
        }
    }
    FatalIOErrorInFunction(this->particleProperties())
        << "particleForces " << culprits << " in "
        << this->particleProperties().name() << " add mass (virtual mass)"
        << " or an implicit non-coupled force, which the DEM engine does"
           " not take: remove them" << exit(FatalIOError);
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
    const bool coupled = this->solution().coupled();
    const bool correctSource = this->solution().cellValueSourceCorrection();
    const bool implicitHeat = heatImplicit();

    // 1. The engine's particles follow the parcels
    syncParticles(cloud);

    // 1b. The hydrogen reduction, from the state at the start of the step
    if (chemistry_->reduction())
    {
        chemistry_->reduce
        (
            cloud,
            collision_->engine(),
            chemistry_->hydrogenTransported()
          ? scalarField(1e-3*this->thermo().thermo().W()().primitiveField())
          : scalarField(),
            dt
        );
    }

    // 1c. The iron on the particles' surfaces
    if (chemistry_->surfaceIronActive())
    {
        chemistry_->updateSurfaceIron(cloud, collision_->engine());
    }

    demEngine& engine = collision_->engine();
    demParticles& P = engine.particles();
    const label nLocal = engine.nLocal();

    // The gas conductivity, for the indirect conduction to walls
    tmp<volScalarField> tkappa;
    if (engine.conduction().needsGasConductivity())
    {
        tkappa = this->thermo().thermo().kappa();
    }

    // 2. Fluid forces and heat, once per parcel, at the start position
    sourceCell_.setSize(nLocal);
    heatFraction_.setSize(nLocal);
    heatFrom_.setSize(nLocal);
    heatGasAt_.setSize(nLocal);
    const bool localGas =
        implicitHeat && DEMCloudDetail::localGasTemperature(this->mesh());
    vectorField gasGradT0;
    if (implicitHeat)
    {
        // The gas temperature at the start and the sum of m c_p f T_p of
        // each cell's parcels; with local, the gradient (limited: the value
        // moved to a parcel stays near the cell's neighbours') and the sum
        // of m c_p f T_g(x_p)
        gasT0_ = this->thermo().thermo().T().primitiveField();
        heatTarget_.setSize(this->mesh().nCells());
        heatTarget_ = 0;
        if (localGas)
        {
            gasGradT0 = DEMCloudDetail::limitedGrad(this->thermo().thermo().T());
            heatGas_.setSize(this->mesh().nCells());
            heatGas_ = 0;
        }
    }
    const vectorField& cellCentres = this->mesh().C().primitiveField();
    for (parcelType& p : cloud)
    {
        const label n = p.demIndex();
        p.setCellValues(cloud, td);
        p.calcDispersion(cloud, td, dt);
        if (correctSource)
        {
            p.cellValueSourceCorrection(cloud, td, dt);
        }

        const label celli = p.cell();
        const scalar np = p.nParticle();
        const scalar m = p.mass();
        const scalar Re = p.Re(td);
        const forceSuSp Fcp =
            cloud.forces().calcCoupled(p, td, dt, m, Re, td.muc());
        const forceSuSp Fncp =
            cloud.forces().calcNonCoupled(p, td, dt, m, Re, td.muc());
        // A force that adds mass does so for every parcel: the first
        // parcel tells
        if
        (
            Fncp.Sp() != 0
         || (!massChecked_ && cloud.forces().massEff(p, td, m) != m)
        )
        {
            unsupportedForce(cloud, p, td, dt);
        }
        massChecked_ = true;

        // Heat with the gas: explicit, the parcel's temperature now; implicit,
        // its share f = 1 - exp(-h A dt/(m c_p)) and its temperature at
        // the start, the parcel following the gathered gas temperature
        // after the gas is solved (correctHeatExchange)
        scalar dhsTrans, hAdt;
        const scalar Tn = p.T();
        const scalar TgAt =
            localGas
          ? gasT0_[p.cell()]
          + (gasGradT0[p.cell()] & (p.position() - cellCentres[p.cell()]))
          : implicitHeat ? gasT0_[p.cell()] : 0;
        const scalar Tconv = p.calcGasHeat(cloud, td, dt, dhsTrans, hAdt);
        const scalar mCp = m*p.Cp();
        const scalar fraction =
            implicitHeat && mCp > 0 ? -std::expm1(-hAdt/mCp) : 0;
        if (!implicitHeat)
        {
            p.T() = Tconv;
        }

        if (coupled)
        {
            this->UCoeff()[celli] += np*dt*Fcp.Sp();
            this->UTrans()[celli] -= np*dt*Fcp.Su();
            if (implicitHeat)
            {
                this->hsCoeff()[celli] += np*mCp*fraction;
                heatTarget_[celli] += np*mCp*fraction*Tn;
                if (localGas)
                {
                    heatGas_[celli] += np*mCp*fraction*TgAt;
                }
            }
            else
            {
                this->hsTrans()[celli] += np*dhsTrans;
            }
        }

        // The position after tracking; the velocity too (a patch that is
        // not a DEM wall, e.g. a rebound outlet, may have changed it)
        P.position[n] = p.position();
        P.velocity[n] = p.U();
        P.externalForce[n] = Fcp.Su() + Fncp.Su();
        P.dragCoeff[n] = Fcp.Sp();
        P.fluidVelocity[n] = td.Uc();
        P.temperature[n] = p.T();
        if (tkappa.valid())
        {
            P.gasConductivity[n] = tkappa()[celli];
        }
        sourceCell_[n] = celli;
        heatFraction_[n] = fraction;
        heatFrom_[n] = Tn;
        heatGasAt_[n] = TgAt;
    }

    // 3. The DEM sub-steps
    collision_->collide(dt);

    // The engine sorted its particles: the parcels and their sources follow
    if (engine.moved())
    {
        const labelList& newIndex = engine.newIndex();
        for (parcelType& p : cloud)
        {
            p.demIndex() = newIndex[p.demIndex()];
        }
        labelList cell(nLocal);
        scalarList fraction(nLocal);
        scalarList from(nLocal);
        scalarList gasAt(nLocal);
        forAll(newIndex, k)
        {
            cell[newIndex[k]] = sourceCell_[k];
            fraction[newIndex[k]] = heatFraction_[k];
            from[newIndex[k]] = heatFrom_[k];
            gasAt[newIndex[k]] = heatGasAt_[k];
        }
        sourceCell_.transfer(cell);
        heatFraction_.transfer(fraction);
        heatFrom_.transfer(from);
        heatGasAt_.transfer(gasAt);
    }

    // 4. Results onto the parcels (temperatures too, with conduction); the
    // gas loses the drag impulse
    const bool conducting = engine.conduction().active();
    for (parcelType& p : cloud)
    {
        const label n = p.demIndex();
        if (coupled)
        {
            this->UTrans()[sourceCell_[n]] -= p.nParticle()*P.dragImpulse[n];
        }
        p.displacement() = P.position[n] - p.position();
        p.U() = P.velocity[n];
        if (conducting)
        {
            p.T() = P.temperature[n];
        }
    }

    // A time to be written: the lists are built again from the written
    // state, as a restart from it builds them (bit-identical restart)
    if (this->db().time().writeTime())
    {
        engine.invalidateLists();
    }

    // 5. One track per parcel along its displacement
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
    const label k = p.demIndex();
    if (k < 0 || k >= heatFraction_.size())
    {
        return;
    }

    if (heatFraction_[k] != 0)
    {
        // Leaving in the step: the exchange at the start's gas temperature
        // where it was, explicit, taken out of the implicit one
        const label c = sourceCell_[k];
        const scalar K = p.nParticle()*p.mass()*p.Cp()*heatFraction_[k];
        const scalar dT = heatFraction_[k]*(heatGasAt_[k] - heatFrom_[k]);
        p.T() += dT;
        this->hsTrans()[c] -= p.nParticle()*p.mass()*p.Cp()*dT;
        this->hsCoeff()[c] -= K;
        heatTarget_[c] -= K*heatFrom_[k];
        if (DEMCloudDetail::localGasTemperature(this->mesh()))
        {
            heatGas_[c] -= K*heatGasAt_[k];
        }
        heatFraction_[k] = 0;
    }

    if (transfer)
    {
        p.statePtr().reset(new demParcelState());
        demStateOf(k, p.statePtr()());
    }
    p.demIndex() = -1;
}


template<class CloudType>
Foam::tmp<Foam::fvScalarMatrix> Foam::DEMCloud<CloudType>::Sh
(
    volScalarField& hs
) const
{
    tmp<fvScalarMatrix> tSh(new fvScalarMatrix(hs, dimEnergy/dimTime));
    if (!this->solution().coupled())
    {
        return tSh;
    }

    // Spread over the smoothing length as the momentum source is (the
    // distribution D of eq 4.7): per volume and time, then smoothed
    const diffusionSmoother& smoother = DEMCloudDetail::smoother(this->mesh());
    const scalarField& V = this->mesh().V();
    const scalar dt = this->db().time().deltaTValue();

    // Explicit exchange (and that of parcels that left in the step)
    fvScalarMatrix& Sh = tSh.ref();
    Sh.source() -=
        V*smoother.smooth<scalar>(this->hsTrans().field()/(V*dt), "cloudHeat");

    // Implicit (the class's description): each cell towards its parcels,
    //     smoothed:  S(sum m c_p f T_p/(V dt)) - B T_g,
    //     local:     S(sum m c_p f (T_p - T_g^0(x_p))/(V dt)) - B (T_g - T_g^0),
    //     B = S(sum m c_p f/(V dt)),  T_g = T_g^0 + (h - h^0)/c_p
    if (heatImplicit())
    {
        const volScalarField Cp(this->thermo().thermo().Cp());
        const scalarField A
        (
            smoother.smooth<scalar>(heatTarget_/(V*dt), "cloudHeatTarget")
        );
        const scalarField B
        (
            smoother.smooth<scalar>
            (
                this->hsCoeff().field()/(V*dt), "cloudHeatCoeff"
            )
        );
        const scalarField BTg
        (
            DEMCloudDetail::localGasTemperature(this->mesh())
          ? smoother.smooth<scalar>(heatGas_/(V*dt), "cloudHeatGas")
          : B*gasT0_
        );
        const scalarField BbyCp(B/Cp.primitiveField());
        Sh.diag() -= V*BbyCp;
        Sh.source() -=
            V*(A - BTg + BbyCp*hs.oldTime().primitiveField());
    }
    return tSh;
}


template<class CloudType>
void Foam::DEMCloud<CloudType>::correctHeatExchange()
{
    if (!heatImplicit())
    {
        return;
    }

    // Each parcel towards the gas temperature it meets (smoothed: the gas
    // temperature, local: the gas's change over the step, (h - h^0)/c_p as
    // the gas took it) gathered over the smoothing length with the
    // transpose of the spreading (the smoothing is its own transpose):
    // what the gas gave the parcels, exactly
    const bool localGas = DEMCloudDetail::localGasTemperature(this->mesh());
    const diffusionSmoother& smoother = DEMCloudDetail::smoother(this->mesh());
    const volScalarField& hs = this->thermo().thermo().he();
    const volScalarField Cp(this->thermo().thermo().Cp());
    const scalarField dTg
    (
        (hs.primitiveField() - hs.oldTime().primitiveField())
       /Cp.primitiveField()
    );
    const scalarField Tg
    (
        localGas
      ? smoother.smooth<scalar>(dTg, "cloudHeatGather")
      : smoother.smooth<scalar>(gasT0_ + dTg, "cloudHeatGather")
    );

    for (parcelType& p : *this)
    {
        const label k = p.demIndex();
        if (k >= 0 && k < heatFraction_.size() && heatFraction_[k] != 0)
        {
            // Conduction in the step moved p.T() on from heatFrom_
            const scalar target =
                localGas
              ? heatGasAt_[k] + Tg[sourceCell_[k]]
              : Tg[sourceCell_[k]];
            p.T() += heatFraction_[k]*(target - heatFrom_[k]);
        }
    }
}


template<class CloudType>
void Foam::DEMCloud<CloudType>::demStateOf
(
    const label i,
    demParcelState& state
) const
{
    const demEngine& engine = collision_->engine();
    state.angularVelocity = engine.particles().angularVelocity[i];
    state.contactForce = engine.particles().force[i];
    state.contactTorque = engine.particles().torque[i];
    engine.recordsOf(i, state.contacts);
}


template<class CloudType>
void Foam::DEMCloud<CloudType>::writeFields() const
{
    // On every processor, parcels or not (collated writes are collective)
    if (collision_.valid())
    {
        parcelType::writeFields(*this);
    }
}
