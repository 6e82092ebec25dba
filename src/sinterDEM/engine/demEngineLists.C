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
        ++nBuilds_;
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
    if (relativeExpiry_ && !halo_.valid())
    {
        builtRMax_ = rMax;
        setExpiryRegions(2*rMax + reach);
    }
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
    const vector* __restrict__ x = particles_.position.cdata();
    const vector* __restrict__ x0 = builtAt_.cdata();
    scalar moved2 = 0;
    for (label i = 0; i < nL; ++i)
    {
        moved2 = max(moved2, magSqr(x[i] - x0[i]));
    }
    return listsExpired(moved2);
}


bool Foam::demEngine::listsExpired(const scalar moved2) const
{
    if (!(moved2 > sqr(0.5*skin_)))
    {
        return false;
    }
    if (!relativeExpiry_ || halo_.valid() || moved2 > sqr(skin_))
    {
        return true;
    }
    return relativeDisplacementExpired();
}


void Foam::demEngine::setExpiryRegions(const scalar binWidth)
{
    const label nL = nLocal();
    const UList<vector> x(SubList<vector>(particles_.position, nL));
    expiryRegion_.setSize(nL);
    if (nL == 0)
    {
        expiryDims_ = 1;
        return;
    }

    // Regions of twice the list bins' width (wider if there would be more
    // regions than particles)
    const boundBox box(x, false);
    const vector span = box.span();
    scalar width = 2*binWidth;
    while (true)
    {
        for (direction d = 0; d < 3; ++d)
        {
            expiryDims_[d] = label(span[d]/width) + 1;
        }
        if (scalar(expiryDims_[0])*expiryDims_[1]*expiryDims_[2] <= nL + 27)
        {
            break;
        }
        width *= 1.26;
    }
    const point& o = box.min();
    forAll(x, i)
    {
        label index[3];
        for (direction d = 0; d < 3; ++d)
        {
            index[d] = min(label((x[i][d] - o[d])/width), expiryDims_[d] - 1);
        }
        expiryRegion_[i] =
            index[0] + expiryDims_[0]*(index[1] + expiryDims_[1]*index[2]);
    }
    const label nRegions = expiryDims_[0]*expiryDims_[1]*expiryDims_[2];
    regionLo_.setSize(nRegions);
    regionHi_.setSize(nRegions);
}


bool Foam::demEngine::relativeDisplacementExpired() const
{
    const label nL = nLocal();
    if (expiryRegion_.size() != nL)
    {
        return true;
    }
    const vector* __restrict__ x = particles_.position.cdata();
    const vector* __restrict__ x0 = builtAt_.cdata();
    const label* __restrict__ region = expiryRegion_.cdata();
    vector* __restrict__ lo = regionLo_.data();
    vector* __restrict__ hi = regionHi_.data();
    const label nRegions = regionLo_.size();

    // Each region's box of the displacements, and the box of all
    const vector empty = vector::uniform(GREAT);
    for (label r = 0; r < nRegions; ++r)
    {
        lo[r] = empty;
        hi[r] = -empty;
    }
    vector allLo = empty;
    vector allHi = -empty;
    for (label i = 0; i < nL; ++i)
    {
        const vector d = x[i] - x0[i];
        const label r = region[i];
        lo[r] = min(lo[r], d);
        hi[r] = max(hi[r], d);
        allLo = min(allLo, d);
        allHi = max(allHi, d);
    }

    // Pairs two regions or more apart started 2 (2 r_max + skin) apart
    if (magSqr(allHi - allLo) >= sqr(2*builtRMax_ + 2*skin_))
    {
        return true;
    }

    // Each box widened over the neighbours, one direction at a time: a
    // running min/max over three regions (empty regions are neutral)
    const label stride[3] =
        {1, expiryDims_[0], expiryDims_[0]*expiryDims_[1]};
    for (direction d = 0; d < 3; ++d)
    {
        const label n = expiryDims_[d];
        if (n < 2)
        {
            continue;
        }
        const label step = stride[d];
        // Lines along d: every region whose index along d is 0
        for (label r0 = 0; r0 < nRegions; ++r0)
        {
            if ((r0/step) % n != 0)
            {
                continue;
            }
            vector prevLo = lo[r0];
            vector prevHi = hi[r0];
            for (label k = 0; k < n; ++k)
            {
                const label r = r0 + k*step;
                const vector curLo = lo[r];
                const vector curHi = hi[r];
                vector wLo = min(prevLo, curLo);
                vector wHi = max(prevHi, curHi);
                if (k + 1 < n)
                {
                    wLo = min(wLo, lo[r + step]);
                    wHi = max(wHi, hi[r + step]);
                }
                lo[r] = wLo;
                hi[r] = wHi;
                prevLo = curLo;
                prevHi = curHi;
            }
        }
    }

    // Only the regions that hold particles: a pair of the regions around
    // an empty one lies in the widened box of one of them, or two apart
    const scalar skin2 = sqr(skin_);
    for (label i = 0; i < nL; ++i)
    {
        const label r = region[i];
        if (magSqr(hi[r] - lo[r]) >= skin2)
        {
            return true;
        }
    }
    return false;
}
