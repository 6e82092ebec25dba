// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "DEMCollision.H"
#include "fixedValueFvPatchFields.H"
#include "demHalo.H"
#include "coarseGrainFactor.H"
#include "wallPolyPatch.H"
#include "volFields.H"
#include "IOdictionary.H"
#include "knownKeywords.H"
#include "keywordSource.H"
#include "keywordRange.H"

template<class CloudType>
Foam::labelList Foam::DEMCollision<CloudType>::wallPatchIds() const
{
    const polyBoundaryMesh& patches = owner_.mesh().boundaryMesh();
    const dictionary& dict = coeffs_;

    labelHashSet ids;
    if (dict.found("walls"))
    {
        const wordRes names(dict.get<wordRes>("walls"));
        ids = patches.patchSet(names);
        if (ids.empty())
        {
            FatalIOErrorInKeyword(dict, "walls")
                << "Keyword walls in " << dict.name() << " matches no patch."
                << " Valid patches are " << patches.names()
                << exit(FatalIOError);
        }
    }
    else
    {
        forAll(patches, patchi)
        {
            if (isA<wallPolyPatch>(patches[patchi]))
            {
                ids.insert(patchi);
            }
        }
    }
    return ids.sortedToc();
}


template<class CloudType>
Foam::demWalls Foam::DEMCollision<CloudType>::meshWalls() const
{
    const polyMesh& mesh = owner_.mesh();
    const polyBoundaryMesh& patches = mesh.boundaryMesh();

    DynamicList<face> faces;
    DynamicList<label> material;
    for (const label patchi : wallPatches_)
    {
        const polyPatch& pp = patches[patchi];
        const label m = engine_.materials().wallMaterial(pp.name());
        forAll(pp, i)
        {
            faces.append(pp[i]);
            material.append(m);
        }
    }

    return demWalls(mesh.points(), faceList(std::move(faces)), material);
}


template<class CloudType>
const Foam::dictionary& Foam::DEMCollision<CloudType>::coeffDict
(
    const dictionary& subModels
)
{
    const word typeName(modelName());
    const word model(subModels.get<word>("collisionModel"));
    if (model != typeName)
    {
        FatalIOErrorInKeyword(subModels, "collisionModel")
            << "Unknown collisionModel type " << model << " in "
            << subModels.name() << nl << nl
            << "Valid collisionModel types are" << nl
            << "1(" << typeName << ")" << nl
            << exit(FatalIOError);
    }
    return subModels.subDict(typeName + "Coeffs");
}


template<class CloudType>
Foam::DEMCollision<CloudType>::DEMCollision
(
    const dictionary& subModels,
    CloudType& owner
)
:
    owner_(owner),
    coeffs_(coeffDict(subModels)),
    engine_
    (
        coeffs_,
        contactMaterials::read(owner.mesh()),
        coarseGrainFactor(owner.constProps().dict())
    ),
    deltaT_(coeffs_.lookupOrDefault<scalar>("deltaT", 0)),
    fraction_(coeffs_.lookupOrDefault<scalar>("collisionTimeFraction", 0)),
    impactVelocity_(coeffs_.lookupOrDefault<scalar>("impactVelocity", 1)),
    domainExtent_(cmptMin(boundBox(owner.mesh().points(), true).span())),
    warnedFast_(false),
    warnedPlaced_(false)
{
    const dictionary& coeffs = coeffs_;
    // The coefficients of any law or cohesion model may stay while
    // another is selected
    DynamicList<word> valid
    {
        "contactLaw", "particleParticle", "particleWall", "walls", "deltaT",
        "collisionTimeFraction", "impactVelocity", "skin", "cohesionModel",
        "conduction"
    };
    for (const word& law : contactLaw::dictionaryConstructorTablePtr_->toc())
    {
        valid.append(law + "Coeffs");
    }
    for
    (
        const word& model : cohesionModel::dictionaryConstructorTablePtr_->toc()
    )
    {
        valid.append(model + "Coeffs");
    }
    knownKeywords::check(coeffs, valid);
    const bool hasStep = coeffs.found("deltaT");
    const bool hasFraction = coeffs.found("collisionTimeFraction");

    if (hasStep == hasFraction)
    {
        FatalIOErrorInFunction(coeffs)
            << "Give exactly one of deltaT [s] and collisionTimeFraction"
            << " in " << coeffs.name()
            << exit(FatalIOError);
    }
    if (hasStep)
    {
        keywordRange::check
        (
            coeffs, "deltaT", deltaT_, 0, GREAT, "the DEM step [s]", true
        );
    }
    if (hasFraction)
    {
        keywordRange::check
        (
            coeffs, "collisionTimeFraction", fraction_, 0,
            maxCollisionTimeFraction,
            "the DEM step as a fraction of the collision time t_c", true
        );
    }
    keywordRange::check
    (
        coeffs, "impactVelocity", impactVelocity_, 0.01, 100,
        "the approach speed [m/s] of the collision time t_c that sets the"
        " DEM step: a tiny one lengthens t_c (as v^-1/5 for Hertz) and so"
        " the step"
    );

    // The cloud's density and heat capacity are the particles' material's
    const dictionary& constProps = owner.constProps().dict();
    const contactMaterials& materials = engine_.materials();
    materials.checkSame
    (
        constProps, "rho0", constProps.get<scalar>("rho0"), "density"
    );
    if (constProps.found("Cp0"))
    {
        materials.checkHeatCapacity
        (
            constProps, "Cp0", constProps.get<scalar>("Cp0")
        );
    }

    // Temperatures are kelvin: below 200 K was given in C (the cloud
    // would clamp it to its TMin without a word)
    if (constProps.found("T0"))
    {
        const scalar T0 = constProps.get<scalar>("T0");
        if (!(T0 >= 200))
        {
            FatalIOErrorInKeyword(constProps, "T0")
                << "Keyword T0 = " << T0 << " K in " << constProps.name()
                << " is below 200 K: temperatures are in kelvin"
                << exit(FatalIOError);
        }
        if (engine_.cohesion().active())
        {
            engine_.cohesion().checkTemperature(T0);
        }
    }

    if (Pstream::parRun())
    {
        engine_.setHalo
        (
            autoPtr<demHalo>::New(boundBox(owner.mesh().points(), false))
        );
    }

    wallPatches_ = wallPatchIds();
    engine_.setWalls(meshWalls());

    // The parcels follow the engine's particles wherever it sorts them
    engine_.setSpatialSort(true);

    adiabaticWall_.setSize(wallPatches_.size(), false);
    if (engine_.conduction().active())
    {
        const fvMesh& mesh = owner.mesh();
        const dictionary& conductionDict = coeffs_.subDict("conduction");
        const wordRes adiabatic
        (
            conductionDict.lookupOrDefault<wordRes>("adiabaticWalls", wordRes())
        );
        wordList wallNames(wallPatches_.size());
        forAll(wallPatches_, i)
        {
            wallNames[i] = mesh.boundaryMesh()[wallPatches_[i]].name();
            adiabaticWall_[i] = adiabatic.match(wallNames[i]);
        }

        // Each entry names a DEM wall patch (a typo would leave a wall
        // conducting without a word)
        for (const wordRe& entry : adiabatic)
        {
            bool found = false;
            for (const word& name : wallNames)
            {
                found = found || entry.match(name);
            }
            if (!found)
            {
                FatalIOErrorInKeyword(conductionDict, "adiabaticWalls")
                    << "adiabaticWalls entry " << entry << " in "
                    << conductionDict.name() << " matches no DEM wall patch."
                    << " Valid patches are " << wallNames
                    << exit(FatalIOError);
            }
        }

        const volScalarField* T = mesh.findObject<volScalarField>("T");
        Info<< "    contact conduction to the wall patches of fixed"
               " temperature:";
        forAll(wallPatches_, i)
        {
            const label patchi = wallPatches_[i];
            if
            (
                T
             && !adiabaticWall_[i]
             && isA<fixedValueFvPatchScalarField>(T->boundaryField()[patchi])
            )
            {
                Info<< ' ' << mesh.boundaryMesh()[patchi].name();
            }
        }
        Info<< " (the others are adiabatic)" << endl;

        // The thermal wall condition lumps the particle-wall conduction
        // into the gas's wall flux (thesis §4.2.2)
        for (const label patchi : wallPatches_)
        {
            if
            (
                T
             && T->boundaryField()[patchi].type() == "bedWallTemperature"
            )
            {
                Info<< "    particle-wall conduction off on "
                    << mesh.boundaryMesh()[patchi].name()
                    << ": its thermal wall condition (bedWallTemperature)"
                       " takes the bed-to-wall heat" << endl;
            }
        }
    }
}


template<class CloudType>
void Foam::DEMCollision<CloudType>::setWallTemperature()
{
    const fvMesh& mesh = owner_.mesh();
    const volScalarField* T = mesh.findObject<volScalarField>("T");
    if (!T)
    {
        return;
    }

    // The faces' temperature; a face conducts heat (a reservoir) where the
    // gas temperature's condition is a fixed value, not at an adiabatic or
    // mixed one (an outlet's inletOutlet, the thermal wall condition)
    scalarField Tw(engine_.walls().size());
    boolList conducting(Tw.size());
    label n = 0;
    forAll(wallPatches_, i)
    {
        const fvPatchScalarField& Tp = T->boundaryField()[wallPatches_[i]];
        const bool fixed =
            !adiabaticWall_[i] && isA<fixedValueFvPatchScalarField>(Tp);
        for (const scalar t : Tp)
        {
            conducting[n] = fixed;
            Tw[n++] = t;
        }
    }
    engine_.setWallTemperature(Tw);
    engine_.setWallConducting(conducting);
}


template<class CloudType>
Foam::label Foam::DEMCollision<CloudType>::nSubSteps(const scalar dt) const
{
    const demParticles& P = engine_.particles();

    // The smallest parcel has the shortest contact; the largest must fit
    // the domain; the fastest could approach at twice its speed
    scalar rMin = GREAT;
    scalar mMin = GREAT;
    scalar rMax = 0;
    scalar U2Max = 0;
    for (label i = 0; i < engine_.nLocal(); ++i)
    {
        rMin = min(rMin, P.radius[i]);
        mMin = min(mMin, P.mass(i));
        rMax = max(rMax, P.radius[i]);
        U2Max = max(U2Max, magSqr(P.velocity[i]));
    }
    reduce(rMin, minOp<scalar>());
    reduce(mMin, minOp<scalar>());
    reduce(rMax, maxOp<scalar>());
    reduce(U2Max, maxOp<scalar>());

    if (rMin == GREAT)
    {
        return 1;
    }

    if (2*rMax > domainExtent_)
    {
        FatalErrorInFunction
            << "A parcel of diameter " << 2*rMax << " m is wider than the"
            << " domain's smallest extent " << domainExtent_ << " m" << nl
            << "Check the sizes of the injection models in constant/"
            << "cloudProperties (subModels/injectionModels/.../"
            << "sizeDistribution, in metres) and the coarseGrainFactor"
            << " of constantProperties (the parcel is K times the primary"
            << " particle)" << exit(FatalError);
    }

    if (!warnedFast_ && 2*sqrt(U2Max) > impactVelocity_)
    {
        warnedFast_ = true;
        WarningInFunction
            << "Parcels move at up to " << sqrt(U2Max) << " m/s: two could"
            << " approach faster than impactVelocity " << impactVelocity_
            << " m/s of " << coeffs_.name() << ", and their contact is"
            << " shorter than the t_c that sets the DEM step (told once)"
            << endl;
    }

    const scalar tc = engine_.law().collisionTime(rMin, mMin, impactVelocity_);
    const scalar step = deltaT_ > 0 ? deltaT_ : fraction_*tc;

    if (step > maxCollisionTimeFraction*tc*(1 + 1e-12))
    {
        FatalIOErrorInKeyword(coeffs_, "deltaT")
            << "Keyword deltaT " << step << " s in "
            << coeffs_.name() << " is larger than "
            << maxCollisionTimeFraction << " of the collision time "
            << tc << " s of the smallest parcel (radius " << rMin
            << " m, mass " << mMin << " kg) at impactVelocity "
            << impactVelocity_ << " m/s"
            << exit(FatalIOError);
    }

    return max(label(1), label(std::ceil(dt/step*(1 - 1e-12))));
}


template<class CloudType>
void Foam::DEMCollision<CloudType>::collide(const scalar dt)
{
    if (engine_.cohesion().active() || engine_.conduction().active())
    {
        setWallTemperature();
    }

    const label nSub = nSubSteps(dt);
    const scalar dtDEM = dt/nSub;

    engine_.setTime(owner_.db().time().value() - dt);
    // The list builds by cause before this step
    typedef demEngine::buildCause cause;
    FixedList<label, demEngine::nBuildCauses> causes0;
    forAll(causes0, k)
    {
        causes0[k] = engine_.nBuilds(cause(k));
    }
    engine_.resetPlacedOverlaps();
    engine_.beginStep();
    engine_.advance(dtDEM, nSub);
    // Contacts of particles placed into each other (the deepest is
    // gathered only when there are some: nPlaced is the same on all ranks)
    const label nPlaced =
        returnReduce(engine_.nPlacedOverlaps(), sumOp<label>());
    scalar deepestPercent = 0;
    if (nPlaced)
    {
        deepestPercent = 0.1*std::round
        (
            1000*returnReduce(engine_.deepestPlacedOverlap(), maxOp<scalar>())
        );
    }
    if (nPlaced && !warnedPlaced_)
    {
        warnedPlaced_ = true;
        WarningInFunction
            << nPlaced << " contacts began with particles placed into each"
            << " other (or into a wall), up to "
            << deepestPercent << " % of the smaller radius: their springs"
            << " push them apart at high speed. Inject parcels apart"
            << " (positions, a slower pour) or start from a settled bed."
            << " The DEM lines of the log count such contacts (told once)"
            << endl;
    }

    Info<< "    DEM: " << nSub << " sub-steps of " << dtDEM << " s, "
        << returnReduce(engine_.nPairContacts(), sumOp<label>())
        << " particle-particle and "
        << returnReduce(engine_.nWallContacts(), sumOp<label>())
        << " particle-wall contacts";
    if (engine_.cohesion().active())
    {
        Info<< ", "
            << returnReduce(engine_.nBridgedContacts(), sumOp<label>())
            << " bridged";
    }
    {
        // The list builds of this step, and why
        label built = 0;
        forAll(causes0, k)
        {
            causes0[k] = engine_.nBuilds(cause(k)) - causes0[k];
            built += causes0[k];
        }
        Info<< "; lists built " << built << " times";
        const char* sep = " (";
        forAll(causes0, k)
        {
            if (causes0[k])
            {
                Info<< sep << demEngine::name(cause(k)) << ' ' << causes0[k];
                sep = ", ";
            }
        }
        if (built)
        {
            Info<< ')';
        }
    }
    if (Pstream::parRun())
    {
        Info<< "; " << returnReduce(engine_.nGhosts(), sumOp<label>())
            << " ghosts";
    }
    if (nPlaced)
    {
        Info<< "; " << nPlaced << " began placed into each other (deepest "
            << deepestPercent << " % of the radius)";
    }
    Info<< endl;
}


template<class CloudType>
Foam::labelRange Foam::DEMCollision<CloudType>::wallFaces
(
    const label patchi
) const
{
    // The engine's wall faces are the patches' faces in wallPatches_ order
    const polyBoundaryMesh& patches = owner_.mesh().boundaryMesh();
    label start = 0;
    for (const label wallPatchi : wallPatches_)
    {
        const label n = patches[wallPatchi].size();
        if (wallPatchi == patchi)
        {
            return labelRange(start, n);
        }
        start += n;
    }
    return labelRange(start, 0);
}


template<class CloudType>
Foam::scalar Foam::DEMCollision<CloudType>::conductedWallHeat
(
    const label patchi
) const
{
    const scalarList& faceHeat = engine_.wallFaceHeat();
    scalar heat = 0;
    if (faceHeat.size())
    {
        for (const label f : wallFaces(patchi))
        {
            heat += faceHeat[f];
        }
    }
    return heat;
}


template<class CloudType>
Foam::vector Foam::DEMCollision<CloudType>::wallImpulse
(
    const label patchi
) const
{
    const List<vector>& faceImpulse = engine_.wallFaceImpulse();
    vector impulse(Zero);
    if (faceImpulse.size())
    {
        for (const label f : wallFaces(patchi))
        {
            impulse += faceImpulse[f];
        }
    }
    return impulse;
}

template<class CloudType>
void Foam::DEMCollision<CloudType>::syncParticles()
{
    const demParticles& P = engine_.particles();
    const label nLocal = engine_.nLocal();

    // The same particles (in any order: the engine may sort them): each
    // parcel's index is a local particle of its identity, and identities
    // are unique
    bool same = owner_.size() == nLocal;
    if (same)
    {
        for (const parcelType& p : owner_)
        {
            const label k = p.demIndex();
            if (k < 0 || k >= nLocal || P.identity[k] != p.identity())
            {
                same = false;
                break;
            }
        }
    }
    if (same)
    {
        return;
    }

    // Where each parcel was in the engine, or -1 (new, arrived, read)
    labelList order(owner_.size());
    label n = 0;
    for (const parcelType& p : owner_)
    {
        const label k = p.demIndex();
        order[n++] =
            (k >= 0 && k < nLocal && P.identity[k] == p.identity()) ? k : -1;
    }

    engine_.reorder(order);

    demParticles& Q = engine_.particles();
    n = 0;
    for (parcelType& p : owner_)
    {
        if (order[n] < 0)
        {
            Q.position[n] = p.position();
            Q.velocity[n] = p.U();
            Q.setSphere(n, 0.5*p.d(), p.rho());
            Q.temperature[n] = p.T();
            Q.reductionDegree[n] = p.reductionDegree();
            Q.identity[n] = p.identity();
            if (const demParcelState* st = p.state())
            {
                Q.angularVelocity[n] = st->angularVelocity;
                Q.force[n] = st->contactForce;
                Q.torque[n] = st->contactTorque;
                engine_.addRecords(n, st->contacts);
                p.statePtr().clear();
            }
        }
        p.demIndex() = n;
        ++n;
    }
}


template<class CloudType>
void Foam::DEMCollision<CloudType>::stateOf
(
    const label i,
    demParcelState& state
) const
{
    const demParticles& P = engine_.particles();
    state.angularVelocity = P.angularVelocity[i];
    state.contactForce = P.force[i];
    state.contactTorque = P.torque[i];
    engine_.recordsOf(i, state.contacts);
}
