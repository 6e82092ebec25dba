// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "binGrid.H"

Foam::label Foam::binGrid::binIndex(const vector& x) const
{
    const vector rel = (x - bounds_.min())/width_;
    const label ix = min(max(label(rel.x()), 0), nx_ - 1);
    const label iy = min(max(label(rel.y()), 0), ny_ - 1);
    const label iz = min(max(label(rel.z()), 0), nz_ - 1);
    return ix + nx_*(iy + ny_*iz);
}


void Foam::binGrid::build(const UList<vector>& positions, const scalar width)
{
    const label n = positions.size();
    bounds_ = boundBox(positions, false);
    if (n == 0)
    {
        bounds_ = boundBox(Zero, Zero);
    }

    const vector span = bounds_.span();
    width_ = width;
    const label maxBins = 8*n + 27;
    while (true)
    {
        nx_ = max(label(span.x()/width_) + 1, 1);
        ny_ = max(label(span.y()/width_) + 1, 1);
        nz_ = max(label(span.z()/width_) + 1, 1);
        if (scalar(nx_)*ny_*nz_ <= maxBins)
        {
            break;
        }
        width_ *= 1.26;
    }

    const label nBins = nx_*ny_*nz_;
    start_.setSize(nBins + 1);
    start_ = 0;

    labelList bin(n);
    forAll(positions, i)
    {
        bin[i] = binIndex(positions[i]);
        ++start_[bin[i] + 1];
    }
    for (label b = 0; b < nBins; ++b)
    {
        start_[b + 1] += start_[b];
    }

    sorted_.setSize(n);
    labelList fill(SubList<label>(start_, nBins));
    forAll(positions, i)
    {
        sorted_[fill[bin[i]]++] = i;
    }
}


template<class PairOp>
void Foam::binGrid::forEachPair
(
    const demParticles& P,
    const label nLocal,
    const scalar skin,
    const PairOp& op
) const
{
    // Forward half of the 26 neighbours
    static const label offsets[13][3] =
    {
        {1, 0, 0},
        {-1, 1, 0}, {0, 1, 0}, {1, 1, 0},
        {-1, -1, 1}, {0, -1, 1}, {1, -1, 1},
        {-1, 0, 1}, {0, 0, 1}, {1, 0, 1},
        {-1, 1, 1}, {0, 1, 1}, {1, 1, 1}
    };

    const UList<vector>& x = P.position;
    const UList<scalar>& r = P.radius;

    auto test = [&](const label a, const label b)
    {
        const scalar range = r[a] + r[b] + skin;
        if
        (
            (a < nLocal || b < nLocal)
         && magSqr(x[a] - x[b]) < range*range
        )
        {
            op(min(a, b), max(a, b));
        }
    };

    for (label iz = 0; iz < nz_; ++iz)
    {
        for (label iy = 0; iy < ny_; ++iy)
        {
            for (label ix = 0; ix < nx_; ++ix)
            {
                const label b = ix + nx_*(iy + ny_*iz);
                const label s = start_[b];
                const label e = start_[b + 1];

                for (label p = s; p < e; ++p)
                {
                    for (label q = p + 1; q < e; ++q)
                    {
                        test(sorted_[p], sorted_[q]);
                    }
                }

                for (const auto& o : offsets)
                {
                    const label jx = ix + o[0];
                    const label jy = iy + o[1];
                    const label jz = iz + o[2];
                    if
                    (
                        jx < 0 || jx >= nx_ || jy < 0 || jy >= ny_
                     || jz >= nz_
                    )
                    {
                        continue;
                    }
                    const label nb = jx + nx_*(jy + ny_*jz);
                    for (label p = s; p < e; ++p)
                    {
                        for (label q = start_[nb]; q < start_[nb + 1]; ++q)
                        {
                            test(sorted_[p], sorted_[q]);
                        }
                    }
                }
            }
        }
    }
}


namespace
{

struct appendPair
{
    Foam::contactList& list;
    void operator()(const Foam::label a, const Foam::label b) const
    {
        list.append(a, b);
    }
};

struct countPair
{
    Foam::label& n;
    void operator()(const Foam::label, const Foam::label) const
    {
        ++n;
    }
};

} // End anonymous namespace


void Foam::binGrid::pairs
(
    const demParticles& P,
    const label nLocal,
    const scalar skin,
    contactList& result
) const
{
    forEachPair(P, nLocal, skin, appendPair{result});
}


Foam::label Foam::binGrid::countPairs
(
    const demParticles& P,
    const label nLocal,
    const scalar skin
) const
{
    label n = 0;
    forEachPair(P, nLocal, skin, countPair{n});
    return n;
}
