// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "writtenTimes.H"
#include "OFstream.H"
#include "IFstream.H"
#include "OSspecific.H"

const char* const Foam::writtenTimes::markerName = "sinterFoamWritten";


void Foam::writtenTimes::markComplete
(
    const Time& runTime,
    const label nParcels
)
{
    if (!runTime.writeTime())
    {
        return;
    }
    const label nTotal = returnReduce(nParcels, sumOp<label>());
    const fileName dir(runTime.timePath()/"uniform");
    mkDir(dir);
    OFstream os(dir/markerName);
    os  << "// Every object of this time was written (sinterFoam)" << nl
        << "parcels " << nTotal << ";    // of the whole case" << nl;
}


Foam::label Foam::writtenTimes::checkStart
(
    const Time& runTime,
    const word& cloudName
)
{
    const fileName dir(runTime.timePath());
    if (!isFile(dir/"uniform"/"time"))
    {
        return -1;  // prepared by the user
    }

    const fileName marker(dir/"uniform"/markerName);
    if (!isFile(marker))
    {
        FatalErrorInFunction
            << "The start time " << runTime.timeName() << " in "
            << dir << " is incomplete: it has no uniform/" << markerName
            << ", which sinterFoam writes after every other file of a"
            << " time. The run that wrote it was stopped while writing."
            << nl << "Remove this time (in every processor directory of a"
            << " decomposed case) and restart from the time before it"
            << exit(FatalError);
    }

    IFstream is(marker);
    const dictionary written(is);
    const label nParcels = written.get<label>("parcels");

    // Over all processors (decomposePar and reconstructPar copy the
    // marker; a processor may hold no parcel)
    const fileName cloudDir(dir/"lagrangian"/cloudName);
    const bool anyParcels =
        returnReduce(isFile(cloudDir/"coordinates"), orOp<bool>());
    if (nParcels > 0 && !anyParcels)
    {
        FatalErrorInFunction
            << "The start time " << runTime.timeName() << " was written"
            << " with " << nParcels << " parcels, but "
            << cloudDir/"coordinates" << " is missing: the run would"
            << " restart with an empty bed." << nl
            << "Restore the time's lagrangian/" << cloudName
            << " directory or restart from another time"
            << exit(FatalError);
    }
    const fileName state
    (
        dir/"uniform"/"lagrangian"/cloudName/"cloudOutputProperties"
    );
    if (!isFile(state))
    {
        FatalErrorInFunction
            << "The start time " << runTime.timeName() << " has no "
            << state << ": the cloud's injectors would start again and"
            << " inject their parcels a second time." << nl
            << "Restore the file or restart from another time"
            << exit(FatalError);
    }
    return nParcels;
}


void Foam::writtenTimes::checkParcelsRead
(
    const Time& runTime,
    const label nWritten,
    const label nRead
)
{
    const label nTotal = returnReduce(nRead, sumOp<label>());
    if (nWritten >= 0 && nTotal != nWritten)
    {
        FatalErrorInFunction
            << "The start time " << runTime.timeName() << " was written"
            << " with " << nWritten << " parcels, but " << nTotal
            << " were read from its lagrangian files"
            << (Pstream::parRun() ? " (over all processors)" : "")
            << ": a processor's files are missing or cut short." << nl
            << "Restore the time's lagrangian directories or restart from"
            << " another time" << exit(FatalError);
    }
}
