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
    depth_(0),
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
    const vector across = up_ ^ axis_;

    // The mesh's extents along the axis and across it
    const pointField corners(mesh_.bounds().points());
    axisLo_ = GREAT;
    axisHi_ = -GREAT;
    scalar acrossLo = GREAT, acrossHi = -GREAT;
    for (const point& c : corners)
    {
        axisLo_ = min(axisLo_, c & axis_);
        axisHi_ = max(axisHi_, c & axis_);
        acrossLo = min(acrossLo, c & across);
        acrossHi = max(acrossHi, c & across);
    }
    depth_ = acrossHi - acrossLo;

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

    const scalar slabVolume = (axisHi_ - axisLo_)*depth_*thickness_;
    const scalar binVolume = slabVolume/nBins_;

    if (mesh_.time().value() >= averageFrom_ - 0.5*mesh_.time().deltaTValue())
    {
        profileSum_ += binSum/binVolume;
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
