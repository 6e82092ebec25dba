// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "cloudCoupling.H"
#include "keywordRange.H"
#include "keywordSource.H"

namespace Foam
{
    defineTypeNameAndDebug(cloudCoupling, 0);
}


namespace
{

Foam::scalar readVoidageMin(const Foam::dictionary& dict)
{
    using namespace Foam;
    return keywordRange::get
    (
        dict, "voidageMin", 0, 1,
        "the smallest gas volume fraction the coupling allows", true, true
    );
}


bool readLocalGasTemperature(const Foam::dictionary& dict)
{
    using namespace Foam;
    const word kind
    (
        dict.lookupOrDefault<word>("parcelGasTemperature", "smoothed")
    );
    if (kind != "smoothed" && kind != "local")
    {
        FatalIOErrorInKeyword(dict, "parcelGasTemperature")
            << "Unknown parcelGasTemperature " << kind << nl
            << "Valid types are (smoothed local)"
            << exit(FatalIOError);
    }
    Info<< "Parcel-gas heat exchange with the gas temperature "
        << (kind == "local" ? "where each parcel is" : "smoothed over L")
        << " (parcelGasTemperature " << kind << ')' << endl;
    return kind == "local";
}

} // End anonymous namespace


Foam::cloudCoupling::cloudCoupling(const fvMesh& mesh)
:
    MeshObject<fvMesh, TopologicalMeshObject, cloudCoupling>(mesh),
    dict_
    (
        IOobject
        (
            "couplingProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ_IF_MODIFIED,
            IOobject::NO_WRITE
        )
    ),
    voidageMin_(readVoidageMin(dict_)),
    volumeFraction_(volumeFractionModel::New(mesh, dict_)),
    smoother_(mesh, dict_),
    localGasTemperature_(readLocalGasTemperature(dict_))
{}
