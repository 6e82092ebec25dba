// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "contactConduction.H"
#include "keywordRange.H"
#include "conductionGeometry.H"

namespace
{

//- The engine's conduction dictionary (none without one), with the lens
//  law's minimum distance scaled by K (coarse graining: every length of a
//  parcel contact scales). Returned as a copy made in the return slot:
//  OpenFOAM's dictionary move leaves the sub-dictionaries' parent pointers
//  on the moved-from object, and an error message on a sub-dictionary
//  (which walks to the top dictionary) then read freed memory.
Foam::dictionary conductionDict
(
    const Foam::dictionary& engineDict,
    const Foam::scalar K
)
{
    using namespace Foam;
    if (!engineDict.found("conduction"))
    {
        dictionary none;
        none.add("direct", "none");
        none.add("indirect", "none");
        return none;
    }
    dictionary d(engineDict.subDict("conduction"));
    const word coeffs(d.lookupOrDefault<word>("indirect", "none") + "Coeffs");
    if (K != 1 && d.isDict(coeffs) && d.subDict(coeffs).found("minimumDistance"))
    {
        dictionary& c = d.subDict(coeffs);
        c.set("minimumDistance", K*c.get<scalar>("minimumDistance"));
    }
    return dictionary(d);
}


//- The particles' solid conductivity for the indirect law (0 when the
//  engine has no indirect conduction: its material need not give one)
Foam::scalar particleConductivity
(
    const Foam::dictionary& engineDict,
    const Foam::contactMaterials& materials
)
{
    using namespace Foam;
    if
    (
        !engineDict.isDict("conduction")
     || engineDict.subDict("conduction").lookupOrDefault<word>
        (
            "indirect", "none"
        ) == "none"
    )
    {
        return 0;
    }
    return
        keywordRange::positive
        (
            materials.particleDict(), "thermalConductivity", "[W/(m K)]"
        );
}

} // End anonymous namespace


Foam::contactConduction::contactConduction
(
    const dictionary& engineDict,
    const contactMaterials& materials,
    const scalar overlapExponent,
    const scalar coarseGrainFactor
)
:
    direct_(directConduction::New(conductionDict(engineDict, coarseGrainFactor))),
    indirect_
    (
        indirectConduction::New
        (
            conductionDict(engineDict, coarseGrainFactor),
            particleConductivity(engineDict, materials)
        )
    ),
    cp_(0),
    gPP_(0),
    gPW_(materials.nWalls(), scalar(0)),
    cPP_(1),
    cPW_(materials.nWalls(), scalar(1)),
    wallFactor_(coarseGrainFactor)
{
    if (!active())
    {
        return;
    }

    const dictionary& pDict = materials.particleDict();
    cp_ = materials.particleHeatCapacity();
    const scalar kP =
        keywordRange::positive(pDict, "thermalConductivity", "[W/(m K)]");

    // g = G/R_c of the direct law for each pair of materials
    gPP_ = direct_->conductance(kP, kP, 1);
    const contactMaterial& p = materials.particle();
    cPP_ =
        conductionGeometry::overlapFactor
        (
            p.effectiveModulus(p), p.effectiveRealModulus(p), overlapExponent
        );
    for (label m = 0; m < materials.nWalls(); ++m)
    {
        const dictionary& wDict =
            materials.dict().subDict(materials.wallNames()[m]);
        const scalar kW =
            keywordRange::positive(wDict, "thermalConductivity", "[W/(m K)]");
        gPW_[m] = direct_->conductance(kP, kW, 1);
        const contactMaterial& w = materials.wall(m);
        cPW_[m] =
            conductionGeometry::overlapFactor
            (
                p.effectiveModulus(w), p.effectiveRealModulus(w),
                overlapExponent
            );
    }
}


void Foam::contactConduction::pairs
(
    const demParticles& P,
    const contactList& C,
    scalar* Q
) const
{
    const bool direct = direct_->active();
    const bool indirect = indirect_->active();
    if (!direct && !indirect)
    {
        return;
    }

    const vector* __restrict__ x = P.position.cdata();
    const scalar* __restrict__ r = P.radius.cdata();
    const scalar* __restrict__ T = P.temperature.cdata();
    const scalar* __restrict__ kf = P.gasConductivity.cdata();
    const label* __restrict__ first = C.first.cdata();
    const label* __restrict__ second = C.second.cdata();

    const label n = C.size();
    for (label k = 0; k < n; ++k)
    {
        const label i = first[k];
        const label j = second[k];
        const scalar rSum = r[i] + r[j];
        const scalar d2 = magSqr(x[j] - x[i]);
        const bool touch = d2 < rSum*rSum;
        if (!touch && !indirect)
        {
            continue;
        }
        const scalar overlap = rSum - std::sqrt(d2);
        const scalar delta = cPP_*max(overlap, scalar(0));
        scalar G = 0;
        if (direct && touch)
        {
            G += gPP_*conductionGeometry::pairContactRadius(r[i], r[j], delta);
        }
        if (indirect)
        {
            // The gap; in contact, the thermal overlap (case 5)
            const scalar gap = touch ? -delta : -overlap;
            G +=
                indirect_->pairConductance
                (
                    0.5*(kf[i] + kf[j]), r[i], r[j], gap
                );
        }
        const scalar q = G*(T[j] - T[i]);
        Q[i] += q;
        Q[j] -= q;
    }
}


void Foam::contactConduction::walls
(
    const demParticles& P,
    const contactList& C,
    const demWalls& walls,
    scalar* Q,
    const scalar deltaT,
    scalar* faceHeat
) const
{
    const scalar* __restrict__ r = P.radius.cdata();
    const scalar* __restrict__ T = P.temperature.cdata();
    const scalar* __restrict__ kf = P.gasConductivity.cdata();
    const label* __restrict__ first = C.first.cdata();
    const label* __restrict__ face = C.second.cdata();
    const scalar* __restrict__ overlap = C.overlap.cdata();
    const scalarField& Tw = walls.temperature();
    const labelList& material = walls.materials();
    const boolList& conducting = walls.conducting();
    const bool all = conducting.empty();
    const bool direct = direct_->active();
    const bool indirect = indirect_->active();

    const label n = C.size();
    for (label k = 0; k < n; ++k)
    {
        if (!all && !conducting[face[k]])
        {
            continue;
        }
        const label i = first[k];
        const label m = material[face[k]];
        const scalar delta = cPW_[m]*max(overlap[k], scalar(0));
        scalar G = 0;
        if (direct && delta > 0)
        {
            G += gPW_[m]*conductionGeometry::wallContactRadius(r[i], delta);
        }
        if (indirect)
        {
            // The gap; in contact, the thermal overlap (case 5)
            const scalar gap = overlap[k] > 0 ? -delta : -overlap[k];
            G += indirect_->wallConductance(kf[i], r[i], gap);
        }
        const scalar q = wallFactor_*G*(Tw[face[k]] - T[i]);
        Q[i] += q;
        faceHeat[face[k]] += deltaT*q;
    }
}


void Foam::contactConduction::heat
(
    demParticles& P,
    const label n,
    const scalar* Q,
    const scalar deltaT
) const
{
    scalar* __restrict__ T = P.temperature.data();
    const scalar* __restrict__ invM = P.invMass.cdata();
    const scalar f = deltaT/cp_;
    for (label i = 0; i < n; ++i)
    {
        T[i] += f*invM[i]*Q[i];
    }
}
