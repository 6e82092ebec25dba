// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "demEngine.H"
#include "profiling.H"
#include <utility>
#include "keywordSource.H"
#include "keywordRange.H"

Foam::demEngine::demEngine
(
    const dictionary& dict,
    const dictionary& materials,
    const scalar coarseGrainFactor
)
:
    materials_(materials),
    slots_(),
    durationSlot_(slots_.addScalar("duration", "demEngine", false)),
    law_(contactLaw::New(dict, materials_, coarseGrainFactor, slots_)),
    cohesion_(cohesionModel::New(dict, law_(), coarseGrainFactor, slots_)),
    kernel_(contactKernel::New(law_(), cohesion_(), durationSlot_)),
    conduction_
    (
        dict, materials_, law_->thermalOverlapExponent(), coarseGrainFactor
    ),
    time_(0),
    skinFraction_
    (
        keywordRange::aboveOrDefault<scalar>
        (
            dict, "skin", 0.1, 0, false,
            "the neighbour lists' skin, a fraction of the largest diameter"
        )
    ),
    skin_(0),
    nLocal_(0),
    listsValid_(false),
    rebuildRequested_(false),
    lastPairs_(0),
    lastWalls_(0),
    nBuildsBy_(Zero),
    spatialSort_(false),
    movedValid_(false),
    recordIndexValid_(false)
{
    pairs_.setLayout(law_->nCoeffs(), slots_.stride(), false);
    wallContacts_.setLayout(law_->nWallCoeffs(), slots_.stride(), true);
}


Foam::demParticles& Foam::demEngine::resetParticles()
{
    particles_.clear();
    nLocal_ = -1;
    clearPending();
    clearLists();
    pairs_.clearStates();
    wallContacts_.clearStates();
    return particles_;
}


void Foam::demEngine::setWalls(const demWalls& walls)
{
    for (const label m : walls.materials())
    {
        if (m < 0 || m >= materials_.nWalls())
        {
            FatalErrorInFunction
                << "Wall material " << m << " of a wall face: there are "
                << materials_.nWalls() << " wall materials "
                << materials_.wallNames() << exit(FatalError);
        }
    }
    keepStates();
    walls_ = walls;
    listsValid_ = false;
}


void Foam::demEngine::setHalo(autoPtr<demHalo>&& halo)
{
    keepStates();
    halo_ = std::move(halo);
    listsValid_ = false;
}


Foam::scalar Foam::demEngine::maxRadius() const
{
    scalar rMax = 0;
    const label nL = nLocal();
    for (label i = 0; i < nL; ++i)
    {
        rMax = max(rMax, particles_.radius[i]);
    }
    if (halo_.valid())
    {
        reduce(rMax, maxOp<scalar>());
    }
    return rMax;
}


void Foam::demEngine::checkWallTemperature() const
{
    if
    (
        conduction_.active()
     && walls_.size()
     && walls_.temperature().size() != walls_.size()
    )
    {
        FatalErrorInFunction
            << "The contact conduction takes wall contacts at the wall"
               " faces' temperature, but the wall faces have none"
            << exit(FatalError);
    }
    if
    (
        cohesion_->needsWallTemperature()
     && walls_.size()
     && walls_.temperature().size() != walls_.size()
    )
    {
        FatalErrorInFunction
            << "cohesionModel " << cohesion_->type() << " takes wall contacts"
               " at the wall faces' temperature (wallTemperature wall), but"
               " the wall faces have none (the solver sets it from the gas"
               " temperature field T); use wallTemperature particle"
            << exit(FatalError);
    }
}


void Foam::demEngine::computeForces(const scalar deltaT)
{
    demParticles& P = particles_;
    vector* __restrict__ F = P.force.data();
    vector* __restrict__ M = P.torque.data();
    const label n = P.size();
    for (label i = 0; i < n; ++i)
    {
        F[i] = Zero;
        M[i] = Zero;
    }

    sizeWallAccumulators();
    kernel_->pairs(P, pairs_, deltaT, time_);
    walls_.update(P, wallContacts_, conduction_.needsGasConductivity());
    kernel_->walls
    (
        P, wallContacts_, walls_, deltaT, time_, wallFaceImpulse_.data()
    );
}


template<bool Drift, bool TwoKicks>
bool Foam::demEngine::integrate(const scalar deltaT)
{
    demParticles& P = particles_;
    const label nL = nLocal();
    const scalar h = 0.5*deltaT;

    vector* __restrict__ x = P.position.data();
    vector* __restrict__ v = P.velocity.data();
    vector* __restrict__ w = P.angularVelocity.data();
    vector* __restrict__ Jd = P.dragImpulse.data();
    vector* __restrict__ F = P.force.data();
    vector* __restrict__ M = P.torque.data();
    const vector* __restrict__ Fext = P.externalForce.cdata();
    const vector* __restrict__ Uf = P.fluidVelocity.cdata();
    const scalar* __restrict__ beta = P.dragCoeff.cdata();
    const scalar* __restrict__ invM = P.invMass.cdata();
    const scalar* __restrict__ invI = P.invInertia.cdata();
    const vector* __restrict__ x0 = builtAt_.cdata();
    const bool track = builtAt_.size() == nL;

    scalar moved2 = 0;
    for (label i = 0; i < nL; ++i)
    {
        // v <- (v + h/m (F + F_ext + beta U_f))/(1 + h beta/m), once or
        // twice with the same forces (the closing half of one step and
        // the opening half of the next)
        const scalar hm = h*invM[i];
        const scalar damp = 1/(1 + hm*beta[i]);
        const vector push = hm*(F[i] + Fext[i] + beta[i]*Uf[i]);
        const scalar hb = h*beta[i];

        vector vi = (v[i] + push)*damp;
        vector J = hb*(Uf[i] - vi);
        vector wi = w[i] + (h*invI[i])*M[i];
        if (TwoKicks)
        {
            vi = (vi + push)*damp;
            J += hb*(Uf[i] - vi);
            wi += (h*invI[i])*M[i];
        }
        v[i] = vi;
        w[i] = wi;
        Jd[i] += J;

        if (Drift)
        {
            x[i] += deltaT*vi;
            F[i] = Zero;
            M[i] = Zero;
            if (track)
            {
                moved2 = max(moved2, magSqr(x[i] - x0[i]));
            }
        }
    }

    return !track || moved2 > sqr(0.5*skin_);
}


const char* Foam::demEngine::name(const buildCause c)
{
    static const char* names[nBuildCauses] =
        {"start", "requested", "particles changed", "skin"};
    return names[static_cast<int>(c)];
}


void Foam::demEngine::beginStep()
{
    if (nLocal_ < 0)
    {
        nLocal_ = particles_.size();
    }
    movedValid_ = false;
    checkWallTemperature();
    recordIndexValid_ = false;

    // Why the lists are built again, on any processor: a bit per cause,
    // the lowest set bit the cause counted
    auto bit = [](const buildCause c) { return label(1) << int(c); };
    label why =
        rebuildRequested_ ? bit(buildCause::requested)
      : listsChanged() ? bit(buildCause::changed)
      : listsExpired() ? bit(buildCause::skin)
      : 0;
    if (why && nBuilds() == 0)
    {
        why = bit(buildCause::start);
    }
    if (halo_.valid())
    {
        reduce(why, bitOrOp<label>());
    }
    if (why)
    {
        int c = 0;
        while (!(why & (label(1) << c)))
        {
            ++c;
        }
        addProfiling(lists, "demEngine::lists");
        keepStates();
        rebuild(buildCause(c));
    }
    else if (halo_.valid())
    {
        addProfiling(ghosts, "demEngine::ghosts");
        halo_->update(particles_, nLocal_, true);
    }
    rebuildRequested_ = false;
    wallFaceHeat_ = 0;
    wallFaceImpulse_ = Zero;

    vector* __restrict__ Jd = particles_.dragImpulse.data();
    for (label i = 0; i < nLocal_; ++i)
    {
        Jd[i] = Zero;
    }
}


void Foam::demEngine::sizeWallAccumulators()
{
    if (wallFaceHeat_.size() != walls_.size())
    {
        wallFaceHeat_.setSize(walls_.size(), scalar(0));
    }
    if (wallFaceImpulse_.size() != walls_.size())
    {
        wallFaceImpulse_.setSize(walls_.size(), Zero);
    }
}


void Foam::demEngine::initialise()
{
    if (nLocal_ < 0)
    {
        nLocal_ = particles_.size();
    }
    checkWallTemperature();
    keepStates();
    rebuild(nBuilds() == 0 ? buildCause::start : buildCause::changed);
    computeForces(0);
}


void Foam::demEngine::advance(const scalar deltaT, const label nSteps)
{
    bool cold = nLocal_ < 0 || !listsValid_;
    if (halo_.valid())
    {
        reduce(cold, orOp<bool>());
    }
    if (cold)
    {
        initialise();
    }

    demParticles& P = particles_;
    const label nL = nLocal();
    sizeWallAccumulators();

    for (label s = 0; s < nSteps; ++s)
    {
        // Kick(s) with the last forces, drift, forces cleared; whether a
        // particle moved more than half the skin since the last build
        addProfiling(integrateStep, "demEngine::integrate");
        bool expired =
            s == 0
          ? integrate<true, false>(deltaT)
          : integrate<true, true>(deltaT);
        endProfiling(integrateStep);

        vector* __restrict__ F = P.force.data();
        vector* __restrict__ M = P.torque.data();
        for (label i = nL; i < P.size(); ++i)
        {
            F[i] = Zero;
            M[i] = Zero;
        }

        if (halo_.valid())
        {
            // Ghosts at the new positions (and temperatures, with
            // conduction), then a rebuild everywhere if any processor needs
            // one (the ghosts are chosen again with it)
            addProfiling(ghosts, "demEngine::ghosts");
            halo_->update(P, nL, conduction_.active());
            endProfiling(ghosts);
            // Where the processors wait for each other (load imbalance)
            addProfiling(wait, "demEngine::wait");
            reduce(expired, orOp<bool>());
        }
        if (expired)
        {
            addProfiling(lists, "demEngine::lists");
            {
                addProfiling(keep, "demEngine::lists::keepStates");
                keepStates();
            }
            rebuild(buildCause::skin);
        }

        time_ += deltaT;
        {
            addProfiling(pairLoop, "demEngine::pairs");
            kernel_->pairs(P, pairs_, deltaT, time_);
        }
        {
            addProfiling(wallLoop, "demEngine::walls");
            walls_.update(P, wallContacts_, conduction_.needsGasConductivity());
            kernel_->walls
            (
                P, wallContacts_, walls_, deltaT, time_,
                wallFaceImpulse_.data()
            );
        }

        if (conduction_.active())
        {
            addProfiling(conductionStep, "demEngine::conduction");
            heatFlow_.resize(P.size());
            heatFlow_ = 0;
            scalar* __restrict__ Q = heatFlow_.data();
            conduction_.pairs(P, pairs_, Q);
            conduction_.walls
            (
                P, wallContacts_, walls_, Q, deltaT, wallFaceHeat_.data()
            );
            conduction_.heat(P, nL, Q, deltaT);
        }
    }

    // The closing half-kick; the forces stay for the next opening one
    if (nSteps > 0)
    {
        integrate<false, false>(deltaT);
    }
    recordIndexValid_ = false;
}


Foam::label Foam::demEngine::nPairContacts() const
{
    const demParticles& P = particles_;
    const label nL = nLocal();
    const label dur = durationSlot_;
    label count = 0;
    for (label k = 0; k < pairs_.size(); ++k)
    {
        const label i = pairs_.first[k];
        const label j = pairs_.second[k];
        if
        (
            pairs_.stateOf(k)[dur] > 0
         && (j < nL || P.identity[i] < P.identity[j])
        )
        {
            ++count;
        }
    }
    return count;
}


Foam::label Foam::demEngine::nWallContacts() const
{
    label count = 0;
    for (label k = 0; k < wallContacts_.size(); ++k)
    {
        if (wallContacts_.stateOf(k)[durationSlot_] > 0)
        {
            ++count;
        }
    }
    return count;
}


Foam::label Foam::demEngine::nBridgedContacts() const
{
    const label b = cohesion_->bridgeSlot();
    if (b < 0)
    {
        return 0;
    }
    const demParticles& P = particles_;
    const label nL = nLocal();
    const label dur = durationSlot_;
    label count = 0;
    for (label k = 0; k < pairs_.size(); ++k)
    {
        const scalar* s = pairs_.stateOf(k);
        const label i = pairs_.first[k];
        const label j = pairs_.second[k];
        if
        (
            s[dur] > 0 && s[b] > 0
         && (j < nL || P.identity[i] < P.identity[j])
        )
        {
            ++count;
        }
    }
    for (label k = 0; k < wallContacts_.size(); ++k)
    {
        const scalar* s = wallContacts_.stateOf(k);
        if (s[dur] > 0 && s[b] > 0)
        {
            ++count;
        }
    }
    return count;
}


Foam::contactGraphComponents Foam::demEngine::agglomerates
(
    const scalar minDuration,
    const bool bridgedOnly
) const
{
    if (!listsValid_)
    {
        FatalErrorInFunction
            << "The contact lists are not valid: agglomerates are taken"
            << " after a step" << abort(FatalError);
    }
    const label b = cohesion_->bridgeSlot();
    if (bridgedOnly && b < 0)
    {
        FatalErrorInFunction
            << "Bridged agglomerates need a cohesion model with bridges,"
            << " not " << cohesion_->type() << exit(FatalError);
    }

    const label dur = durationSlot_;
    DynamicList<label> first(pairs_.size()/2);
    DynamicList<label> second(pairs_.size()/2);
    for (label k = 0; k < pairs_.size(); ++k)
    {
        const scalar* s = pairs_.stateOf(k);
        if
        (
            s[dur] > 0 && s[dur] >= minDuration
         && (!bridgedOnly || s[b] > 0)
        )
        {
            first.append(pairs_.first[k]);
            second.append(pairs_.second[k]);
        }
    }

    const label nL = nLocal();
    boolList shared;
    if (halo_.valid())
    {
        shared.setSize(nL, false);
        halo_->markSent(shared);
    }
    return contactGraphComponents
    (
        particles_.identity, nL, first, second, shared
    );
}
