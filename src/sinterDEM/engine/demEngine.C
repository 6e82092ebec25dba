// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "demEngine.H"

Foam::demEngine::demEngine
(
    const dictionary& dict,
    const scalar coarseGrainFactor
)
:
    law_(contactLaw::New(dict, coarseGrainFactor)),
    skinFraction_(dict.lookupOrDefault<scalar>("skin", 0.1)),
    skin_(0),
    listsValid_(false),
    historyPending_(false),
    nBuilds_(0)
{
    if (!(skinFraction_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword skin in " << dict.name()
            << " must be positive, not " << skinFraction_
            << exit(FatalIOError);
    }
}


void Foam::demEngine::setWalls(const demWalls& walls)
{
    walls_ = walls;
    listsValid_ = false;
}


void Foam::demEngine::restoreHistory
(
    const UList<contactPair>& pairs,
    const UList<wallContactRecord>& walls
)
{
    pairs_ = pairs;
    wallContacts_.clear();
    pendingWall_ = walls;
    historyPending_ = true;
    listsValid_ = false;
}


void Foam::demEngine::buildLists()
{
    const demParticles& P = particles_;
    const label n = P.size();

    scalar rMax = 0;
    forAll(P.radius, i)
    {
        rMax = max(rMax, P.radius[i]);
    }
    skin_ = skinFraction_*2*rMax;

    // Old pair histories, indexed by their first particle
    const bool keep = listsValid_ || historyPending_;
    labelList start(n + 1, 0);
    if (keep)
    {
        for (const contactPair& c : pairs_)
        {
            ++start[c.i + 1];
        }
    }
    for (label i = 0; i < n; ++i)
    {
        start[i + 1] += start[i];
    }
    List<contactPair> old(start[n]);
    {
        labelList fill(SubList<label>(start, n));
        if (keep)
        {
            for (const contactPair& c : pairs_)
            {
                old[fill[c.i]++] = c;
            }
        }
    }

    pairs_.clear();
    bins_.build(P.position, 2*rMax + skin_);
    bins_.pairs(P, skin_, pairs_);

    for (contactPair& c : pairs_)
    {
        for (label k = start[c.i]; k < start[c.i + 1]; ++k)
        {
            if (old[k].j == c.j)
            {
                c.history = old[k].history;
                break;
            }
        }
    }

    // Wall contacts: same, keyed by (particle, face)
    List<wallContact> oldWall;
    if (listsValid_)
    {
        oldWall = wallContacts_;
    }
    labelList wallStart(n + 1, 0);
    for (const wallContact& c : oldWall)
    {
        ++wallStart[c.i + 1];
    }
    for (label i = 0; i < n; ++i)
    {
        wallStart[i + 1] += wallStart[i];
    }

    wallContacts_.clear();
    walls_.candidates(P, skin_, wallContacts_);

    // oldWall is grouped by particle in increasing order already
    for (wallContact& c : wallContacts_)
    {
        for (label k = wallStart[c.i]; k < wallStart[c.i + 1]; ++k)
        {
            if (oldWall[k].face == c.face)
            {
                c.history = oldWall[k].history;
                break;
            }
        }
    }

    // Wall histories given by face centre
    if (historyPending_)
    {
        labelList pendStart(n + 1, 0);
        for (const wallContactRecord& r : pendingWall_)
        {
            ++pendStart[r.i + 1];
        }
        for (label i = 0; i < n; ++i)
        {
            pendStart[i + 1] += pendStart[i];
        }
        List<const wallContactRecord*> pend(pendingWall_.size());
        {
            labelList fill(SubList<label>(pendStart, n));
            for (const wallContactRecord& r : pendingWall_)
            {
                pend[fill[r.i]++] = &r;
            }
        }

        const scalar tol2 = sqr(1e-6*skin_);
        for (wallContact& c : wallContacts_)
        {
            if (pendStart[c.i] == pendStart[c.i + 1])
            {
                continue;
            }
            const point centre = walls_.centre(c.face);
            for (label k = pendStart[c.i]; k < pendStart[c.i + 1]; ++k)
            {
                if (magSqr(pend[k]->faceCentre - centre) < tol2)
                {
                    c.history = pend[k]->history;
                    break;
                }
            }
        }

        pendingWall_.clear();
        historyPending_ = false;
    }

    builtAt_ = P.position;
    listsValid_ = true;
    ++nBuilds_;
}


bool Foam::demEngine::listsExpired() const
{
    if (!listsValid_ || builtAt_.size() != particles_.size())
    {
        return true;
    }
    const scalar limit2 = sqr(0.5*skin_);
    forAll(builtAt_, i)
    {
        if (magSqr(particles_.position[i] - builtAt_[i]) > limit2)
        {
            return true;
        }
    }
    return false;
}


void Foam::demEngine::computeForces(const scalar deltaT)
{
    demParticles& P = particles_;
    forAll(P.force, i)
    {
        P.force[i] = P.externalForce[i];
        P.torque[i] = Zero;
    }

    law_->pairForces(P, pairs_, deltaT);

    walls_.update(P, wallContacts_);
    law_->wallForces(P, wallContacts_, deltaT);
}


void Foam::demEngine::initialise()
{
    buildLists();
    computeForces(0);
}


void Foam::demEngine::step(const scalar deltaT)
{
    if (!listsValid_)
    {
        initialise();
    }

    demParticles& P = particles_;
    const label n = P.size();
    const scalar half = 0.5*deltaT;

    vector* __restrict__ x = P.position.data();
    vector* __restrict__ v = P.velocity.data();
    vector* __restrict__ w = P.angularVelocity.data();
    const vector* __restrict__ F = P.force.cdata();
    const vector* __restrict__ T = P.torque.cdata();
    const scalar* __restrict__ m = P.mass.cdata();
    const scalar* __restrict__ I = P.inertia.cdata();

    for (label i = 0; i < n; ++i)
    {
        v[i] += (half/m[i])*F[i];
        w[i] += (half/I[i])*T[i];
        x[i] += deltaT*v[i];
    }

    if (listsExpired())
    {
        buildLists();
    }

    computeForces(deltaT);

    for (label i = 0; i < n; ++i)
    {
        v[i] += (half/m[i])*P.force[i];
        w[i] += (half/I[i])*P.torque[i];
    }
}


Foam::label Foam::demEngine::nPairContacts() const
{
    label count = 0;
    for (const contactPair& c : pairs_)
    {
        if (c.history.active())
        {
            ++count;
        }
    }
    return count;
}


Foam::label Foam::demEngine::nWallContacts() const
{
    label count = 0;
    for (const wallContact& c : wallContacts_)
    {
        if (c.history.active())
        {
            ++count;
        }
    }
    return count;
}
