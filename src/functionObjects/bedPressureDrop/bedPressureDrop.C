// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "bedPressureDrop.H"
#include "volFields.H"
#include "gravityMeshObject.H"
#include "addToRunTimeSelectionTable.H"
#include "findSinterCloud.H"
#include "keywordRange.H"
#include "keywordSource.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(bedPressureDrop, 0);
    addToRunTimeSelectionTable(functionObject, bedPressureDrop, dictionary);
}
}


// Patch index of the keyword's patch name, or a fatal error naming it
static Foam::label requiredPatch
(
    const Foam::fvMesh& mesh,
    const Foam::dictionary& dict,
    const Foam::word& key
)
{
    const Foam::word name(dict.get<Foam::word>(key));
    const Foam::label patchi = mesh.boundaryMesh().findPatchID(name);
    if (patchi < 0)
    {
        FatalIOErrorInKeyword(dict, key)
            << "Unknown patch " << name << " for keyword " << key << Foam::nl
            << "Valid patches are " << mesh.boundaryMesh().names()
            << Foam::exit(Foam::FatalIOError);
    }
    return patchi;
}


Foam::functionObjects::bedPressureDrop::bedPressureDrop
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    lowerPatch_(-1),
    upperPatch_(-1),
    window_(0),
    ratioBelow_(0),
    stdBelow_(0),
    duration_(0),
    first_(0),
    historyStart_(-1)
{
    read(dict);
    restoreState();
    if (!Pstream::master() || !writeToFile())
    {
        return;
    }
    writeHeader(file(), "Bed pressure drop");
    writeCommented(file(), "Time");
    writeTabbed(file(), "dp");
    writeTabbed(file(), "W/A");
    writeTabbed(file(), "dp/(W/A)");
    writeTabbed(file(), "eps_bed");
    writeTabbed(file(), "dp_mean");
    writeTabbed(file(), "dp_std");
    writeTabbed(file(), "defluidized");
    writeTabbed(file(), "frozen");
    file() << endl;
}


bool Foam::functionObjects::bedPressureDrop::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    lowerPatch_ = requiredPatch(mesh_, dict, "lowerPatch");
    upperPatch_ = requiredPatch(mesh_, dict, "upperPatch");
    pName_ = dict.lookupOrDefault<word>("p", "p");
    cloudName_ = dict.lookupOrDefault<word>("cloud", "cloud");
    requireSinterCloud(mesh_, dict);
    voidageName_ = dict.lookupOrDefault<word>("voidage", "voidage");

    window_ = keywordRange::aboveOrDefault<scalar>
    (
        dict,
        "window",
        0.2,
        0,
        false,
        "the averaging window [s]"
    );
    if (dict.found("defluidization") && !dict.isDict("defluidization"))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword defluidization of " << name() << " must be a"
            << " sub-dictionary of ratioBelow, stdBelow and duration"
            << exit(FatalIOError);
    }
    const dictionary crit(dict.subOrEmptyDict("defluidization"));
    ratioBelow_ = keywordRange::aboveOrDefault<scalar>
    (
        crit,
        "ratioBelow",
        0.8,
        0,
        false,
        "dp/(W/A) below which a still bed has collapsed [-]"
    );
    stdBelow_ = keywordRange::aboveOrDefault<scalar>
    (
        crit,
        "stdBelow",
        0.02,
        0,
        false,
        "the STD of dp/(W/A) below which the bed is still [-]"
    );
    duration_ = keywordRange::aboveOrDefault<scalar>
    (
        crit,
        "duration",
        window_,
        0,
        true,
        "how long the criteria must hold [s]"
    );

    return true;
}


void Foam::functionObjects::bedPressureDrop::addSample
(
    const scalar t,
    const scalar dp,
    const scalar dt
)
{
    if (historyStart_ < 0)
    {
        historyStart_ = t;
    }
    sampleTime_.append(t);
    sampleDp_.append(dp);
    // Keep at least the newest sample, whatever the window
    while
    (
        first_ < sampleTime_.size() - 1
     && t - sampleTime_[first_] >= window_ - 0.5*dt
    )
    {
        ++first_;
    }

    // Drop the old samples from the storage now and then
    if (first_ > 1024 && 2*first_ > sampleTime_.size())
    {
        const label n = sampleTime_.size() - first_;
        for (label i = 0; i < n; ++i)
        {
            sampleTime_[i] = sampleTime_[first_ + i];
            sampleDp_[i] = sampleDp_[first_ + i];
        }
        sampleTime_.resize(n);
        sampleDp_.resize(n);
        first_ = 0;
    }
}


void Foam::functionObjects::bedPressureDrop::storeState()
{
    const label n = sampleTime_.size() - first_;
    setProperty("windowTimes", scalarList(SubList<scalar>(sampleTime_, n, first_)));
    setProperty("windowDp", scalarList(SubList<scalar>(sampleDp_, n, first_)));
    setProperty("historyStart", historyStart_);
    setProperty("lookedDefluidizedSince", defluidized_.since);
    setProperty("defluidized", defluidized_.flag);
    setProperty("lookedFrozenSince", frozen_.since);
    setProperty("frozen", frozen_.flag);
}


void Foam::functionObjects::bedPressureDrop::restoreState()
{
    if (!foundProperty("windowTimes"))
    {
        return;
    }
    sampleTime_ = getProperty<scalarList>("windowTimes");
    sampleDp_ = getProperty<scalarList>("windowDp");
    first_ = 0;
    historyStart_ = getProperty<scalar>("historyStart");
    defluidized_.since = getProperty<scalar>("lookedDefluidizedSince");
    defluidized_.flag = getProperty<bool>("defluidized");
    // A state stored before the frozen state was diagnosed: it starts now
    if (foundProperty("frozen"))
    {
        frozen_.since = getProperty<scalar>("lookedFrozenSince");
        frozen_.flag = getProperty<bool>("frozen");
    }
    Info<< type() << ' ' << name() << ": continues its window of "
        << sampleTime_.size() << " samples from the stored state" << endl;
}


bool Foam::functionObjects::bedPressureDrop::update
(
    stillState& state,
    const bool looks,
    const scalar t,
    const scalar dt
) const
{
    if (!looks)
    {
        state.since = -1;
        const bool changed = state.flag;
        state.flag = false;
        return changed;
    }
    if (state.since < 0)
    {
        state.since = t;
    }
    if (!state.flag && t - state.since >= duration_ - 0.5*dt)
    {
        state.flag = true;
        return true;
    }
    return false;
}


Foam::scalar Foam::functionObjects::bedPressureDrop::patchAverage
(
    const volScalarField& p,
    const label patchi
) const
{
    const scalarField& magSf = mesh_.magSf().boundaryField()[patchi];
    return
        gSum(magSf*p.boundaryField()[patchi])
       /max(gSum(magSf), VSMALL);
}


bool Foam::functionObjects::bedPressureDrop::write()
{
    return true;
}


bool Foam::functionObjects::bedPressureDrop::execute()
{
    const volScalarField& p = lookupObject<volScalarField>(pName_);
    const scalar dp = patchAverage(p, lowerPatch_) - patchAverage(p, upperPatch_);

    const volScalarField& voidage = lookupObject<volScalarField>(voidageName_);

    // Mass and mass-weighted voidage at the parcels
    scalar mass = 0;
    scalar massVoidage = 0;
    if (const basicSinterCloud* cloudPtr = findSinterCloud(mesh_, cloudName_))
    {
        for (const basicSinterParcel& parcel : *cloudPtr)
        {
            const scalar m = parcel.nParticle()*cloudPtr->mass(parcel);
            mass += m;
            massVoidage += m*voidage[parcel.cell()];
        }
    }
    reduce(mass, sumOp<scalar>());
    reduce(massVoidage, sumOp<scalar>());

    const scalar g = mag(meshObjects::gravity::New(mesh_.time()).value());
    const scalar area = gSum(mesh_.magSf().boundaryField()[lowerPatch_]);
    const scalar WbyA = g*mass/area;

    // The moving window
    const Time& time = mesh_.time();
    const scalar t = time.value();
    const scalar dt = time.deltaTValue();
    addSample(t, dp, dt);
    const label n = sampleTime_.size() - first_;
    scalar mean = 0;
    for (label i = first_; i < sampleDp_.size(); ++i)
    {
        mean += sampleDp_[i];
    }
    mean /= n;
    scalar var = 0;
    for (label i = first_; i < sampleDp_.size(); ++i)
    {
        var += sqr(sampleDp_[i] - mean);
    }
    const scalar stdDev = sqrt(var/n);

    // The diagnosis
    const bool full = t - historyStart_ >= window_ - 0.5*dt;
    const bool still = full && WbyA > 0 && stdDev/WbyA < stdBelow_;
    const scalar ratio = WbyA > 0 ? mean/WbyA : 0;
    const scalar stdRatio = WbyA > 0 ? stdDev/WbyA : 0;
    const bool collapsed = still && ratio < ratioBelow_;

    // The window's figures, for the log when a flag changes
    const auto over = [&]()
    {
        return
            " s: over the last " + Foam::name(window_) + " s dp_mean/(W/A) = "
          + Foam::name(ratio) + ", dp_std/(W/A) = " + Foam::name(stdRatio);
    };
    if (update(defluidized_, collapsed, t, dt))
    {
        if (defluidized_.flag)
        {
            Info<< type() << ' ' << name() << ": the bed defluidized at t = "
                << t << over().c_str() << " (< " << ratioBelow_ << " and < "
                << stdBelow_ << " since t = " << defluidized_.since << " s)"
                << endl;
        }
        else
        {
            Info<< type() << ' ' << name() << ": the bed is no longer"
                << " defluidized at t = " << t << over().c_str() << endl;
        }
    }
    if (update(frozen_, still && !collapsed, t, dt))
    {
        if (frozen_.flag)
        {
            Info<< type() << ' ' << name() << ": the bed froze at t = "
                << t << over().c_str() << " (>= " << ratioBelow_ << ": the gas"
                << " carries it; < " << stdBelow_ << ": it does not bubble;"
                << " since t = " << frozen_.since << " s)" << endl;
        }
        else
        {
            Info<< type() << ' ' << name() << ": the bed is no longer"
                << " frozen at t = " << t << over().c_str() << endl;
        }
    }

    if (Pstream::master() && writeToFile())
    {
        file()
            << time.timeName() << tab << dp << tab << WbyA << tab
            << (WbyA > 0 ? dp/WbyA : 0) << tab
            << (mass > 0 ? massVoidage/mass : 1) << tab
            << mean << tab << stdDev << tab << label(defluidized_.flag)
            << tab << label(frozen_.flag) << endl;
    }

    if (time.writeTime())
    {
        storeState();
    }

    return true;
}
