// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "agglomerateStatistics.H"
#include "addToRunTimeSelectionTable.H"
#include "findSinterCloud.H"
#include "IOField.H"
#include "OFstream.H"
#include <algorithm>
#include <map>
#include "keywordSource.H"
#include "keywordRange.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(agglomerateStatistics, 0);
    addToRunTimeSelectionTable
    (
        functionObject,
        agglomerateStatistics,
        dictionary
    );
}
}


Foam::functionObjects::agglomerateStatistics::agglomerateStatistics
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    minContactTime_(0.01),
    minSize_(5),
    bridgedOnly_(false)
{
    read(dict);

    if (Pstream::master() && writeToFile())
    {
        writeHeader(file(), "Agglomerates (thesis 5.4.2)");
        writeHeaderValue(file(), "minContactTime [s]", minContactTime_);
        writeHeaderValue(file(), "minSize [parcels]", minSize_);
        writeHeaderValue(file(), "bridgedOnly", Switch(bridgedOnly_));
        writeCommented(file(), "Time");
        for
        (
            const char* c :
            {
                "nAgglomerates", "particleFraction", "massFraction",
                "largestFraction", "meanSize", "parcels"
            }
        )
        {
            writeTabbed(file(), c);
        }
        file() << endl;
    }
}


bool Foam::functionObjects::agglomerateStatistics::read
(
    const dictionary& dict
)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    cloudName_ = dict.lookupOrDefault<word>("cloud", "cloud");
    const demEngine* engine = requireSinterCloud(mesh_, dict).engine();
    if (!engine)
    {
        FatalIOErrorInFunction(dict)
            << "Cloud " << cloudName_ << " of " << name() << " has no DEM"
            << " engine: agglomerates need collisionModel demCollision"
            << exit(FatalIOError);
    }
    minContactTime_ = keywordRange::aboveOrDefault<scalar>
    (
        dict, "minContactTime", 0.01, 0, true,
        "the least contact time [s] of an agglomerate's contact"
    );
    minSize_ = keywordRange::aboveOrDefault<label>
    (
        dict, "minSize", 5, 2, true,
        "the least number of parcels of an agglomerate"
    );
    bridgedOnly_ = dict.lookupOrDefault<Switch>("bridgedOnly", false);

    if (bridgedOnly_ && engine->cohesion().bridgeSlot() < 0)
    {
        FatalIOErrorInKeyword(dict, "bridgedOnly")
            << "Keyword bridgedOnly of " << name() << " needs a cohesion"
            << " model with bridges (cohesionModel solidBridge), not "
            << engine->cohesion().type() << exit(FatalIOError);
    }
    return true;
}


void Foam::functionObjects::agglomerateStatistics::evaluate
(
    const bool writeFields
)
{
    const basicSinterCloud* cloudPtr = findSinterCloud(mesh_, cloudName_);
    if (!cloudPtr || !cloudPtr->engine())
    {
        FatalErrorInFunction
            << name() << ": no cloud " << cloudName_ << " with the DEM"
            << " engine (collisionModel demCollision)" << exit(FatalError);
    }
    const demEngine& engine = *cloudPtr->engine();
    const contactGraphComponents c =
        engine.agglomerates(minContactTime_, bridgedOnly_);
    const List<demIdentity>& compLabel = c.labels();
    const labelList& size = c.sizes();
    const demParticles& P = engine.particles();

    // Over the engine's local particles: every particle is local to one
    // engine, and an agglomerate is counted where its smallest identity is
    label nParcels = 0, nIn = 0, nAgg = 0, largest = 0;
    scalar mass = 0, massIn = 0;
    DynamicList<demIdentity> aggLabel;
    DynamicList<label> aggSize;
    forAll(compLabel, i)
    {
        const scalar m = P.invMass[i] > 0 ? 1/P.invMass[i] : 0;
        ++nParcels;
        mass += m;
        largest = max(largest, size[i]);
        if (size[i] >= minSize_)
        {
            ++nIn;
            massIn += m;
            if (P.identity[i] == compLabel[i])
            {
                ++nAgg;
                aggLabel.append(compLabel[i]);
                aggSize.append(size[i]);
            }
        }
    }
    reduce(nParcels, sumOp<label>());
    reduce(nIn, sumOp<label>());
    reduce(nAgg, sumOp<label>());
    reduce(largest, maxOp<label>());
    reduce(mass, sumOp<scalar>());
    reduce(massIn, sumOp<scalar>());

    if (Pstream::master() && writeToFile())
    {
        file()
            << mesh_.time().timeName()
            << tab << nAgg
            << tab << (nParcels ? scalar(nIn)/nParcels : 0)
            << tab << (mass > 0 ? massIn/mass : 0)
            << tab << (nParcels ? scalar(largest)/nParcels : 0)
            << tab << (nAgg ? scalar(nIn)/nAgg : 0)
            << tab << nParcels << endl;
    }

    if (!writeFields)
    {
        return;
    }

    // The agglomerates of all processors on the master, numbered in the
    // order of their labels; the histogram of their sizes
    List<List<demIdentity>> labels(Pstream::nProcs());
    labels[Pstream::myProcNo()] = aggLabel;
    List<labelList> sizes(Pstream::nProcs());
    sizes[Pstream::myProcNo()] = aggSize;
    Pstream::gatherList(labels);
    Pstream::gatherList(sizes);
    List<demIdentity> sorted;
    if (Pstream::master())
    {
        std::map<label, label> histogram;
        DynamicList<demIdentity> all;
        forAll(labels, proci)
        {
            all.append(labels[proci]);
            for (const label s : sizes[proci])
            {
                ++histogram[s];
            }
        }
        sorted.transfer(all);
        std::sort(sorted.begin(), sorted.end());

        if (writeToFile())
        {
            const fileName dir
            (
                baseFileDir()/name()/mesh_.time().timeName()
            );
            mkDir(dir);
            OFstream os(dir/"agglomerateSizes.dat");
            os  << "# Agglomerate sizes at t = " << mesh_.time().timeName()
                << " s: size [parcels], number of agglomerates" << nl;
            for (const auto& h : histogram)
            {
                os  << h.first << tab << h.second << nl;
            }
        }
    }
    Pstream::scatter(sorted);

    // Per parcel, in the cloud's order (the order its fields are written)
    IOField<label> ids
    (
        IOobject
        (
            "agglomerateId",
            mesh_.time().timeName(),
            cloud::prefix/cloudName_,
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        cloudPtr->size()
    );
    label n = 0;
    for (const auto& p : *cloudPtr)
    {
        const label k = p.demIndex();
        label id = -1;
        if (k >= 0 && k < size.size() && size[k] >= minSize_)
        {
            id = label
            (
                std::lower_bound(sorted.begin(), sorted.end(), compLabel[k])
              - sorted.begin()
            );
        }
        ids[n++] = id;
    }
    ids.write();
}


bool Foam::functionObjects::agglomerateStatistics::execute()
{
    evaluate(mesh_.time().writeTime());
    return true;
}


bool Foam::functionObjects::agglomerateStatistics::write()
{
    return true;
}
