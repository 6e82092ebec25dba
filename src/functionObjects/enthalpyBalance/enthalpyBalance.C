// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "enthalpyBalance.H"
#include "gasConduction.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "addToRunTimeSelectionTable.H"
#include "findSinterCloud.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(enthalpyBalance, 0);
    addToRunTimeSelectionTable(functionObject, enthalpyBalance, dictionary);
}
}


Foam::functionObjects::enthalpyBalance::enthalpyBalance
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    Hout_(0),
    Hwall_(0),
    timeIndex_(-1),
    haveInitial_(false),
    Hp0_(0),
    Hg0_(0)
{
    read(dict);

    // Carried over from the run this one restarts
    Hout_ = getProperty<scalar>("Hout", 0);
    Hwall_ = getProperty<scalar>("Hwall", 0);
    haveInitial_ = getProperty<bool>("haveInitial", false);
    Hp0_ = getProperty<scalar>("Hp0", 0);
    Hg0_ = getProperty<scalar>("Hg0", 0);

    if (Pstream::master() && writeToFile())
    {
        writeHeader(file(), "Sensible enthalpy balance [J]");
        writeCommented(file(), "Time");
        writeTabbed(file(), "H_p");
        writeTabbed(file(), "H_g");
        writeTabbed(file(), "H_out");
        writeTabbed(file(), "imbalance");
        writeTabbed(file(), "H_wall");
        writeTabbed(file(), "T_p_mean");
        file() << endl;
    }
}


bool Foam::functionObjects::enthalpyBalance::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    cloudName_ = dict.lookupOrDefault<word>("cloud", "cloud");
    voidageName_ = dict.lookupOrDefault<word>("voidage", "voidage");
    hName_ = dict.lookupOrDefault<word>("h", "h");
    rhoName_ = dict.lookupOrDefault<word>("rho", "rho");
    phiName_ = dict.lookupOrDefault<word>("phi", "phi");
    alphaEffName_ = dict.lookupOrDefault<word>("alphaEff", "alphaEff");

    return true;
}


Foam::scalar Foam::functionObjects::enthalpyBalance::gasEnthalpy() const
{
    const volScalarField& eps = lookupObject<volScalarField>(voidageName_);
    const volScalarField& rho = lookupObject<volScalarField>(rhoName_);
    const volScalarField& h = lookupObject<volScalarField>(hName_);

    return gSum(eps.primitiveField()*rho.primitiveField()*h.primitiveField()
        *mesh_.V().field());
}


Foam::scalar Foam::functionObjects::enthalpyBalance::particleEnthalpy
(
    scalar& meanT
) const
{
    scalar H = 0;
    scalar mass = 0;
    scalar mT = 0;
    if (const basicSinterCloud* cloudPtr = findSinterCloud(mesh_, cloudName_))
    {
        const basicSinterCloud& cloud = *cloudPtr;
        const scalar Cp = cloud.constProps().Cp0();
        for (const auto& p : cloud)
        {
            const scalar m = p.nParticle()*cloud.mass(p);
            const scalar T = cloud.temperature(p);
            H += m*Cp*T;
            mass += m;
            mT += m*T;
        }
    }
    reduce(mass, sumOp<scalar>());
    reduce(mT, sumOp<scalar>());
    meanT = mass > 0 ? mT/mass : scalar(0);
    return returnReduce(H, sumOp<scalar>());
}


Foam::scalar Foam::functionObjects::enthalpyBalance::outflowRate() const
{
    const surfaceScalarField& phi = lookupObject<surfaceScalarField>(phiName_);
    const volScalarField& h = lookupObject<volScalarField>(hName_);

    const volScalarField* alphaEffPtr =
        mesh_.cfindObject<volScalarField>(alphaEffName_);

    scalar rate = 0;
    forAll(phi.boundaryField(), patchi)
    {
        const fvPatchScalarField& hp = h.boundaryField()[patchi];
        if (hp.coupled())
        {
            continue;
        }

        // Convected out
        rate += sum(phi.boundaryField()[patchi]*hp);

        // Conducted out
        if (alphaEffPtr)
        {
            rate -= gasConductionIn(*alphaEffPtr, h, patchi);
        }
    }
    return returnReduce(rate, sumOp<scalar>());
}


bool Foam::functionObjects::enthalpyBalance::execute()
{
    const Time& time = mesh_.time();
    if (time.timeIndex() != timeIndex_)
    {
        timeIndex_ = time.timeIndex();

        // Face fluxes of the step that just ended, counted from the step
        // after the one that set the initial totals
        if (haveInitial_)
        {
            Hout_ += outflowRate()*time.deltaTValue();
            if
            (
                const basicSinterCloud* cloudPtr =
                    findSinterCloud(mesh_, cloudName_)
            )
            {
                Hwall_ +=
                    returnReduce(cloudPtr->conductedWallHeat(), sumOp<scalar>());
            }
        }
    }
    return true;
}


bool Foam::functionObjects::enthalpyBalance::write()
{
    scalar meanTp = 0;
    const scalar Hp = particleEnthalpy(meanTp);
    const scalar Hg = gasEnthalpy();
    if (!haveInitial_)
    {
        haveInitial_ = true;
        Hp0_ = Hp;
        Hg0_ = Hg;
    }

    setProperty("Hout", Hout_);
    setProperty("Hwall", Hwall_);
    setProperty("haveInitial", haveInitial_);
    setProperty("Hp0", Hp0_);
    setProperty("Hg0", Hg0_);

    if (Pstream::master() && writeToFile())
    {
        file()
            << mesh_.time().timeName() << tab << Hp << tab << Hg << tab
            << Hout_ << tab << (Hp - Hp0_) + (Hg - Hg0_) + Hout_ - Hwall_
            << tab << Hwall_ << tab << meanTp << endl;
    }
    return true;
}
