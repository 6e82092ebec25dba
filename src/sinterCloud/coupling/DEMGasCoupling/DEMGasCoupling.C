// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "DEMGasCoupling.H"
#include "forceSuSp.H"

template<class CloudType>
Foam::DEMGasCoupling<CloudType>::DEMGasCoupling(CloudType& owner)
:
    owner_(owner),
    exchange_(owner.mesh()),
    massChecked_(false)
{}


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
void Foam::DEMGasCoupling<CloudType>::unsupportedForce
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
    FatalIOErrorInFunction(owner_.particleProperties())
        << "particleForces " << culprits << " in "
        << owner_.particleProperties().name() << " add mass (virtual mass)"
        << " or an implicit non-coupled force, which the DEM engine does"
           " not take: remove them" << exit(FatalIOError);
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

        // Heat with the gas: explicit, the parcel's temperature now;
        // implicit, its share f = 1 - exp(-h A dt/(m c_p)) and its
        // temperature at the start, the parcel following the gathered gas
        // temperature after the gas is solved (correctHeatExchange)
        scalar dhsTrans, hAdt;
        const scalar Tn = p.T();
        const scalar TgAt = exchange_.gasTemperatureAt(celli, p.position());
        const scalar Tconv = p.calcGasHeat(cloud, td, dt, dhsTrans, hAdt);
        const scalar mCp = m*p.Cp();
        const scalar fraction = exchange_.fraction(hAdt, mCp);
        if (!implicitHeat)
        {
            p.T() = Tconv;
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
    }
}


template<class CloudType>
bool Foam::DEMGasCoupling<CloudType>::leaves(parcelType& p)
{
    const label k = p.demIndex();
    if (!exchange_.holds(k))
    {
        return false;
    }
    p.T() += exchange_.leave
    (
        k,
        p.nParticle()*p.mass()*p.Cp(),
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
void Foam::DEMGasCoupling<CloudType>::correctHeatExchange()
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
    for (parcelType& p : owner_)
    {
        p.T() += exchange_.correction(p.demIndex());
    }
}
