// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "bedPressureDrop.H"
#include "volFields.H"
#include "gravityMeshObject.H"
#include "addToRunTimeSelectionTable.H"
#include "findSinterCloud.H"

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
        FatalIOErrorInFunction(dict)
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
    upperPatch_(-1)
{
    read(dict);
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
    voidageName_ = dict.lookupOrDefault<word>("voidage", "voidage");

    return true;
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


bool Foam::functionObjects::bedPressureDrop::execute()
{
    return true;
}


bool Foam::functionObjects::bedPressureDrop::write()
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
            const scalar m = parcel.nParticle()*parcel.mass();
            mass += m;
            massVoidage += m*voidage[parcel.cell()];
        }
    }
    reduce(mass, sumOp<scalar>());
    reduce(massVoidage, sumOp<scalar>());

    const scalar g = mag(meshObjects::gravity::New(mesh_.time()).value());
    const scalar area = gSum(mesh_.magSf().boundaryField()[lowerPatch_]);
    const scalar WbyA = g*mass/area;

    if (Pstream::master() && writeToFile())
    {
        file()
            << mesh_.time().timeName() << tab << dp << tab << WbyA << tab
            << (WbyA > 0 ? dp/WbyA : 0) << tab
            << (mass > 0 ? massVoidage/mass : 1) << endl;
    }

    return true;
}
