// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

// The contact state that goes with the particles: the records a parcel
// carries (restart, a move to another processor) taken into and given
// out of the contact lists, and the states kept across a reorder
// (demEngine.H)

#include "demEngine.H"
#include "demEngineDetail.H"
#include <utility>

using namespace Foam::demEngineDetail;

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
