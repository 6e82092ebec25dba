// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "wallHeatFlow.H"
#include "volFields.H"
#include "wallPolyPatch.H"
#include "addToRunTimeSelectionTable.H"
#include "findSinterCloud.H"

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

    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    if (dict.found("patches"))
    {
        const wordRes names(dict.get<wordRes>("patches"));
        DynamicList<label> ids;
        for (const wordRe& name : names)
        {
            DynamicList<label> matched;
            forAll(pbm, patchi)
            {
                if (name.match(pbm[patchi].name()))
                {
                    matched.append(patchi);
                }
            }
            if (matched.empty())
            {
                FatalIOErrorInFunction(dict)
                    << "No patch matches " << name << " of keyword patches"
                    << nl << "Valid patches are " << pbm.names()
                    << exit(FatalIOError);
            }
            for (const label patchi : matched)
            {
                if (!ids.found(patchi))
                {
                    ids.append(patchi);
                }
            }
        }
        patches_.transfer(ids);
    }
    else
    {
        DynamicList<label> ids;
        forAll(pbm, patchi)
        {
            if (isA<wallPolyPatch>(pbm[patchi]))
            {
                ids.append(patchi);
            }
        }
        patches_.transfer(ids);
    }

    cloudName_ = dict.lookupOrDefault<word>("cloud", "cloud");
    hName_ = dict.lookupOrDefault<word>("h", "h");
    alphaEffName_ = dict.lookupOrDefault<word>("alphaEff", "alphaEff");

    return true;
}


Foam::scalar Foam::functionObjects::wallHeatFlow::gasHeatFlow
(
    const label patchi
) const
{
    const volScalarField& h = lookupObject<volScalarField>(hName_);
    const volScalarField& alphaEff =
        lookupObject<volScalarField>(alphaEffName_);

    // The face normal points out of the domain: into the domain is
    // alphaEff (h_face - h_cell) deltaCoeff |Sf| = alphaEff dh/dn |Sf|
    return gSum
    (
        alphaEff.boundaryField()[patchi]*h.boundaryField()[patchi].snGrad()
       *mesh_.magSf().boundaryField()[patchi]
    );
}


bool Foam::functionObjects::wallHeatFlow::execute()
{
    return true;
}


bool Foam::functionObjects::wallHeatFlow::write()
{
    const scalar dt = mesh_.time().deltaTValue();
    const basicSinterCloud* cloudPtr = findSinterCloud(mesh_, cloudName_);

    List<scalar> Qgas(patches_.size());
    List<scalar> Qp(patches_.size(), scalar(0));
    forAll(patches_, i)
    {
        Qgas[i] = gasHeatFlow(patches_[i]);
        if (cloudPtr)
        {
            Qp[i] = cloudPtr->conductedWallHeat(patches_[i])/dt;
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
