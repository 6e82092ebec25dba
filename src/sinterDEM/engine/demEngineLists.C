// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

// The neighbour lists: the engine's particles sorted along the cells of
// their lists, the lists rebuilt and their expiry (demEngine.H)

#include "demEngine.H"
#include "profiling.H"
#include "demEngineDetail.H"
#include <utility>

using namespace Foam::demEngineDetail;

void Foam::demEngine::clearLists()
{
    pairs_.clear();
    wallContacts_.clear();
    builtAt_.clear();
    listsValid_ = false;
    recordIndexValid_ = false;
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


void Foam::demEngine::rebuild(const buildCause cause)
{
    ++nBuildsBy_[static_cast<int>(cause)];

    demParticles& P = particles_;
    const label nL = nLocal();

    const scalar rMax = maxRadius();
    skin_ = skinFraction_*2*rMax;

    // The pair lists reach the skin, and with indirect conduction the lens
    const scalar reach = skin_ + conduction_.pairRange(rMax);

    if (spatialSort_ && rMax > 0)
    {
        addProfiling(sort, "demEngine::lists::sort");
        sortLocals(2*rMax + reach);
    }

    if (halo_.valid())
    {
        addProfiling(ghosts, "demEngine::lists::ghosts");
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
        return;
    }

    // Pending states by particle
    addProfiling(pairLists, "demEngine::lists::pairs");
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
    endProfiling(pairLists);
    addProfiling(pairStates, "demEngine::lists::pairStates");

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
    endProfiling(pairStates);

    // Wall contacts of local particles, states by face centre
    addProfiling(wallLists, "demEngine::lists::walls");
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
}


bool Foam::demEngine::listsChanged() const
{
    return !listsValid_ || builtAt_.size() != nLocal();
}


bool Foam::demEngine::listsExpired() const
{
    const label nL = nLocal();
    if (listsChanged())
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
