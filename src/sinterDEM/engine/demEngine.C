// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "demEngine.H"
#include <utility>
#include "keywordSource.H"

namespace
{

//- Items grouped by their particle in [0, n): offsets start (n + 1) and
//  the items in that order (counting sort, stable)
void groupByParticle
(
    const Foam::labelUList& particle,
    const Foam::label n,
    Foam::labelList& start,
    Foam::labelList& sorted
)
{
    using namespace Foam;
    start.setSize(n + 1);
    start = 0;
    for (const label i : particle)
    {
        ++start[i + 1];
    }
    for (label i = 0; i < n; ++i)
    {
        start[i + 1] += start[i];
    }
    sorted.setSize(particle.size());
    labelList fill(SubList<label>(start, n));
    forAll(particle, k)
    {
        sorted[fill[particle[k]]++] = k;
    }
}


void copyBlock(const Foam::scalar* from, Foam::scalar* to, const Foam::label n)
{
    for (Foam::label c = 0; c < n; ++c)
    {
        to[c] = from[c];
    }
}

//- Pending states of the particles that stay (newIndex >= 0), renumbered
//  (the blocks of the others are left to the next compactStates)
template<class Partner>
void remapPending
(
    const Foam::labelUList& newIndex,
    Foam::DynamicList<Foam::label>& particle,
    Foam::DynamicList<Partner>& partner,
    Foam::DynamicList<Foam::label>& block
)
{
    using namespace Foam;
    label n = 0;
    forAll(particle, p)
    {
        const label i = newIndex[particle[p]];
        if (i >= 0)
        {
            particle[n] = i;
            partner[n] = partner[p];
            block[n] = block[p];
            ++n;
        }
    }
    particle.resize(n);
    partner.resize(n);
    block.resize(n);
}

//- Room for n more pending states, growing by a quarter at least (not
//  doubling: restart records are many)
template<class Partner>
void growPending
(
    Foam::DynamicList<Foam::label>& particle,
    Foam::DynamicList<Partner>& partner,
    Foam::DynamicList<Foam::label>& block,
    const Foam::label n
)
{
    using namespace Foam;
    const label need = particle.size() + n;
    if (need > particle.capacity())
    {
        const label cap = max(need, label(1.25*particle.capacity()) + 16);
        particle.setCapacity(cap);
        partner.setCapacity(cap);
        block.setCapacity(cap);
    }
}

} // End anonymous namespace


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
    skinFraction_(dict.lookupOrDefault<scalar>("skin", 0.1)),
    skin_(0),
    nLocal_(0),
    listsValid_(false),
    rebuildRequested_(false),
    lastPairs_(0),
    lastWalls_(0),
    nBuilds_(0),
    spatialSort_(false),
    movedValid_(false),
    recordIndexValid_(false)
{
    if (!(skinFraction_ > 0))
    {
        FatalIOErrorInKeyword(dict, "skin")
            << "Keyword skin in " << dict.name()
            << " must be positive, not " << skinFraction_
            << exit(FatalIOError);
    }
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


void Foam::demEngine::clearLists()
{
    pairs_.clear();
    wallContacts_.clear();
    builtAt_.clear();
    listsValid_ = false;
    recordIndexValid_ = false;
}


void Foam::demEngine::clearPending(const bool freeStorage)
{
    if (freeStorage)
    {
        pendingPairParticle_.clearStorage();
        pendingPairPartner_.clearStorage();
        pendingPairBlock_.clearStorage();
        pendingWallParticle_.clearStorage();
        pendingWallCentre_.clearStorage();
        pendingWallBlock_.clearStorage();
    }
    else
    {
        pendingPairParticle_.clear();
        pendingPairPartner_.clear();
        pendingPairBlock_.clear();
        pendingWallParticle_.clear();
        pendingWallCentre_.clear();
        pendingWallBlock_.clear();
    }
    recordIndexValid_ = false;
}


void Foam::demEngine::keepStates(const labelUList& newIndex)
{
    if (!listsValid_)
    {
        return;
    }

    const label nL = nLocal();

    // Room for exactly the touching contacts (those with a block), then
    // their blocks (the states stay where they are)
    label nPairs = 0;
    for (const label b : pairs_.slot)
    {
        nPairs += b >= 0;
    }
    label nWalls = 0;
    for (const label b : wallContacts_.slot)
    {
        nWalls += b >= 0;
    }
    growPending
    (
        pendingPairParticle_, pendingPairPartner_, pendingPairBlock_, nPairs
    );
    growPending
    (
        pendingWallParticle_, pendingWallCentre_, pendingWallBlock_, nWalls
    );

    for (label k = 0; k < pairs_.size(); ++k)
    {
        const label blk = pairs_.slot[k];
        if (blk >= 0)
        {
            label a = pairs_.first[k];
            label b = pairs_.second[k];
            const bool flip =
                newIndex.size() && b < nL
             && newIndex[a] < 0 && newIndex[b] >= 0;
            if (flip)
            {
                std::swap(a, b);
                slots_.flipSides(pairs_.block(blk));
            }
            pendingPairParticle_.append(a);
            pendingPairPartner_.append(particles_.identity[b]);
            pendingPairBlock_.append(blk);
        }
    }
    for (label k = 0; k < wallContacts_.size(); ++k)
    {
        const label blk = wallContacts_.slot[k];
        if (blk >= 0)
        {
            pendingWallParticle_.append(wallContacts_.first[k]);
            pendingWallCentre_.append(walls_.centre(wallContacts_.second[k]));
            pendingWallBlock_.append(blk);
        }
    }
    listsValid_ = false;
    recordIndexValid_ = false;
}


void Foam::demEngine::remapPendingStates(const labelUList& newIndex)
{
    remapPending
    (
        newIndex, pendingPairParticle_, pendingPairPartner_, pendingPairBlock_
    );
    remapPending
    (
        newIndex, pendingWallParticle_, pendingWallCentre_, pendingWallBlock_
    );
}


void Foam::demEngine::reorder(const labelUList& order)
{
    const label nOld = nLocal();
    labelList newIndex(nOld, -1);
    forAll(order, k)
    {
        if (order[k] >= 0)
        {
            newIndex[order[k]] = k;
        }
    }

    // A pair whose first particle goes is kept from its second's side
    keepStates(newIndex);

    remapPendingStates(newIndex);

    particles_.resize(nOld);
    particles_.reorder(order);
    nLocal_ = order.size();
    clearLists();
}


void Foam::demEngine::addRecords(const label i, const contactRecords& records)
{
    keepStates();
    if (records.size() && records.stride != slots_.stride())
    {
        FatalErrorInFunction
            << "Contact records of particle " << i << " hold "
            << records.stride << " scalars per contact; the models declare "
            << slots_.stride() << exit(FatalError);
    }
    const label stride = slots_.stride();

    // Without other processors every partner is a local particle, which
    // brings its own record of the pair: the side of the smaller identity
    // is enough (the list build takes a state from either side)
    const bool oneSide = !halo_.valid();
    const demIdentity self = particles_.identity[i];

    label nPairs = 0;
    label nWalls = 0;
    forAll(records.partner, k)
    {
        const demIdentity partner = records.partner[k];
        if (contactRecords::isWall(partner))
        {
            ++nWalls;
        }
        else if (!oneSide || self < partner)
        {
            ++nPairs;
        }
    }
    growPending(pendingPairParticle_, pendingPairPartner_, pendingPairBlock_, nPairs);
    growPending(pendingWallParticle_, pendingWallCentre_, pendingWallBlock_, nWalls);

    // Each state in a new block of its list's pool
    forAll(records.partner, k)
    {
        const scalar* b = records.stateOf(k);
        if (contactRecords::isWall(records.partner[k]))
        {
            const label blk = wallContacts_.newBlock();
            copyBlock(b, wallContacts_.block(blk), stride);
            pendingWallParticle_.append(i);
            pendingWallCentre_.append(records.faceCentre[k]);
            pendingWallBlock_.append(blk);
        }
        else if (!oneSide || self < records.partner[k])
        {
            const label blk = pairs_.newBlock();
            copyBlock(b, pairs_.block(blk), stride);
            pendingPairParticle_.append(i);
            pendingPairPartner_.append(records.partner[k]);
            pendingPairBlock_.append(blk);
        }
    }
    recordIndexValid_ = false;
}


void Foam::demEngine::sortLocals(const scalar range)
{
    demParticles& P = particles_;
    const label nL = nLocal();
    if (nL < 2)
    {
        return;
    }

    // The bins of the locals (the list build bins them again with the
    // ghosts), then by identity within a bin
    bins_.build(SubList<vector>(P.position, nL), range);
    labelList order(bins_.sorted());
    const labelList& start = bins_.start();
    const label nBins = start.size() - 1;

    // Within a bin by identity (a few particles: insertion sort)
    const demIdentity* id = P.identity.cdata();
    for (label b = 0; b < nBins; ++b)
    {
        for (label p = start[b] + 1; p < start[b + 1]; ++p)
        {
            const label i = order[p];
            label q = p;
            while (q > start[b] && id[order[q - 1]] > id[i])
            {
                order[q] = order[q - 1];
                --q;
            }
            order[q] = i;
        }
    }

    labelList newIndex(nL);
    bool same = true;
    forAll(order, k)
    {
        newIndex[order[k]] = k;
        same = same && order[k] == k;
    }
    if (same)
    {
        return;
    }

    remapPendingStates(newIndex);

    // In place, through the list-build positions (rebuilt after this)
    P.resize(nL);
    builtAt_.resize(nL);
    P.permute(order, builtAt_);

    if (movedValid_)
    {
        forAll(moved_, k)
        {
            moved_[k] = newIndex[moved_[k]];
        }
    }
    else
    {
        moved_.transfer(newIndex);
        movedValid_ = true;
    }
}


void Foam::demEngine::rebuild()
{
    demParticles& P = particles_;
    const label nL = nLocal();

    const scalar rMax = maxRadius();
    skin_ = skinFraction_*2*rMax;

    // The pair lists reach the skin, and with indirect conduction the lens
    const scalar reach = skin_ + conduction_.pairRange(rMax);

    if (spatialSort_ && rMax > 0)
    {
        sortLocals(2*rMax + reach);
    }

    if (halo_.valid())
    {
        halo_->select(P, nL, 2*rMax + reach);
    }

    if (!(rMax > 0))
    {
        // No particles anywhere: empty lists
        clearPending();
        clearLists();
        pairs_.clearStates();
        wallContacts_.clearStates();
        listsValid_ = true;
        ++nBuilds_;
        return;
    }

    // Pending states by particle
    labelList start;
    labelList sorted;
    groupByParticle(pendingPairParticle_, nL, start, sorted);

    // Pairs (of two ghosts: their owners' business)
    // Room for the pairs: as many as last time and a little more, or, the
    // first time, exactly as many (counted)
    bins_.build(P.position, 2*rMax + reach);
    pairs_.clearWithRoom
    (
        lastPairs_ > 0
      ? label(1.05*lastPairs_) + 64
      : bins_.countPairs(P, nL, reach)
    );
    bins_.pairs(P, nL, reach, pairs_);
    law_->setPairCoefficients(P, pairs_);

    // A pair's state is kept from the side of its first particle; a state
    // kept from the other side (the particles changed order) is flipped
    auto findPair = [&](const label a, const label b) -> label
    {
        const demIdentity partner = P.identity[b];
        for (label q = start[a]; q < start[a + 1]; ++q)
        {
            if (pendingPairPartner_[sorted[q]] == partner)
            {
                return sorted[q];
            }
        }
        return -1;
    };

    for (label k = 0; k < pairs_.size(); ++k)
    {
        const label a = pairs_.first[k];
        const label b = pairs_.second[k];
        label p = findPair(a, b);
        if (p >= 0)
        {
            pairs_.slot[k] = pendingPairBlock_[p];
        }
        else if (b < nL && (p = findPair(b, a)) >= 0)
        {
            pairs_.slot[k] = pendingPairBlock_[p];
            slots_.flipSides(pairs_.block(pairs_.slot[k]));
        }
    }
    pairs_.compactStates(blockScratch_);

    // Wall contacts of local particles, states by face centre
    wallContacts_.clearWithRoom(label(1.05*lastWalls_) + 64);
    walls_.candidates(P, nL, skin_ + conduction_.wallRange(rMax), wallContacts_);
    law_->setWallCoefficients(P, walls_, wallContacts_);

    groupByParticle(pendingWallParticle_, nL, start, sorted);
    // Face centres a hundredth of the skin apart are the same face: far
    // above the rounding of an ascii write, far below the face spacing
    const scalar tol2 = sqr(0.01*skin_);
    for (label k = 0; k < wallContacts_.size(); ++k)
    {
        const label i = wallContacts_.first[k];
        if (start[i] == start[i + 1])
        {
            continue;
        }
        const point centre = walls_.centre(wallContacts_.second[k]);
        for (label q = start[i]; q < start[i + 1]; ++q)
        {
            const label p = sorted[q];
            if (magSqr(pendingWallCentre_[p] - centre) < tol2)
            {
                wallContacts_.slot[k] = pendingWallBlock_[p];
                break;
            }
        }
    }
    wallContacts_.compactStates(blockScratch_);

    // Kept for the next build (no allocation per build)
    clearPending(false);

    lastPairs_ = pairs_.size();
    lastWalls_ = wallContacts_.size();
    builtAt_ = SubList<vector>(P.position, nL);
    listsValid_ = true;
    recordIndexValid_ = false;
    ++nBuilds_;
}


bool Foam::demEngine::listsExpired() const
{
    const label nL = nLocal();
    if (!listsValid_ || builtAt_.size() != nL)
    {
        return true;
    }
    const scalar limit2 = sqr(0.5*skin_);
    const vector* __restrict__ x = particles_.position.cdata();
    const vector* __restrict__ x0 = builtAt_.cdata();
    for (label i = 0; i < nL; ++i)
    {
        if (magSqr(x[i] - x0[i]) > limit2)
        {
            return true;
        }
    }
    return false;
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


void Foam::demEngine::beginStep()
{
    if (nLocal_ < 0)
    {
        nLocal_ = particles_.size();
    }
    movedValid_ = false;
    checkWallTemperature();
    recordIndexValid_ = false;

    bool rebuildNow = rebuildRequested_ || listsExpired();
    if (halo_.valid())
    {
        reduce(rebuildNow, orOp<bool>());
    }
    if (rebuildNow)
    {
        keepStates();
        rebuild();
    }
    else if (halo_.valid())
    {
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
    rebuild();
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
        bool expired =
            s == 0
          ? integrate<true, false>(deltaT)
          : integrate<true, true>(deltaT);

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
            halo_->update(P, nL, conduction_.active());
            reduce(expired, orOp<bool>());
        }
        if (expired)
        {
            keepStates();
            rebuild();
        }

        time_ += deltaT;
        kernel_->pairs(P, pairs_, deltaT, time_);
        kernel_->walls
        (
            P, wallContacts_, walls_, deltaT, time_, wallFaceImpulse_.data()
        );

        if (conduction_.active())
        {
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


void Foam::demEngine::indexRecords() const
{
    const label nL = nLocal();
    const label dur = durationSlot_;

    // Entries: valid lists: 2k (pair k from its first particle), 2k + 1
    // (from its second), -k-1 (wall contact k); otherwise 2p (pending pair
    // state p), -p-1 (pending wall state p)
    DynamicList<label> owner;
    DynamicList<label> entry;
    if (listsValid_)
    {
        for (label k = 0; k < pairs_.size(); ++k)
        {
            if (pairs_.stateOf(k)[dur] > 0)
            {
                owner.append(pairs_.first[k]);
                entry.append(2*k);
                if (pairs_.second[k] < nL)
                {
                    owner.append(pairs_.second[k]);
                    entry.append(2*k + 1);
                }
            }
        }
        for (label k = 0; k < wallContacts_.size(); ++k)
        {
            if (wallContacts_.stateOf(k)[dur] > 0)
            {
                owner.append(wallContacts_.first[k]);
                entry.append(-k - 1);
            }
        }
    }
    else
    {
        forAll(pendingPairParticle_, p)
        {
            owner.append(pendingPairParticle_[p]);
            entry.append(2*p);
        }
        forAll(pendingWallParticle_, p)
        {
            owner.append(pendingWallParticle_[p]);
            entry.append(-p - 1);
        }
    }

    labelList sorted;
    groupByParticle(owner, nL, recordStart_, sorted);
    recordContact_.setSize(sorted.size());
    forAll(sorted, q)
    {
        recordContact_[q] = entry[sorted[q]];
    }
    recordIndexValid_ = true;
}


void Foam::demEngine::recordsOf(const label i, contactRecords& records) const
{
    if (!recordIndexValid_)
    {
        indexRecords();
    }

    const label stride = slots_.stride();
    const label s = recordStart_[i];
    const label e = recordStart_[i + 1];
    records.setSize(e - s, stride, slots_.vectorOffsets());
    for (label q = s; q < e; ++q)
    {
        const label c = recordContact_[q];
        const label k = q - s;
        scalar* b = records.stateOf(k);
        if (!listsValid_)
        {
            if (c >= 0)
            {
                const label p = c/2;
                records.partner[k] = pendingPairPartner_[p];
                records.faceCentre[k] = Zero;
                copyBlock(pairs_.block(pendingPairBlock_[p]), b, stride);
            }
            else
            {
                const label p = -c - 1;
                records.partner[k] = -1;
                records.faceCentre[k] = pendingWallCentre_[p];
                copyBlock(wallContacts_.block(pendingWallBlock_[p]), b, stride);
            }
        }
        else if (c >= 0)
        {
            const label pk = c/2;
            const bool fromSecond = c % 2;
            const label partner =
                fromSecond ? pairs_.first[pk] : pairs_.second[pk];
            records.partner[k] = particles_.identity[partner];
            records.faceCentre[k] = Zero;
            copyBlock(pairs_.stateOf(pk), b, stride);
            if (fromSecond)
            {
                slots_.flipSides(b);
            }
        }
        else
        {
            const label wk = -c - 1;
            records.partner[k] = -1;
            records.faceCentre[k] = walls_.centre(wallContacts_.second[wk]);
            copyBlock(wallContacts_.stateOf(wk), b, stride);
        }
    }
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
