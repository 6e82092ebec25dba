// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "wallLoad.H"
#include "gravityMeshObject.H"
#include "addToRunTimeSelectionTable.H"
#include "findSinterCloud.H"
#include "patchSelection.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(wallLoad, 0);
    addToRunTimeSelectionTable(functionObject, wallLoad, dictionary);
}
}


Foam::functionObjects::wallLoad::wallLoad
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict)
{
    read(dict);

    if (Pstream::master() && writeToFile())
    {
        writeHeader
        (
            file(),
            "Load of the particles' contacts on the walls [N], share of"
            " the bed weight W [-]"
        );
        writeCommented(file(), "Time");
        writeTabbed(file(), "W");
        const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
        for (const label patchi : patches_)
        {
            const word& n = pbm[patchi].name();
            writeTabbed(file(), n + ":F_x");
            writeTabbed(file(), n + ":F_y");
            writeTabbed(file(), n + ":F_z");
            writeTabbed(file(), n + ":s");
        }
        writeTabbed(file(), "sum_s");
        file() << endl;
    }
}


bool Foam::functionObjects::wallLoad::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    patches_ = selectPatches(mesh_.boundaryMesh(), dict);
    cloudName_ = requireSinterCloud(mesh_, dict).name();

    return true;
}


bool Foam::functionObjects::wallLoad::execute()
{
    return true;
}


bool Foam::functionObjects::wallLoad::write()
{
    const basicSinterCloud* cloudPtr = findSinterCloud(mesh_, cloudName_);
    if (!cloudPtr)
    {
        return false;
    }

    const scalar dt = mesh_.time().deltaTValue();
    const vector g = meshObjects::gravity::New(mesh_.time()).value();
    const scalar gMag = mag(g);
    const scalar W =
        gMag*returnReduce(cloudPtr->massInSystem(), sumOp<scalar>());

    List<vector> F(patches_.size(), Zero);
    forAll(patches_, i)
    {
        F[i] = cloudPtr->wallImpulse(patches_[i])/dt;
    }
    Pstream::listCombineGather(F, plusEqOp<vector>());

    if (Pstream::master() && writeToFile())
    {
        // The share of the weight: the load along g over the weight (none
        // without a bed or without gravity)
        const scalar perWeight = W > VSMALL ? 1/(gMag*W) : 0;
        scalar sumShare = 0;
        file() << mesh_.time().timeName() << tab << W;
        forAll(patches_, i)
        {
            const scalar share = (F[i] & g)*perWeight;
            sumShare += share;
            file()
                << tab << F[i].x() << tab << F[i].y() << tab << F[i].z()
                << tab << share;
        }
        file() << tab << sumShare << endl;
    }
    return true;
}
