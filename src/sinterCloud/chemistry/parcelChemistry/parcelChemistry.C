// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "parcelChemistry.H"
#include "keywordRange.H"
#include "keywordSource.H"
#include "cloudCoupling.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::parcelChemistry::parcelChemistry
(
    const fvMesh& mesh,
    const dictionary& particleProperties,
    const dictionary& constPropsDict,
    const scalar reductionDegree0,
    const contactMaterials& materials
)
:
    constPropsDict_(constPropsDict),
    material_(materials.particleDict()),
    hydrogenMoleFraction_(0),
    hydrogenTransported_(false),
    hydrogenDiffusivity_(0),
    oxygenRemoved_(mesh.nCells(), Zero)
{
    const dictionary& particle = material_;
    if (particle.found("ironContent"))
    {
        path_.reset(new ironOxidePath(particle));
    }
    if (materials.reducedSurfaceDict())
    {
        if (!path_.valid())
        {
            FatalIOErrorInFunction(particle)
                << "The materials name a reducedSurface (the iron on"
                << " reduced particle surfaces), so the particles' material "
                << particle.name() << " needs its ironContent, W0(TFe):"
                << " the surface iron of a particle follows from its"
                << " reduction degree and W0" << exit(FatalIOError);
        }
        surfaceIron_.reset(new surfaceIron(path_(), particle));
        Info<< "    surface iron of the particles from their reduction"
            << " degree: iron content W0 "
            << surfaceIron_->path().ironContent() << ", surface enrichment"
            << " exponent " << surfaceIron_->exponent() << endl;
    }
    else if (particle.found("surfaceIronExponent"))
    {
        WarningInFunction
            << "Keyword surfaceIronExponent of " << particle.name()
            << " is not used: the materials name no reducedSurface (the"
            << " iron of reduced surfaces), so the bridges are the"
            << " particles' material's alone" << endl;
    }
    if (reductionDegree0 > 0)
    {
        // Fatal here, not at the first injection, without ironContent
        reducedPath(reductionDegree0);
    }

    const dictionary* dictPtr = particleProperties.subDictPtr("reduction");
    if (!dictPtr)
    {
        return;
    }
    const dictionary& dict = *dictPtr;
    if (!path_.valid())
    {
        FatalIOErrorInFunction(particle)
            << "The hydrogen reduction (" << dict.name() << ") needs the"
            << " particles' iron content: give ironContent (W0(TFe)) in the"
            << " particles' material " << particle.name()
            << exit(FatalIOError);
    }

    reduction_.reset
    (
        new parcelReduction
        (
            dict,
            path_(),
            wordList({"gas", "hydrogenMoleFraction", "diffusivity"})
        )
    );

    const word gas(dict.get<word>("gas"));
    if (gas == "uniform")
    {
        hydrogenMoleFraction_ = keywordRange::get
        (
            dict, "hydrogenMoleFraction", 0, 1,
            "the hydrogen mole fraction of the gas"
        );
    }
    else if (gas == "transported")
    {
        hydrogenTransported_ = true;
        if (dict.found("hydrogenMoleFraction"))
        {
            FatalIOErrorInKeyword(dict, "hydrogenMoleFraction")
                << "Keyword hydrogenMoleFraction in " << dict.name()
                << " is not read with gas transported: the hydrogen"
                << " fraction comes from the gas's fields Y_H2 and Y_H2O"
                << exit(FatalIOError);
        }
        hydrogenDiffusivity_ = keywordRange::get
        (
            dict, "diffusivity", 0, 1,
            "the diffusivity of H2 and H2O in the gas [m^2/s]", true, true
        );
    }
    else
    {
        FatalIOErrorInKeyword(dict, "gas")
            << "Unknown gas " << gas << " in " << dict.name() << nl
            << "Valid gas compositions are (uniform transported)"
            << exit(FatalIOError);
    }

    Info<< "    hydrogen reduction: " << reduction_->law().type()
        << ", iron content W0 " << reduction_->path().ironContent()
        << ", gas " << gas;
    if (hydrogenTransported_)
    {
        Info<< " (Y_H2, Y_H2O, diffusivity " << hydrogenDiffusivity_
            << " m^2/s)";
    }
    else
    {
        Info<< " with H2 mole fraction " << hydrogenMoleFraction_;
    }
    Info<< ", chemistry acceleration " << reduction_->acceleration() << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::ironOxidePath& Foam::parcelChemistry::reducedPath
(
    const scalar X0
) const
{
    if (!path_.valid())
    {
        FatalIOErrorInFunction(constPropsDict_)
            << "Keyword reductionDegree0 " << X0 << " in "
            << constPropsDict_.name() << " starts the particles"
            << " reduced, which needs their iron content: give ironContent"
            << " (W0(TFe)) in the particles' material "
            << material_.name() << exit(FatalIOError);
    }
    return path_();
}


Foam::tmp<Foam::volScalarField::Internal>
Foam::parcelChemistry::noOxygenSource
(
    const fvMesh& mesh,
    const word& name
)
{
    return tmp<volScalarField::Internal>
    (
        new volScalarField::Internal
        (
            IOobject
            (
                name,
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            mesh,
            dimensionedScalar(dimMoles/dimVolume/dimTime, Zero)
        )
    );
}


Foam::tmp<Foam::volScalarField::Internal> Foam::parcelChemistry::oxygenSource
(
    const fvMesh& mesh,
    const word& name
) const
{
    tmp<volScalarField::Internal> tS(noOxygenSource(mesh, name));
    if (reduction_.valid())
    {
        // Per volume and time, spread over the smoothing length as the heat
        // and momentum sources are (the distribution D of eq 4.7); the
        // smoothing keeps the sum over the cells
        tS.ref().field() =
            cloudCoupling::New(mesh).smoother().smooth<scalar>
            (
                oxygenRemoved_/(mesh.V().field()*mesh.time().deltaTValue()),
                "cloudOxygen"
            );
    }
    return tS;
}
