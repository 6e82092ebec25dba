// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "solidsFlux.H"
#include "addToRunTimeSelectionTable.H"
#include "findSinterCloud.H"
#include "keywordRange.H"
#include "gravityMeshObject.H"
#include "OFstream.H"
#include "mathematicalConstants.H"
#include "keywordSource.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(solidsFlux, 0);
    addToRunTimeSelectionTable(functionObject, solidsFlux, dictionary);
}
}


Foam::label Foam::functionObjects::solidsFlux::slabSums
(
    const UList<vector>& position,
    const UList<vector>& U,
    const UList<scalar>& volume,
    const vector& up,
    const scalar height,
    const scalar thickness,
    const vector& axis,
    const scalar lo,
    const scalar hi,
    scalarField& binSum,
    scalar& upSum,
    scalar& downSum
)
{
    const label nBins = binSum.size();
    label inSlab = 0;
    forAll(position, i)
    {
        const scalar h = position[i] & up;
        if (h < height - 0.5*thickness || h >= height + 0.5*thickness)
        {
            continue;
        }
        ++inSlab;
        const scalar q = volume[i]*(U[i] & up);
        const scalar s = ((position[i] & axis) - lo)/(hi - lo)*nBins;
        const label b = s < 0 ? 0 : (s >= nBins ? nBins - 1 : label(s));
        binSum[b] += q;
        if (q > 0)
        {
            upSum += q;
        }
        else
        {
            downSum += q;
        }
    }
    return inSlab;
}


Foam::functionObjects::solidsFlux::solidsFlux
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    height_(0),
    thickness_(0),
    axis_(1, 0, 0),
    nBins_(20),
    averageFrom_(0),
    up_(0, 0, 1),
    axisLo_(0),
    axisHi_(0),
    binVolume_(),
    nSamples_(0)
{
    read(dict);

    if (foundProperty("profileSum"))
    {
        const scalarField sum(getProperty<scalarField>("profileSum"));
        if (sum.size() == nBins_)
        {
            profileSum_ = sum;
            nSamples_ = getProperty<label>("samples");
            Info<< type() << ' ' << name << ": continues its time average of "
                << nSamples_ << " evaluations from the stored state" << endl;
        }
    }

    if (Pstream::master() && writeToFile())
    {
        writeHeader(file(), "Solids volume flux through a horizontal plane");
        writeHeaderValue(file(), "height [m]", height_);
        writeHeaderValue(file(), "thickness [m]", thickness_);
        writeCommented(file(), "Time");
        writeTabbed(file(), "flux_net [m/s]");
        writeTabbed(file(), "flux_up [m/s]");
        writeTabbed(file(), "flux_down [m/s]");
        writeTabbed(file(), "parcels");
        file() << endl;
    }
}


bool Foam::functionObjects::solidsFlux::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    cloudName_ = dict.lookupOrDefault<word>("cloud", "cloud");
    requireSinterCloud(mesh_, dict);
    height_ = dict.get<scalar>("height");
    thickness_ = keywordRange::above<scalar>
    (
        dict,
        "thickness",
        0,
        false,
        "the slab thickness [m]"
    );
    nBins_ = keywordRange::aboveOrDefault<label>
    (
        dict,
        "bins",
        20,
        1,
        true,
        "the number of bins"
    );
    averageFrom_ = dict.lookupOrDefault<scalar>("averageFrom", 0);

    const vector g = meshObjects::gravity::New(mesh_.time()).value();
    if (mag(g) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << name() << " needs gravity (constant/g) to know what is"
            << " horizontal" << exit(FatalIOError);
    }
    up_ = -g/mag(g);
    axis_ = dict.lookupOrDefault<vector>("axis", vector(1, 0, 0));
    if (mag(axis_) < VSMALL || mag(axis_ & up_) > 1e-6*mag(axis_))
    {
        FatalIOErrorInKeyword(dict, "axis")
            << "Keyword axis of " << name() << " must be a horizontal"
            << " direction (normal to g = " << g << "), not " << axis_
            << exit(FatalIOError);
    }
    axis_ /= mag(axis_);

    // The mesh's extent along the axis
    const pointField corners(mesh_.bounds().points());
    axisLo_ = GREAT;
    axisHi_ = -GREAT;
    for (const point& c : corners)
    {
        axisLo_ = min(axisLo_, c & axis_);
        axisHi_ = max(axisHi_, c & axis_);
    }

    // The slab's volume per bin: each cell's volume times the share of its
    // height in the slab and of its extent along the axis in the bin
    binVolume_.setSize(nBins_);
    binVolume_ = Zero;
    const scalar zLo = height_ - 0.5*thickness_, zHi = height_ + 0.5*thickness_;
    const scalar w = (axisHi_ - axisLo_)/nBins_;
    const pointField& points = mesh_.points();
    const labelListList& cellPoints = mesh_.cellPoints();
    forAll(cellPoints, celli)
    {
        scalar z0 = GREAT, z1 = -GREAT, a0 = GREAT, a1 = -GREAT;
        for (const label pointi : cellPoints[celli])
        {
            const scalar z = points[pointi] & up_;
            const scalar a = points[pointi] & axis_;
            z0 = min(z0, z);
            z1 = max(z1, z);
            a0 = min(a0, a);
            a1 = max(a1, a);
        }
        const scalar inSlab = min(z1, zHi) - max(z0, zLo);
        if (!(inSlab > 0) || !(z1 > z0) || !(a1 > a0))
        {
            continue;
        }
        const scalar v = mesh_.cellVolumes()[celli]*inSlab/(z1 - z0);
        const label b0 = max(label((a0 - axisLo_)/w), label(0));
        const label b1 = min(label((a1 - axisLo_)/w), nBins_ - 1);
        for (label b = b0; b <= b1; ++b)
        {
            const scalar lo = axisLo_ + b*w, hi = lo + w;
            const scalar share = min(a1, hi) - max(a0, lo);
            if (share > 0)
            {
                binVolume_[b] += v*share/(a1 - a0);
            }
        }
    }
    Pstream::listCombineGather(binVolume_, plusEqOp<scalar>());
    Pstream::listCombineScatter(binVolume_);
    if (!(sum(binVolume_) > 0))
    {
        FatalIOErrorInKeyword(dict, "height")
            << "The slab of " << name() << " at height " << height_
            << " m (thickness " << thickness_ << " m) holds no cell of the"
            << " mesh" << exit(FatalIOError);
    }
    Log << type() << " " << name() << ": the plane's cross-section "
        << sum(binVolume_)/thickness_ << " m^2 (from the mesh's cells)"
        << endl;

    if (profileSum_.size() != nBins_)
    {
        profileSum_.setSize(nBins_, Zero);
        nSamples_ = 0;
    }
    return true;
}


bool Foam::functionObjects::solidsFlux::execute()
{
    const basicSinterCloud& cloud = *findSinterCloud(mesh_, cloudName_);
    const label n = cloud.size();
    vectorField position(n), U(n);
    scalarField volume(n);
    label i = 0;
    for (const basicSinterParcel& p : cloud)
    {
        position[i] = p.position();
        U[i] = cloud.velocity(p);
        volume[i] = p.nParticle()*constant::mathematical::pi/6*pow3(p.d());
        ++i;
    }

    scalarField binSum(nBins_, Zero);
    scalar upSum = 0, downSum = 0;
    label inSlab = slabSums
    (
        position, U, volume, up_, height_, thickness_, axis_,
        axisLo_, axisHi_, binSum, upSum, downSum
    );
    Pstream::listCombineGather(binSum, plusEqOp<scalar>());
    Pstream::listCombineScatter(binSum);
    reduce(upSum, sumOp<scalar>());
    reduce(downSum, sumOp<scalar>());
    reduce(inSlab, sumOp<label>());

    const scalar slabVolume = sum(binVolume_);

    if (mesh_.time().value() >= averageFrom_ - 0.5*mesh_.time().deltaTValue())
    {
        forAll(profileSum_, b)
        {
            if (binVolume_[b] > 0)
            {
                profileSum_[b] += binSum[b]/binVolume_[b];
            }
        }
        ++nSamples_;
    }

    if (Pstream::master() && writeToFile())
    {
        file()
            << mesh_.time().timeName() << tab
            << (upSum + downSum)/slabVolume << tab << upSum/slabVolume << tab
            << downSum/slabVolume << tab << inSlab << endl;
    }

    // The average's state, written with the time's
    if (mesh_.time().writeTime())
    {
        setProperty("profileSum", profileSum_);
        setProperty("samples", nSamples_);
    }
    return true;
}


bool Foam::functionObjects::solidsFlux::write()
{
    if (Pstream::master())
    {
        const fileName dir(baseFileDir()/name()/mesh_.time().timeName());
        mkDir(dir);
        OFstream os(dir/"solidsFluxProfile.dat");
        const scalar w = (axisHi_ - axisLo_)/nBins_;
        os  << "# Time-averaged solids volume flux through the plane at height "
            << height_ << " m (slab " << thickness_ << " m), along "
            << axis_ << nl
            << "# averaged over " << nSamples_ << " evaluations from t = "
            << averageFrom_ << " s" << nl
            << "# position [m]\tflux [m/s]" << nl;
        forAll(profileSum_, b)
        {
            os  << axisLo_ + (b + 0.5)*w << tab
                << (nSamples_ ? profileSum_[b]/nSamples_ : 0) << nl;
        }
    }
    return true;
}
