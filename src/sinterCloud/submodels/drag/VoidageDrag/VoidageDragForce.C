// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "VoidageDragForce.H"
#include "volFields.H"
#include "coarseGrainFactor.H"
#include "mathematicalConstants.H"
#include "FlatOutput.H"
#include "keywordSource.H"

template<class CloudType>
const Foam::volScalarField& Foam::VoidageDragForce<CloudType>::voidageField
(
    const fvMesh& mesh,
    const dictionary& dict
)
{
    const word name(dict.lookupOrDefault<word>("voidage", "voidage"));
    if (!mesh.foundObject<volScalarField>(name))
    {
        FatalIOErrorInKeyword(dict, "voidage")
            << "Keyword voidage in " << dict.name() << " names no field: "
            << name << nl << "The volScalarFields are "
            << flatOutput(mesh.sortedNames<volScalarField>())
            << exit(FatalIOError);
    }
    return mesh.lookupObject<volScalarField>(name);
}


template<class CloudType>
Foam::VoidageDragForce<CloudType>::VoidageDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    // A dictionary: `drag { law ...; }`
    ParticleForce<CloudType>(owner, mesh, dict, typeName, true),
    dict_(this->coeffs()),
    law_(dragLaw::New(dict_, wordList(1, word("voidage")))),
    voidage_(voidageField(mesh, dict_)),
    K_(coarseGrainFactor(owner.constProps().dict())),
    coupling_(cloudCoupling::New(mesh)),
    dSauter_()
{}


template<class CloudType>
Foam::VoidageDragForce<CloudType>::VoidageDragForce
(
    const VoidageDragForce<CloudType>& df
)
:
    ParticleForce<CloudType>(df),
    dict_(df.dict_),
    law_(dragLaw::New(dict_, wordList(1, word("voidage")))),
    voidage_(df.voidage_),
    K_(df.K_),
    coupling_(df.coupling_),
    dSauter_(df.dSauter_)
{}


template<class CloudType>
void Foam::VoidageDragForce<CloudType>::cacheFields(const bool store)
{
    if (!store || !law_->polydisperse())
    {
        dSauter_.clear();
        return;
    }

    // Solid volume and primary-particle surface of every parcel, spread and
    // smoothed as the voidage is: <d> = 6 V/A per cell
    const CloudType& cloud = this->owner();
    UPtrList<const particle> parcels(cloud.size());
    scalarField volume(cloud.size());
    scalarField surface(cloud.size());
    label i = 0;
    for (const typename CloudType::parcelType& p : cloud)
    {
        parcels.set(i, &p);
        volume[i] = p.nParticle()*p.volume();
        // nParticle K^3 primaries of diameter d/K
        surface[i] = p.nParticle()*K_*constant::mathematical::pi*sqr(p.d());
        ++i;
    }

    const volumeFractionModel& mapping = coupling_.volumeFraction();
    const diffusionSmoother& smoother = coupling_.smoother();
    // Both smoothed in one block solve
    scalarField V(mapping.theta(parcels, volume));
    scalarField A(mapping.theta(parcels, surface));
    UPtrList<scalarField> fields(2);
    fields.set(0, &V);
    fields.set(1, &A);
    UPtrList<vectorField> none;
    smoother.smooth
    (
        fields, wordList({"dragSolidVolume", "dragSolidSurface"}),
        none, wordList()
    );

    dSauter_.setSize(V.size());
    forAll(V, celli)
    {
        // A cell reached by no parcel keeps 0: a parcel there uses its own d
        dSauter_[celli] = A[celli] > VSMALL ? 6*V[celli]/A[celli] : 0;
    }
}


template<class CloudType>
Foam::forceSuSp Foam::VoidageDragForce<CloudType>::drag
(
    const typename CloudType::parcelType& p,
    const vector& U,
    const typename CloudType::parcelType::trackingData& td,
    const scalar muc
) const
{
    const scalar eps = voidage_[p.cell()];
    const scalar dp = p.d()/K_;
    const scalar slip = mag(td.Uc() - U);

    // <d> of the parcel's cell (0 where no parcel reached it: dp is used)
    const scalar dMean = dSauter_.size() ? dSauter_[p.cell()] : 0;
    const scalar F = law_->particleF(eps, dp, dMean, eps*td.rhoc()*slip/muc);

    // K^3 primaries of diameter dp: 3 pi mu dp eps F K^3
    return forceSuSp(Zero, 3*constant::mathematical::pi*muc*dp*eps*F*pow3(K_));
}
