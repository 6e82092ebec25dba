// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "LatticeBedInjection.H"
#include "distributionModel.H"
#include "knownKeywords.H"
#include "mathematicalConstants.H"
#include "indexedOctree.H"
#include "treeDataFace.H"
#include "treeBoundBox.H"
#include "processorPolyPatch.H"
#include "Random.H"
#include "DynamicList.H"
#include "keywordSource.H"
#include "keywordRange.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::LatticeBedInjection<CloudType>::place()
{
    placed_ = true;

    const polyMesh& mesh = this->owner().mesh();
    const dictionary& dict = this->coeffDict();

    Random rnd(seed_);
    autoPtr<distributionModel> dist(distributionModel::New(sizeDict_, rnd));

    // The frame: w against gravity, u and v across it
    const vector g(this->owner().g().value());
    if (mag(g) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "The latticeBed injection of " << dict.name()
            << " stacks its layers against gravity, and g is zero"
            << exit(FatalIOError);
    }
    const vector ew(-g/mag(g));
    vector seed(1, 0, 0);
    if (mag(ew & seed) > 0.9)
    {
        seed = vector(0, 1, 0);
    }
    vector eu(seed - (seed & ew)*ew);
    eu /= mag(eu);
    const vector ev(ew ^ eu);

    // The region in the frame (the whole mesh's bounds by default)
    const boundBox region(hasBox_ ? box_ : boundBox(mesh.points(), true));
    const pointField corners(region.points());
    vector lo(VGREAT, VGREAT, VGREAT);
    vector hi(-VGREAT, -VGREAT, -VGREAT);
    for (const point& c : corners)
    {
        const vector f(c & eu, c & ev, c & ew);
        lo = min(lo, f);
        hi = max(hi, f);
    }

    // The boundary faces this processor holds, but not its processor faces
    DynamicList<label> faces;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (!isA<processorPolyPatch>(pp))
        {
            forAll(pp, i)
            {
                faces.append(pp.start() + i);
            }
        }
    }
    Random treeRnd(7);
    treeBoundBox treeBb(treeBoundBox(mesh.points()).extend(treeRnd, 1e-4));
    treeBb.min() -= point(ROOTVSMALL, ROOTVSMALL, ROOTVSMALL);
    treeBb.max() += point(ROOTVSMALL, ROOTVSMALL, ROOTVSMALL);
    const indexedOctree<treeDataFace> boundary
    (
        treeDataFace(false, mesh, labelList(std::move(faces))),
        treeBb,
        8,
        10,
        3.0
    );

    // FCC: the points (i, j, k) a/2 with i + j + k even, a = s sqrt(2)
    const scalar s = (1 + gap_)*dMax_;
    const scalar h = 0.5*s*Foam::sqrt(2.0);
    // A layer's sites are held at once: refuse a region so wide against the
    // parcels that one layer would not fit in memory
    const scalar siteRows = max((hi.x() - lo.x() - s)/h, scalar(0)) + 1;
    const scalar siteCols = max((hi.y() - lo.y() - s)/h, scalar(0)) + 1;
    const scalar maxLayerSites = 2e7;
    if (!(0.5*siteRows*siteCols <= maxLayerSites))
    {
        FatalIOErrorInFunction(dict)
            << "The lattice of " << dict.dictName() << " would hold "
            << 0.5*siteRows*siteCols << " sites per layer (more than "
            << maxLayerSites << "): the region " << region
            << " m is too wide for sites " << s << " m apart (the largest"
            << " parcel diameter, dMax, with the gap). Check the mesh's"
            << " size and the parcels' (K, d), or fill a smaller box"
            << " (keyword box)" << exit(FatalIOError);
    }
    const label ni = label(siteRows);
    const label nj = label(siteCols);
    const scalar rho = this->owner().constProps().rho0();
    const scalar mTarget = this->massTotal_;
    const label nProcs = Pstream::nProcs();

    DynamicList<point> pos;
    DynamicList<scalar> dia;
    DynamicList<label> cel, tetF, tetP;
    scalar mass = 0;
    label nTotal = 0;
    bool full = false;

    for (label k = 0; !full && lo.z() + 0.5*s + k*h <= hi.z(); ++k)
    {
        // This layer's sites, their draws (every processor the same)
        DynamicList<point> sites;
        DynamicList<scalar> ds;
        for (label j = 0; j < nj; ++j)
        {
            for (label i = (j + k) % 2; i < ni; i += 2)
            {
                const scalar d = dist->sample();
                const scalar room = jitter_*0.5*(s - d);
                vector r;
                do
                {
                    r = 2*rnd.sample01<vector>() - vector::one;
                }
                while (magSqr(r) > 1);
                const vector f
                (
                    lo.x() + 0.5*s + i*h,
                    lo.y() + 0.5*s + j*h,
                    lo.z() + 0.5*s + k*h
                );
                sites.append(f.x()*eu + f.y()*ev + f.z()*ew + room*r);
                ds.append(d);
            }
        }

        // Which processor holds each site, and which sites are too close
        // to a boundary face on any of them
        labelList holder(sites.size(), nProcs);
        labelList nearBoundary(sites.size(), 0);
        labelList cellOf(sites.size(), -1), tetFOf(sites.size(), -1);
        labelList tetPOf(sites.size(), -1);
        forAll(sites, n)
        {
            const point& p = sites[n];
            if (hasBox_ && !box_.contains(p))
            {
                nearBoundary[n] = 1;
                continue;
            }
            mesh.findCellFacePt(p, cellOf[n], tetFOf[n], tetPOf[n]);
            if (cellOf[n] >= 0)
            {
                holder[n] = Pstream::myProcNo();
            }
            const scalar clear = 0.5*ds[n]*(1 + gap_);
            if (boundary.findNearest(p, sqr(clear)).hit())
            {
                nearBoundary[n] = 1;
            }
        }
        Pstream::listCombineGather(holder, minEqOp<label>());
        Pstream::listCombineScatter(holder);
        Pstream::listCombineGather(nearBoundary, maxEqOp<label>());
        Pstream::listCombineScatter(nearBoundary);

        // Take them in order until the mass is reached
        forAll(sites, n)
        {
            if (holder[n] == nProcs || nearBoundary[n])
            {
                continue;
            }
            const scalar m =
                this->nParticleFixed_*rho*constant::mathematical::pi/6
               *pow3(ds[n]);
            if (mass + m > mTarget && mass + m - mTarget >= mTarget - mass)
            {
                full = true;
                break;
            }
            mass += m;
            ++nTotal;
            if (holder[n] == Pstream::myProcNo())
            {
                pos.append(sites[n]);
                dia.append(ds[n]);
                cel.append(cellOf[n]);
                tetF.append(tetFOf[n]);
                tetP.append(tetPOf[n]);
            }
            if (mass >= mTarget)
            {
                full = true;
                break;
            }
        }
    }

    if (!full)
    {
        FatalIOErrorInFunction(dict)
            << "The latticeBed injection of " << dict.name()
            << " finds room for " << mass << " kg (" << nTotal
            << " parcels, lattice spacing " << s << " m), not massTotal "
            << mTarget << " kg" << nl
            << "Give a larger box (or mesh), or a smaller gap"
            << exit(FatalIOError);
    }

    positions_.transfer(pos);
    diameters_.transfer(dia);
    cells_.transfer(cel);
    tetFaces_.transfer(tetF);
    tetPts_.transfer(tetP);

    localVolume_ = 0;
    for (const scalar d : diameters_)
    {
        localVolume_ += constant::mathematical::pi/6*pow3(d);
    }
    this->volumeTotal_ = returnReduce(localVolume_, sumOp<scalar>());

    scalar top = -GREAT;
    for (const point& p : positions_)
    {
        top = max(top, p & ew);
    }
    reduce(top, maxOp<scalar>());
    Info<< "    latticeBed " << this->modelName() << ": " << nTotal
        << " parcels, " << mass << " kg, lattice spacing " << s
        << " m, the highest centre at " << top << " m against g" << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

template<class CloudType>
Foam::LatticeBedInjection<CloudType>::LatticeBedInjection
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    InjectionModel<CloudType>(dict, owner, modelName, typeName),
    U0_(this->coeffDict().lookupOrDefault("U0", vector::zero)),
    gap_
    (
        keywordRange::getOrDefault(this->coeffDict(), "gap", 0.02, 0, 1, "")
    ),
    jitter_
    (
        keywordRange::getOrDefault
        (
            this->coeffDict(), "jitter", 0.9, 0, 1, "", false, true
        )
    ),
    seed_
    (
        label
        (
            keywordRange::getOrDefault
            (
                this->coeffDict(), "seed", 1, 0, labelMax, ""
            )
        )
    ),
    sizeDict_(this->coeffDict().subDict("sizeDistribution")),
    hasBox_(this->coeffDict().found("box")),
    box_(),
    dMax_(0),
    placed_(false),
    localVolume_(0)
{
    const dictionary& cd = this->coeffDict();
    knownKeywords::check
    (
        cd,
        {
            "type", "SOI", "massTotal", "parcelBasisType", "nParticle", "U0",
            "gap", "jitter", "seed", "box", "sizeDistribution",
            "minParticlesPerParcel", "injectorID", "latticeBedCoeffs"
        }
    );

    if (this->parcelBasis_ != InjectionModel<CloudType>::pbFixed)
    {
        FatalIOErrorInKeyword(cd, "parcelBasisType")
            << "Keyword parcelBasisType in " << cd.name()
            << " must be fixed for a latticeBed injection (its parcels each"
            << " hold nParticle particles; massTotal sets how many)"
            << exit(FatalIOError);
    }
    keywordRange::check
    (
        cd, "nParticle", this->nParticleFixed_, 0, GREAT,
        "the particles each parcel holds", true
    );
    if (owner.solution().active())
    {
        keywordRange::check
        (
            cd, "massTotal", this->massTotal_, 0, GREAT,
            "the bed's mass [kg]", true
        );
    }
    if (hasBox_)
    {
        cd.readEntry("box", box_);
        if (!(box_.span() > vector::zero))
        {
            FatalIOErrorInKeyword(cd, "box")
                << "Keyword box in " << cd.name()
                << " must be (min max) with min < max, not " << box_
                << exit(FatalIOError);
        }
    }

    // The distribution read once here, so that bad input stops at start
    Random rnd(seed_);
    autoPtr<distributionModel> dist(distributionModel::New(sizeDict_, rnd));
    dMax_ = dist->maxValue();
    if (!(dMax_ > 0 && dMax_ < 1) || !(dist->minValue() > 0))
    {
        FatalIOErrorInFunction(sizeDict_)
            << "The sizeDistribution of " << cd.name() << " must give"
            << " diameters in (0, 1) m, bounded: min " << dist->minValue()
            << ", max " << dMax_ << exit(FatalIOError);
    }
}


template<class CloudType>
Foam::LatticeBedInjection<CloudType>::LatticeBedInjection
(
    const LatticeBedInjection<CloudType>& im
)
:
    InjectionModel<CloudType>(im),
    U0_(im.U0_),
    gap_(im.gap_),
    jitter_(im.jitter_),
    seed_(im.seed_),
    sizeDict_(im.sizeDict_),
    hasBox_(im.hasBox_),
    box_(im.box_),
    dMax_(im.dMax_),
    placed_(im.placed_),
    positions_(im.positions_),
    diameters_(im.diameters_),
    cells_(im.cells_),
    tetFaces_(im.tetFaces_),
    tetPts_(im.tetPts_),
    localVolume_(im.localVolume_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::LatticeBedInjection<CloudType>::timeEnd() const
{
    return this->SOI_ + ROOTVSMALL;
}


template<class CloudType>
bool Foam::LatticeBedInjection<CloudType>::placesNow
(
    const scalar time0,
    const scalar time1
)
{
    if (time0 <= 0 && time1 > 0)
    {
        if (!placed_)
        {
            place();
        }
        return true;
    }
    return false;
}


template<class CloudType>
Foam::label Foam::LatticeBedInjection<CloudType>::parcelsToInject
(
    const scalar time0,
    const scalar time1
)
{
    return placesNow(time0, time1) ? positions_.size() : 0;
}


template<class CloudType>
Foam::scalar Foam::LatticeBedInjection<CloudType>::volumeToInject
(
    const scalar time0,
    const scalar time1
)
{
    return placesNow(time0, time1) ? localVolume_ : 0;
}


template<class CloudType>
void Foam::LatticeBedInjection<CloudType>::setPositionAndCell
(
    const label parcelI,
    const label,
    const scalar,
    vector& position,
    label& cellOwner,
    label& tetFacei,
    label& tetPti
)
{
    position = positions_[parcelI];
    cellOwner = cells_[parcelI];
    tetFacei = tetFaces_[parcelI];
    tetPti = tetPts_[parcelI];
}


template<class CloudType>
void Foam::LatticeBedInjection<CloudType>::setProperties
(
    const label parcelI,
    const label,
    const scalar,
    typename CloudType::parcelType& parcel
)
{
    parcel.U() = U0_;
    parcel.d() = diameters_[parcelI];
}
