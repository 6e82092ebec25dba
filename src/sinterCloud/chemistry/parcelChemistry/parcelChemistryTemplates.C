// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "parcelChemistry.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::parcelChemistry::reduce
(
    CloudType& cloud,
    demEngine& engine,
    const scalarField& gasMolarMass,
    const scalar dt
)
{
    demParticles& P = engine.particles();

    // The hydrogen mole fraction of each cell's gas: H2 and H2O in a
    // carrier of the gas's molar mass
    scalarField yH2;
    if (hydrogenTransported_)
    {
        const fvMesh& mesh = cloud.mesh();
        const scalarField& Y1 =
            mesh.template lookupObject<volScalarField>("Y_H2")
           .primitiveField();
        const scalarField& Y2 =
            mesh.template lookupObject<volScalarField>("Y_H2O")
           .primitiveField();
        const scalarField& W = gasMolarMass;
        const scalar M1 = ironOxidePath::MH2, M2 = ironOxidePath::MH2O;
        const scalarField n1(max(Y1, scalar(0))/M1);
        yH2 =
            n1
           /max
            (
                n1 + max(Y2, scalar(0))/M2 + max(1 - Y1 - Y2, scalar(0))/W,
                VSMALL
            );
    }
    oxygenRemoved_ = 0;

    // The particles' state is the engine's; the parcels give their cells
    const scalar Cp = cloud.constProps().Cp0();
    scalar oxygen = 0, heat = 0, sumX = 0;
    scalar minX = GREAT, maxX = -GREAT;
    for (const auto& p : cloud)
    {
        const label i = p.demIndex();
        const scalar m = cloud.mass(p);
        const parcelReduction::step s = reduction_->advance
        (
            P.reductionDegree[i], P.temperature[i], m,
            hydrogenTransported_ ? yH2[p.cell()] : hydrogenMoleFraction_,
            dt
        );
        oxygenRemoved_[p.cell()] += p.nParticle()*s.oxygen;
        P.reductionDegree[i] = s.X;
        P.temperature[i] -= s.heat/(s.mass*Cp);
        P.setSphere(i, P.radius[i], P.density[i]*(s.mass/m));

        oxygen += p.nParticle()*s.oxygen;
        heat += p.nParticle()*s.heat;
        sumX += s.X;
        minX = min(minX, s.X);
        maxX = max(maxX, s.X);
    }

    // A particle's ghosts on other processors carry its mass from the last
    // rebuild of the lists: a rebuild in the step sends the new masses. It
    // is asked for serially as well, so that a run takes the same steps on
    // any number of processors
    engine.invalidateLists();

    const label n = returnReduce(cloud.size(), sumOp<label>());
    Foam::reduce(oxygen, sumOp<scalar>());
    Foam::reduce(heat, sumOp<scalar>());
    Foam::reduce(sumX, sumOp<scalar>());
    Foam::reduce(minX, minOp<scalar>());
    Foam::reduce(maxX, maxOp<scalar>());
    if (n)
    {
        Info<< "    Reduction: X mean " << sumX/n << " (" << minX << " to "
            << maxX << "), oxygen removed " << oxygen << " mol, reaction"
            << " heat " << heat << " J" << endl;
    }
}


template<class CloudType>
void Foam::parcelChemistry::updateSurfaceIron
(
    CloudType& cloud,
    demEngine& engine
) const
{
    demParticles& P = engine.particles();
    bool changed = false;
    for (const auto& p : cloud)
    {
        const label i = p.demIndex();
        const scalar f =
            surfaceIron_->fraction(P.reductionDegree[i], P.temperature[i]);
        scalar& fp = P.surfaceIron[i];
        if (f != fp)
        {
            fp = f;
            changed = true;
        }
    }
    if (returnReduce(changed, orOp<bool>()))
    {
        engine.invalidateLists();
    }
}
