// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "demEngine.H"

namespace
{

//- Items grouped by their particle i in [0, n): offsets start (n + 1) and
//  the items in that order (counting sort, stable)
template<class Item>
void groupByParticle
(
    const Foam::UList<Item>& items,
    const Foam::label n,
    Foam::labelList& start,
    Foam::List<const Item*>& sorted
)
{
    using namespace Foam;
    start.setSize(n + 1);
    start = 0;
    for (const Item& c : items)
    {
        ++start[c.i + 1];
    }
    for (label i = 0; i < n; ++i)
    {
        start[i + 1] += start[i];
    }
    sorted.setSize(items.size());
    labelList fill(SubList<label>(start, n));
    for (const Item& c : items)
    {
        sorted[fill[c.i]++] = &c;
    }
}


//- Keep the contacts whose particle i is local (i < nLocal), in order
template<class Contact>
void keepLocal(Foam::DynamicList<Contact>& contacts, const Foam::label nLocal)
{
    Foam::label k = 0;
    for (const Contact& c : contacts)
    {
        if (c.i < nLocal)
        {
            contacts[k++] = c;
        }
    }
    contacts.resize(k);
}

} // End anonymous namespace

Foam::demEngine::demEngine
(
    const dictionary& dict,
    const scalar coarseGrainFactor
)
:
    law_(contactLaw::New(dict, coarseGrainFactor)),
    cohesion_(cohesionModel::New(dict, law_(), coarseGrainFactor)),
    time_(0),
    skinFraction_(dict.lookupOrDefault<scalar>("skin", 0.1)),
    skin_(0),
    listsValid_(false),
    nLocal_(-1),
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


void Foam::demEngine::setHalo(autoPtr<demHalo>&& halo)
{
    halo_ = std::move(halo);
    listsValid_ = false;
}


Foam::scalar Foam::demEngine::maxRadius() const
{
    scalar rMax = 0;
    for (const scalar r : particles_.radius)
    {
        rMax = max(rMax, r);
    }
    if (halo_.valid())
    {
        reduce(rMax, maxOp<scalar>());
    }
    return rMax;
}


void Foam::demEngine::exchange()
{
    nLocal_ = particles_.size();
    if (halo_.valid())
    {
        const scalar rMax = maxRadius();
        halo_->select(particles_, nLocal_, 2*rMax*(1 + skinFraction_));
    }
    listsValid_ = false;
}


void Foam::demEngine::restoreHistory
(
    const UList<contactPair>& pairs,
    const UList<wallContactRecord>& walls
)
{
    keptPairs_.clear();
    for (const contactPair& c : pairs)
    {
        keptPairs_.append({c.i, particles_.identity[c.j], c.history});
    }
    keptWalls_.clear();
    pendingWall_ = walls;
    pairs_.clear();
    wallContacts_.clear();
    listsValid_ = false;
}


void Foam::demEngine::keepHistory()
{
    keptPairs_.clear();
    keptWalls_.clear();
    if (!listsValid_)
    {
        return;
    }
    for (const contactPair& c : pairs_)
    {
        if (c.history.active())
        {
            keptPairs_.append({c.i, particles_.identity[c.j], c.history});
        }
    }
    for (const wallContact& c : wallContacts_)
    {
        if (c.history.active())
        {
            keptWalls_.append(c);
        }
    }
}


void Foam::demEngine::buildLists()
{
    const demParticles& P = particles_;
    const label n = P.size();
    const label nL = nLocal();

    const scalar rMax = maxRadius();
    skin_ = skinFraction_*2*rMax;

    // Kept pair histories, indexed by their (local) first particle
    labelList start;
    List<const keptPair*> kept;
    groupByParticle(keptPairs_, nL, start, kept);

    // New lists; pairs of two ghosts are their owners' business
    pairs_.clear();
    bins_.build(P.position, 2*rMax + skin_);
    bins_.pairs(P, skin_, pairs_);
    if (nL < n)
    {
        keepLocal(pairs_, nL);
    }

    for (contactPair& c : pairs_)
    {
        const label partner = P.identity[c.j];
        for (label k = start[c.i]; k < start[c.i + 1]; ++k)
        {
            if (kept[k]->partner == partner)
            {
                c.history = kept[k]->history;
                break;
            }
        }
    }

    // Wall contacts of local particles, history by (particle, face)
    labelList wallStart;
    List<const wallContact*> keptWall;
    groupByParticle(keptWalls_, nL, wallStart, keptWall);

    wallContacts_.clear();
    walls_.candidates(P, skin_, wallContacts_);
    if (nL < n)
    {
        keepLocal(wallContacts_, nL);
    }

    for (wallContact& c : wallContacts_)
    {
        for (label k = wallStart[c.i]; k < wallStart[c.i + 1]; ++k)
        {
            if (keptWall[k]->face == c.face)
            {
                c.history = keptWall[k]->history;
                break;
            }
        }
    }

    // Wall histories given by face centre
    if (pendingWall_.size())
    {
        labelList pendStart;
        List<const wallContactRecord*> pend;
        groupByParticle(pendingWall_, nL, pendStart, pend);

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
    }

    keptPairs_.clear();
    keptWalls_.clear();

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
        P.dragForce[i] = P.dragCoeff[i]*(P.fluidVelocity[i] - P.velocity[i]);
        P.force[i] = P.externalForce[i] + P.dragForce[i];
        P.torque[i] = Zero;
    }

    law_->pairForces(P, pairs_, deltaT);
    cohesion_->pairForces(P, pairs_, deltaT, time_);

    walls_.update(P, wallContacts_);
    law_->wallForces(P, wallContacts_, deltaT);
    cohesion_->wallForces(P, wallContacts_, walls_, deltaT, time_);
}


void Foam::demEngine::initialise()
{
    if (nLocal_ < 0)
    {
        exchange();
    }
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
    const label nL = nLocal();
    const scalar half = 0.5*deltaT;

    vector* __restrict__ x = P.position.data();
    vector* __restrict__ v = P.velocity.data();
    vector* __restrict__ w = P.angularVelocity.data();
    const vector* __restrict__ F = P.force.cdata();
    const vector* __restrict__ T = P.torque.cdata();
    const scalar* __restrict__ m = P.mass.cdata();
    const scalar* __restrict__ I = P.inertia.cdata();

    vector* __restrict__ Jd = P.dragImpulse.data();
    const vector* __restrict__ Fd = P.dragForce.cdata();

    for (label i = 0; i < nL; ++i)
    {
        v[i] += (half/m[i])*F[i];
        w[i] += (half/I[i])*T[i];
        x[i] += deltaT*v[i];
        Jd[i] += half*Fd[i];
    }

    if (halo_.valid())
    {
        // Ghosts at the new positions, then a rebuild everywhere if any
        // processor needs one (the ghosts are chosen again with it)
        halo_->update(P, nL);
        if (returnReduce(listsExpired(), orOp<bool>()))
        {
            keepHistory();
            halo_->select(P, nL, 2*maxRadius()*(1 + skinFraction_));
            buildLists();
        }
    }
    else if (listsExpired())
    {
        keepHistory();
        buildLists();
    }

    time_ += deltaT;
    computeForces(deltaT);

    // Fresh pointers: choosing the ghosts may have reallocated the lists
    vector* __restrict__ v2 = P.velocity.data();
    vector* __restrict__ w2 = P.angularVelocity.data();
    const vector* __restrict__ F2 = P.force.cdata();
    const vector* __restrict__ T2 = P.torque.cdata();
    const scalar* __restrict__ m2 = P.mass.cdata();
    const scalar* __restrict__ I2 = P.inertia.cdata();
    vector* __restrict__ Jd2 = P.dragImpulse.data();
    const vector* __restrict__ Fd2 = P.dragForce.cdata();
    for (label i = 0; i < nL; ++i)
    {
        v2[i] += (half/m2[i])*F2[i];
        w2[i] += (half/I2[i])*T2[i];
        Jd2[i] += half*Fd2[i];
    }
}


Foam::label Foam::demEngine::nPairContacts() const
{
    const demParticles& P = particles_;
    const label nL = nLocal();
    label count = 0;
    for (const contactPair& c : pairs_)
    {
        if
        (
            c.history.active()
         && (c.j < nL || P.identity[c.i] < P.identity[c.j])
        )
        {
            ++count;
        }
    }
    return count;
}


Foam::label Foam::demEngine::nBridgedContacts() const
{
    const demParticles& P = particles_;
    const label nL = nLocal();
    label count = 0;
    for (const contactPair& c : pairs_)
    {
        if
        (
            c.history.active() && c.history.bridge > 0
         && (c.j < nL || P.identity[c.i] < P.identity[c.j])
        )
        {
            ++count;
        }
    }
    for (const wallContact& c : wallContacts_)
    {
        if (c.history.active() && c.history.bridge > 0)
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
