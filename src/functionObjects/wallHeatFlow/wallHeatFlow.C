// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "wallHeatFlow.H"
#include "gasConduction.H"
#include "volFields.H"
#include "addToRunTimeSelectionTable.H"
#include "findSinterCloud.H"
#include "keywordSource.H"
#include "patchSelection.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(wallHeatFlow, 0);
    addToRunTimeSelectionTable(functionObject, wallHeatFlow, dictionary);
}
}


Foam::functionObjects::wallHeatFlow::wallHeatFlow
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
        writeHeader(file(), "Heat flow from the walls into the bed [W]");
        const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
        for (const label patchi : patches_)
        {
            writeHeaderValue
            (
                file(),
                "Area " + pbm[patchi].name() + " [m^2]",
                gSum(mesh_.magSf().boundaryField()[patchi])
            );
        }
        writeCommented(file(), "Time");
        for (const label patchi : patches_)
        {
            const word& n = pbm[patchi].name();
            writeTabbed(file(), n + ":Q_gas");
            writeTabbed(file(), n + ":Q_p");
            writeTabbed(file(), n + ":Q");
        }
        file() << endl;
    }
}


bool Foam::functionObjects::wallHeatFlow::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    patches_ = selectPatches(mesh_.boundaryMesh(), dict);

    cloudName_ = dict.lookupOrDefault<word>("cloud", "cloud");
    hName_ = dict.lookupOrDefault<word>("h", "h");
    alphaEffName_ = dict.lookupOrDefault<word>("alphaEff", "alphaEff");

    return true;
}


bool Foam::functionObjects::wallHeatFlow::execute()
{
    return true;
}


bool Foam::functionObjects::wallHeatFlow::write()
{
    const scalar dt = mesh_.time().deltaTValue();
    const basicSinterCloud* cloudPtr = findSinterCloud(mesh_, cloudName_);
    const volScalarField& h = lookupObject<volScalarField>(hName_);
    const volScalarField& alphaEff =
        lookupObject<volScalarField>(alphaEffName_);

    List<scalar> Qgas(patches_.size());
    List<scalar> Qp(patches_.size(), scalar(0));
    forAll(patches_, i)
    {
        const label patchi = patches_[i];
        Qgas[i] = returnReduce
        (
            gasConductionIn(alphaEff, h, patchi), sumOp<scalar>()
        );
        if (cloudPtr)
        {
            Qp[i] = cloudPtr->conductedWallHeat(patchi)/dt;
        }
    }
    Pstream::listCombineGather(Qp, plusEqOp<scalar>());

    if (Pstream::master() && writeToFile())
    {
        file() << mesh_.time().timeName();
        forAll(patches_, i)
        {
            file()
                << tab << Qgas[i] << tab << Qp[i] << tab << Qgas[i] + Qp[i];
        }
        file() << endl;
    }
    return true;
}
