// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "particleStatistics.H"
#include "addToRunTimeSelectionTable.H"
#include "findSinterCloud.H"
#include "keywordRange.H"
#include "volFields.H"
#include "OFstream.H"
#include "gravityMeshObject.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(particleStatistics, 0);
    addToRunTimeSelectionTable(functionObject, particleStatistics, dictionary);
}
}


Foam::functionObjects::particleStatistics::particleStatistics
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    speedMax_(1),
    speedBins_(50),
    Tmin_(273.15),
    Tmax_(1473.15),
    Tbins_(120)
{
    read(dict);

    if (Pstream::master() && writeToFile())
    {
        writeHeader
        (
            file(),
            zoneName_.empty()
          ? string("Particle phase (temperatures in K)")
          : "Particle phase in cellZone " + zoneName_
          + " (temperatures in K)"
        );
        writeCommented(file(), "Time");
        for
        (
            const char* c :
            {
                "parcels", "particles", "T_mean", "T_std", "T_min", "T_max",
                "U_mean", "U_std", "U_max", "Theta_mean", "z_mean", "z_max"
            }
        )
        {
            writeTabbed(file(), c);
        }
        file() << endl;
    }
}


bool Foam::functionObjects::particleStatistics::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    cloudName_ = dict.lookupOrDefault<word>("cloud", "cloud");
    requireSinterCloud(mesh_, dict);
    if (!mesh_.foundObject<volScalarField>("granularTemperature"))
    {
        FatalIOErrorInFunction(dict)
            << "Cloud " << cloudName_ << " of " << name() << " keeps no"
            << " granularTemperature field: it needs collisionModel"
            << " demCollision" << exit(FatalIOError);
    }

    zoneName_ = dict.lookupOrDefault<word>("cellZone", word::null);
    selected_.clear();
    if (!zoneName_.empty())
    {
        const label zonei = mesh_.cellZones().findZoneID(zoneName_);
        if (zonei < 0)
        {
            FatalIOErrorInFunction(dict)
                << "Keyword cellZone of " << name() << ": no cellZone "
                << zoneName_ << " in the mesh (make it with topoSet)."
                << nl << "Valid cellZones are "
                << mesh_.cellZones().names() << exit(FatalIOError);
        }
        selected_.setSize(mesh_.nCells(), false);
        for (const label celli : mesh_.cellZones()[zonei])
        {
            selected_[celli] = true;
        }
    }

    const dictionary speed(dict.subOrEmptyDict("speedDistribution"));
    speedMax_ = keywordRange::aboveOrDefault<scalar>
    (
        speed,
        "max",
        1,
        0,
        false,
        "the top of the speed bins [m/s]"
    );
    speedBins_ = keywordRange::aboveOrDefault<label>
    (
        speed,
        "bins",
        50,
        1,
        true,
        "the number of bins"
    );

    const dictionary T(dict.subOrEmptyDict("temperatureDistribution"));
    Tmin_ = keywordRange::aboveOrDefault<scalar>
    (
        T,
        "min",
        273.15,
        0,
        false,
        "the lowest temperature bin [K]"
    );
    Tmax_ = keywordRange::aboveOrDefault<scalar>
    (
        T,
        "max",
        1473.15,
        Tmin_,
        false,
        "the top temperature bin [K]"
    );
    Tbins_ = keywordRange::aboveOrDefault<label>
    (
        T,
        "bins",
        120,
        1,
        true,
        "the number of bins"
    );

    return true;
}


void Foam::functionObjects::particleStatistics::distributions
(
    binnedDistribution& speed,
    binnedDistribution& T,
    const bool massWeighted
) const
{
    const basicSinterCloud& cloud = *findSinterCloud(mesh_, cloudName_);

    for (const basicSinterParcel& p : cloud)
    {
        if (!counts(p.cell())) continue;
        const scalar n = p.nParticle();
        speed.add(mag(cloud.velocity(p)), n);
        T.add(cloud.temperature(p), massWeighted ? n*cloud.mass(p) : n);
    }
    speed.reduce();
    T.reduce();
    for (const basicSinterParcel& p : cloud)
    {
        if (!counts(p.cell())) continue;
        const scalar n = p.nParticle();
        speed.addSpread(mag(cloud.velocity(p)), n);
        T.addSpread(cloud.temperature(p), massWeighted ? n*cloud.mass(p) : n);
    }
    speed.reduceSpread();
    T.reduceSpread();
}


bool Foam::functionObjects::particleStatistics::execute()
{
    binnedDistribution speed(0, speedMax_, speedBins_);
    binnedDistribution Tmass(Tmin_, Tmax_, Tbins_);
    distributions(speed, Tmass, true);

    // The granular temperature of the parcels' cells
    const basicSinterCloud& cloud = *findSinterCloud(mesh_, cloudName_);
    const volScalarField& Theta =
        mesh_.lookupObject<volScalarField>("granularTemperature");
    // and the parcels' heights above the mesh's lowest point, along -g
    // (along z without gravity)
    const vector g = meshObjects::gravity::New(mesh_.time()).value();
    const vector up = mag(g) > 0 ? -g/mag(g) : vector(0, 0, 1);
    const scalar floor = gMin(mesh_.points() & up);
    label parcels = 0;
    scalar sumTheta = 0;
    scalar mass = 0;
    scalar massHeight = 0;
    scalar top = 0;
    for (const basicSinterParcel& p : cloud)
    {
        if (!counts(p.cell())) continue;
        ++parcels;
        sumTheta += Theta[p.cell()];
        const scalar m = p.nParticle()*cloud.mass(p);
        const scalar z = (p.position() & up) - floor;
        mass += m;
        massHeight += m*z;
        top = max(top, z);
    }
    reduce(parcels, sumOp<label>());
    reduce(sumTheta, sumOp<scalar>());
    reduce(mass, sumOp<scalar>());
    reduce(massHeight, sumOp<scalar>());
    reduce(top, maxOp<scalar>());

    if (Pstream::master() && writeToFile())
    {
        file()
            << mesh_.time().timeName() << tab << parcels << tab
            << speed.total() << tab << Tmass.mean() << tab << Tmass.stdDev()
            << tab << Tmass.min() << tab << Tmass.max() << tab
            << speed.mean() << tab << speed.stdDev() << tab << speed.max()
            << tab << (parcels ? sumTheta/parcels : 0)
            << tab << (mass > 0 ? massHeight/mass : 0) << tab << top << endl;
    }
    return true;
}


bool Foam::functionObjects::particleStatistics::write()
{
    binnedDistribution speed(0, speedMax_, speedBins_);
    binnedDistribution T(Tmin_, Tmax_, Tbins_);
    distributions(speed, T, false);

    if (Pstream::master())
    {
        const fileName dir(baseFileDir()/name()/mesh_.time().timeName());
        mkDir(dir);
        OFstream speedFile(dir/"speedDistribution.dat");
        speed.write(speedFile, "particle speed", "m/s");
        OFstream Tfile(dir/"temperatureDistribution.dat");
        T.write(Tfile, "particle temperature", "K");
    }
    return true;
}
