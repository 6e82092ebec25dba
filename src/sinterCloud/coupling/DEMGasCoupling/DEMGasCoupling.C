// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "DEMGasCoupling.H"
#include "forceSuSp.H"
#include "VoidageDragForce.H"
#include "GasPressureGradientForce.H"
#include "WeightForce.H"

template<class CloudType>
Foam::DEMGasCoupling<CloudType>::DEMGasCoupling(CloudType& owner)
:
    owner_(owner),
    exchange_(owner.mesh()),
    drag_(nullptr)
{
    // The engine holds the particles' state: the DEM cloud's forces take
    // it (the drag, the only one that reads the velocity, from here);
    // OpenFOAM's would read the parcels' copy
    typedef VoidageDragForce<kinematicCloudType> dragType;
    const wordList valid
    {
        dragType::typeName,
        GasPressureGradientForce<kinematicCloudType>::typeName,
        WeightForce<kinematicCloudType>::typeName
    };
    forAll(owner.forces(), fi)
    {
        const word type(owner.forces()[fi].type());
        if (isA<dragType>(owner.forces()[fi]))
        {
            drag_ = &refCast<const dragType>(owner.forces()[fi]);
        }
        if (!valid.found(type))
        {
            FatalIOErrorInFunction(owner.particleProperties())
                << "particleForces " << type << " in "
                << owner.particleProperties().name() << ": the DEM engine"
                << " holds the particles' state and takes only the DEM"
                << " cloud's forces" << nl << nl
                << "Valid particleForces are" << nl << valid
                << exit(FatalIOError);
        }
    }
}


template<class CloudType>
bool Foam::DEMGasCoupling<CloudType>::heatImplicit() const
{
    return
        owner_.solution().coupled()
     && owner_.solution().semiImplicit("h")
     && owner_.heatTransfer().active();
}


template<class CloudType>
template<class TrackCloudType>
void Foam::DEMGasCoupling<CloudType>::start
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td,
    const scalar dt,
    demEngine& engine
)
{
    const bool coupled = owner_.solution().coupled();
    const bool correctSource = owner_.solution().cellValueSourceCorrection();
    const bool implicitHeat = heatImplicit();
    demParticles& P = engine.particles();

    // The gas conductivity, for the indirect conduction to walls
    tmp<volScalarField> tkappa;
    if (engine.conduction().needsGasConductivity())
    {
        tkappa = owner_.thermo().thermo().kappa();
    }

    exchange_.begin
    (
        engine.nLocal(), implicitHeat, owner_.thermo().thermo().T()
    );
    startPosition_.setSize(engine.nLocal());
    const scalar Cp = owner_.constProps().Cp0();
    for (parcelType& p : cloud)
    {
        // The gas at the parcel (the parcel: its place in the mesh) and
        // the particle's state (the engine's)
        const label n = p.demIndex();
        const label celli = p.cell();
        const point x = p.position();
        const vector& U = P.velocity[n];
        p.setCellValues(cloud, td);
        td.Uc() =
            cloud.dispersion().update
            (
                dt, celli, U, td.Uc(), p.UTurb(), p.tTurb()
            );
        if (correctSource)
        {
            p.cellValueSourceCorrection(cloud, td, dt);
        }

        const scalar np = p.nParticle();
        const scalar m = owner_.mass(p);
        const scalar Re =
            parcelType::Re(td.rhoc(), U, td.Uc(), p.d(), td.muc());
        forceSuSp Fcp =
            cloud.forces().calcCoupled(p, td, dt, m, Re, td.muc());
        if (drag_)
        {
            Fcp += drag_->drag(p, U, td, td.muc());
        }
        const forceSuSp Fncp =
            cloud.forces().calcNonCoupled(p, td, dt, m, Re, td.muc());

        // Heat with the gas: explicit, the particle's temperature now;
        // implicit, its share f = 1 - exp(-h A dt/(m c_p)) and its
        // temperature at the start, the particle following the gathered
        // gas temperature after the gas is solved (correctHeatExchange)
        scalar dhsTrans, hAdt;
        scalar& T = P.temperature[n];
        const scalar Tn = T;
        const scalar TgAt = exchange_.gasTemperatureAt(celli, x);
        const scalar mCp = m*Cp;
        const scalar Tconv =
            p.calcGasHeat(cloud, td, dt, Tn, U, mCp, dhsTrans, hAdt);
        const scalar fraction = exchange_.fraction(hAdt, mCp);
        if (!implicitHeat)
        {
            T = Tconv;
        }

        if (coupled)
        {
            owner_.UCoeff()[celli] += np*dt*Fcp.Sp();
            owner_.UTrans()[celli] -= np*dt*Fcp.Su();
            if (!implicitHeat)
            {
                owner_.hsTrans()[celli] += np*dhsTrans;
            }
        }
        exchange_.add
        (
            n, celli, fraction, Tn, TgAt, coupled, np*mCp,
            owner_.hsCoeff().field()
        );

        // The position after tracking
        P.position[n] = x;
        startPosition_[n] = x;
        P.externalForce[n] = Fcp.Su() + Fncp.Su();
        P.dragCoeff[n] = Fcp.Sp();
        P.fluidVelocity[n] = td.Uc();
        if (tkappa.valid())
        {
            P.gasConductivity[n] = tkappa()[celli];
        }
    }
}


template<class CloudType>
bool Foam::DEMGasCoupling<CloudType>::leaves
(
    const parcelType& p,
    demParticles& P
)
{
    const label k = p.demIndex();
    if (!exchange_.holds(k))
    {
        return false;
    }
    P.temperature[k] += exchange_.leave
    (
        k,
        p.nParticle()*owner_.mass(p)*owner_.constProps().Cp0(),
        owner_.hsTrans().field(),
        owner_.hsCoeff().field()
    );
    return true;
}


template<class CloudType>
Foam::tmp<Foam::fvScalarMatrix> Foam::DEMGasCoupling<CloudType>::Sh
(
    volScalarField& hs
) const
{
    if (!owner_.solution().coupled())
    {
        return tmp<fvScalarMatrix>(new fvScalarMatrix(hs, dimEnergy/dimTime));
    }

    // Spread over the smoothing length as the momentum source is (the
    // distribution D of eq 4.7)
    return exchange_.Sh
    (
        hs,
        owner_.thermo().thermo().Cp()().primitiveField(),
        owner_.hsTrans().field(),
        owner_.hsCoeff().field(),
        owner_.db().time().deltaTValue()
    );
}


template<class CloudType>
void Foam::DEMGasCoupling<CloudType>::correctHeatExchange(demParticles& P)
{
    if (!heatImplicit())
    {
        return;
    }

    // Each parcel towards the gas temperature it meets, gathered with the
    // transpose of the spreading
    exchange_.gather
    (
        owner_.thermo().thermo().he(),
        owner_.thermo().thermo().Cp()().primitiveField()
    );
    UList<scalar>& T = P.temperature;
    for (const parcelType& p : owner_)
    {
        if (exchange_.holds(p.demIndex()))
        {
            T[p.demIndex()] += exchange_.correction(p.demIndex());
        }
    }
}
