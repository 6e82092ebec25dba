// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "demHalo.H"
#include "Pstream.H"
#include "PstreamBuffers.H"
#include "UIPstream.H"
#include "UOPstream.H"
#include "registerSwitch.H"
#include "profiling.H"

#include <algorithm>
#include <cmath>
#include <vector>
#include <cstdint>

namespace
{

// A ghost's motion in a packed buffer: position, velocity, angular
// velocity (9 scalars); returns the offset after them
inline Foam::label packMotion
(
    const Foam::demParticles& P,
    const Foam::label i,
    Foam::scalar* b,
    Foam::label offset
)
{
    const Foam::vector& x = P.position[i];
    const Foam::vector& v = P.velocity[i];
    const Foam::vector& w = P.angularVelocity[i];
    b[offset++] = x.x(); b[offset++] = x.y(); b[offset++] = x.z();
    b[offset++] = v.x(); b[offset++] = v.y(); b[offset++] = v.z();
    b[offset++] = w.x(); b[offset++] = w.y(); b[offset++] = w.z();
    return offset;
}

inline void unpackMotion
(
    const Foam::scalar* r,
    Foam::demParticles& P,
    const Foam::label g
)
{
    P.position[g] = Foam::vector(r[0], r[1], r[2]);
    P.velocity[g] = Foam::vector(r[3], r[4], r[5]);
    P.angularVelocity[g] = Foam::vector(r[6], r[7], r[8]);
}

} // End anonymous namespace

#include <unordered_set>

int Foam::demHalo::gridPerParticle
(
    Foam::debug::optimisationSwitch("demHaloGridPerParticle", 64)
);
registerOptSwitch
(
    "demHaloGridPerParticle",
    int,
    Foam::demHalo::gridPerParticle
);


Foam::demHalo::demHalo(const boundBox& meshBox)
:
    meshBox_(meshBox),
    neighbours_(),
    sendMap_(),
    nReceived_()
{}


void Foam::demHalo::select
(
    demParticles& P,
    const label nLocal,
    const scalar range
)
{
    P.resize(nLocal);

    // This processor's region: its mesh and its particles
    boundBox region(meshBox_);
    for (label i = 0; i < nLocal; ++i)
    {
        region.add(P.position[i]);
    }

    // (The profiling phases below split the choice: the regions' exchange
    // waits for every processor to reach the build)
    List<boundBox> regions(Pstream::nProcs());
    regions[Pstream::myProcNo()] = region;
    {
        addProfiling(regionsExchange, "demHalo::select::regions");
        Pstream::gatherList(regions);
        Pstream::scatterList(regions);
    }

    // Neighbours: enlarged regions that overlap (a symmetric relation)
    DynamicList<label> nbrs;
    List<boundBox> grown(regions.size());
    forAll(regions, proci)
    {
        grown[proci] = regions[proci];
        grown[proci].min() -= vector::uniform(range);
        grown[proci].max() += vector::uniform(range);
    }
    // The same test on both sides of a pair (the lower rank's region
    // grown), so that the relation is symmetric to the last bit
    const label me = Pstream::myProcNo();
    forAll(regions, proci)
    {
        if
        (
            proci != me
         && grown[min(proci, me)].overlaps(regions[max(proci, me)])
        )
        {
            nbrs.append(proci);
        }
    }
    neighbours_.transfer(nbrs);

    // Send each neighbour the local particles within range of one of its
    // particles, tested on bins of the range (a grid common to all
    // processors): a particle is sent when one of the 27 bins around its
    // own holds a particle of the neighbour. A pair within range has its
    // partners in neighbouring bins, so none is missed; unlike the
    // enlarged box alone, a boundary that follows the cells (a jagged
    // one) costs a strip of the range, not of a cell.
    point origin(point::uniform(GREAT));
    for (const boundBox& b : regions)
    {
        if (b.valid())
        {
            origin = min(origin, b.min());
        }
    }
    const scalar h = range > 0 ? range : scalar(1);
    auto binOf = [&origin, h](const point& x)
    {
        return FixedList<label, 3>
        ({
            label(std::floor((x.x() - origin.x())/h)),
            label(std::floor((x.y() - origin.y())/h)),
            label(std::floor((x.z() - origin.z())/h))
        });
    };
    // A bin's key: 21 bits per direction (bins of the range over 2 million
    // ranges; the indices are >= 0 from the global origin)
    auto key = [](const label i, const label j, const label k)
    {
        return
            (std::uint64_t(i) & 0x1FFFFF)
          | ((std::uint64_t(j) & 0x1FFFFF) << 21)
          | ((std::uint64_t(k) & 0x1FFFFF) << 42);
    };

    // This processor's occupied bins, each once
    addProfiling(ownBinsPhase, "demHalo::select::bins");
    List<FixedList<label, 3>> bin(nLocal);
    std::vector<std::uint64_t> ownBins(nLocal);
    for (label i = 0; i < nLocal; ++i)
    {
        bin[i] = binOf(P.position[i]);
        ownBins[i] = key(bin[i][0], bin[i][1], bin[i][2]);
    }
    std::sort(ownBins.begin(), ownBins.end());
    ownBins.erase(std::unique(ownBins.begin(), ownBins.end()), ownBins.end());

    endProfiling(ownBinsPhase);

    // The neighbours' occupied bins
    List<labelList> nbrBins(neighbours_.size());
    {
        addProfiling(binsExchange, "demHalo::select::binsExchange");
        PstreamBuffers binBuffers(Pstream::commsTypes::nonBlocking);
        labelList mine(3*ownBins.size());
        label n = 0;
        for (const std::uint64_t b : ownBins)
        {
            mine[n++] = label(b & 0x1FFFFF);
            mine[n++] = label((b >> 21) & 0x1FFFFF);
            mine[n++] = label((b >> 42) & 0x1FFFFF);
        }
        forAll(neighbours_, k)
        {
            UOPstream os(neighbours_[k], binBuffers);
            os << mine;
        }
        binBuffers.finishedSends();
        forAll(neighbours_, k)
        {
            UIPstream is(neighbours_[k], binBuffers);
            is >> nbrBins[k];
        }
    }

    // A particle goes to a neighbour when its bin is one of the 27 around
    // a bin of the neighbour: those bins marked once on a dense grid over
    // the part of the neighbour's enlarged region that this region covers
    // (one look-up per particle), or, should that grid be far larger than
    // the particles, looked up in a hash set (27 look-ups per particle)
    static bool reported = false;
    if (gridPerParticle != 64 && !reported)
    {
        Info<< "demHalo: dense grid of bins up to " << gridPerParticle
            << " per particle (OptimisationSwitch demHaloGridPerParticle)"
            << endl;
        reported = true;
    }

    addProfiling(choose, "demHalo::select::choose");
    sendMap_.setSize(neighbours_.size());
    forAll(neighbours_, k)
    {
        const boundBox& box = grown[neighbours_[k]];
        const labelList& theirs = nbrBins[k];
        DynamicList<label> send;

        const FixedList<label, 3> lo = binOf(max(box.min(), region.min()));
        const FixedList<label, 3> hi = binOf(min(box.max(), region.max()));
        const scalar nx = scalar(hi[0] - lo[0] + 1);
        const scalar ny = scalar(hi[1] - lo[1] + 1);
        const scalar nz = scalar(hi[2] - lo[2] + 1);
        const bool overlap = nx > 0 && ny > 0 && nz > 0;
        const scalar nGrid = overlap ? nx*ny*nz : 0;

        if
        (
            overlap && gridPerParticle > 0
         && nGrid <= scalar(gridPerParticle)*(nLocal + theirs.size()/3) + 4096
        )
        {
            const label mx = label(nx), my = label(ny), mz = label(nz);
            std::vector<char> near(size_t(mx)*my*mz, 0);
            for (label m = 0; m + 2 < theirs.size(); m += 3)
            {
                for (label dk = -1; dk <= 1; ++dk)
                {
                    const label c = theirs[m+2] + dk - lo[2];
                    if (c < 0 || c >= mz) continue;
                    for (label dj = -1; dj <= 1; ++dj)
                    {
                        const label b = theirs[m+1] + dj - lo[1];
                        if (b < 0 || b >= my) continue;
                        for (label di = -1; di <= 1; ++di)
                        {
                            const label a = theirs[m] + di - lo[0];
                            if (a < 0 || a >= mx) continue;
                            near[size_t(a) + size_t(mx)*(b + size_t(my)*c)] = 1;
                        }
                    }
                }
            }
            for (label i = 0; i < nLocal; ++i)
            {
                if (!box.contains(P.position[i]))
                {
                    continue;
                }
                // Inside the box and the region: its bin is on the grid
                // (the bin of a coordinate does not decrease with it)
                const label a = bin[i][0] - lo[0];
                const label b = bin[i][1] - lo[1];
                const label c = bin[i][2] - lo[2];
                if (near[size_t(a) + size_t(mx)*(b + size_t(my)*c)])
                {
                    send.append(i);
                }
            }
        }
        else if (overlap)
        {
            std::unordered_set<std::uint64_t> theirSet;
            theirSet.reserve(theirs.size()/3);
            for (label m = 0; m + 2 < theirs.size(); m += 3)
            {
                theirSet.insert(key(theirs[m], theirs[m+1], theirs[m+2]));
            }
            for (label i = 0; i < nLocal; ++i)
            {
                if (!box.contains(P.position[i]))
                {
                    continue;
                }
                bool near = false;
                for (label dk = -1; dk <= 1 && !near; ++dk)
                {
                    for (label dj = -1; dj <= 1 && !near; ++dj)
                    {
                        for (label di = -1; di <= 1 && !near; ++di)
                        {
                            near = theirSet.count
                            (
                                key
                                (
                                    bin[i][0] + di,
                                    bin[i][1] + dj,
                                    bin[i][2] + dk
                                )
                            );
                        }
                    }
                }
                if (near)
                {
                    send.append(i);
                }
            }
        }
        sendMap_[k].transfer(send);
    }

    endProfiling(choose);

    addProfiling(ghostsExchange, "demHalo::select::ghostsExchange");

    // How many ghosts each neighbour sends
    const int tag = UPstream::msgType();
    nReceived_.setSize(neighbours_.size());
    labelList nSendTo(neighbours_.size());
    {
        const label startRequest = UPstream::nRequests();
        forAll(neighbours_, k)
        {
            nSendTo[k] = sendMap_[k].size();
            UIPstream::read
            (
                UPstream::commsTypes::nonBlocking,
                neighbours_[k],
                reinterpret_cast<char*>(&nReceived_[k]),
                sizeof(label),
                tag
            );
        }
        forAll(neighbours_, k)
        {
            UOPstream::write
            (
                UPstream::commsTypes::nonBlocking,
                neighbours_[k],
                reinterpret_cast<const char*>(&nSendTo[k]),
                sizeof(label),
                tag
            );
        }
        UPstream::waitRequests(startRequest);
    }

    // The ghosts, one packed message each way per neighbour: 15 scalars
    // and the identity's two labels (exact as scalars) per ghost
    const label nv = 17;
    label nSend = 0;
    label nRecv = 0;
    forAll(neighbours_, k)
    {
        nSend += nSendTo[k];
        nRecv += nReceived_[k];
    }
    sendBuf_.resize(nSend*nv);
    recvBuf_.resize(nRecv*nv);

    scalar* __restrict__ b = sendBuf_.data();
    label offset = 0;
    forAll(neighbours_, k)
    {
        for (const label i : sendMap_[k])
        {
            offset = packMotion(P, i, b, offset);
            b[offset++] = P.radius[i];
            b[offset++] = P.invMass[i];
            b[offset++] = P.invInertia[i];
            b[offset++] = P.temperature[i];
            b[offset++] = P.gasConductivity[i];
            b[offset++] = P.surfaceIron[i];
            b[offset++] = identityProc(P.identity[i]);
            b[offset++] = identityIndex(P.identity[i]);
        }
    }
    exchangeBuffers(nv);

    P.resize(nLocal + nRecv);
    const scalar* __restrict__ r = recvBuf_.cdata();
    offset = 0;
    for (label g = nLocal; g < nLocal + nRecv; ++g)
    {
        unpackMotion(r + offset, P, g);
        P.radius[g] = r[offset + 9];
        P.invMass[g] = r[offset + 10];
        P.invInertia[g] = r[offset + 11];
        P.temperature[g] = r[offset + 12];
        P.gasConductivity[g] = r[offset + 13];
        P.surfaceIron[g] = r[offset + 14];
        P.identity[g] =
            makeIdentity(label(r[offset + 15]), label(r[offset + 16]));
        offset += nv;
    }
}


void Foam::demHalo::exchangeBuffers(const label nv) const
{
    const label startRequest = UPstream::nRequests();
    const int tag = UPstream::msgType();

    label offset = 0;
    forAll(neighbours_, k)
    {
        const label n = nReceived_[k]*nv;
        if (n)
        {
            UIPstream::read
            (
                UPstream::commsTypes::nonBlocking,
                neighbours_[k],
                reinterpret_cast<char*>(recvBuf_.data() + offset),
                n*sizeof(scalar),
                tag
            );
        }
        offset += n;
    }

    offset = 0;
    forAll(neighbours_, k)
    {
        const label n = sendMap_[k].size()*nv;
        if (n)
        {
            UOPstream::write
            (
                UPstream::commsTypes::nonBlocking,
                neighbours_[k],
                reinterpret_cast<const char*>(sendBuf_.cdata() + offset),
                n*sizeof(scalar),
                tag
            );
        }
        offset += n;
    }

    UPstream::waitRequests(startRequest);
}


void Foam::demHalo::update
(
    demParticles& P,
    const label nLocal,
    const bool withTemperature
) const
{
    // Scalars per ghost: position, velocity, angular velocity (, T and
    // the gas conductivity)
    const label nv = withTemperature ? 11 : 9;

    label nSend = 0;
    for (const labelList& send : sendMap_)
    {
        nSend += send.size();
    }
    label nRecv = 0;
    for (const label n : nReceived_)
    {
        nRecv += n;
    }
    sendBuf_.resize(nSend*nv);
    recvBuf_.resize(nRecv*nv);

    scalar* __restrict__ b = sendBuf_.data();
    label offset = 0;
    forAll(neighbours_, k)
    {
        for (const label i : sendMap_[k])
        {
            offset = packMotion(P, i, b, offset);
            if (withTemperature)
            {
                b[offset++] = P.temperature[i];
                b[offset++] = P.gasConductivity[i];
            }
        }
    }
    exchangeBuffers(nv);

    const scalar* __restrict__ r = recvBuf_.cdata();
    offset = 0;
    for (label g = nLocal; g < nLocal + nRecv; ++g)
    {
        unpackMotion(r + offset, P, g);
        if (withTemperature)
        {
            P.temperature[g] = r[offset + 9];
            P.gasConductivity[g] = r[offset + 10];
        }
        offset += nv;
    }
}

