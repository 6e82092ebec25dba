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


void Foam::binGrid::copySorted(const demParticles& P, const label nLocal)
{
    const label n = sorted_.size();
    xSorted_.setSize(n);
    rSorted_.setSize(n);
    localSorted_.setSize(n);
    for (label p = 0; p < n; ++p)
    {
        const label i = sorted_[p];
        xSorted_[p] = P.position[i];
        rSorted_[p] = P.radius[i];
        localSorted_[p] = (i < nLocal);
    }
}


template<bool Emit>
Foam::label Foam::binGrid::scanPairs
(
    const scalar skin,
    DynamicList<label>& A,
    DynamicList<label>& B,
    label n
) const
{
    const vector* __restrict__ x = xSorted_.cdata();
    const scalar* __restrict__ r = rSorted_.cdata();
    const char* __restrict__ local = localSorted_.cdata();
    const label* __restrict__ index = sorted_.cdata();
    const label* __restrict__ start = start_.cdata();

    // The bins' forward half of the 26 neighbours as contiguous runs of
    // the sorted particles: the next bin along x (joined to the rest of
    // the particle's own bin), the row of three bins at y + 1, and the
    // three rows at z + 1
    auto row = [&](const label ix, const label jy, const label jz, label& b0, label& b1)
    {
        const label base = nx_*(jy + ny_*jz);
        b0 = start[max(ix - 1, 0) + base];
        b1 = start[min(ix + 1, nx_ - 1) + base + 1];
    };

    label rowBegin[4];
    label rowEnd[4];
    for (label iz = 0; iz < nz_; ++iz)
    {
        for (label iy = 0; iy < ny_; ++iy)
        {
            for (label ix = 0; ix < nx_; ++ix)
            {
                const label bin = ix + nx_*(iy + ny_*iz);
                const label s = start[bin];
                const label e = start[bin + 1];
                if (s == e)
                {
                    continue;
                }

                const label ownEnd = start[bin + 1 + (ix + 1 < nx_)];
                label nRows = 0;
                label perParticle = ownEnd - s;
                if (iy + 1 < ny_)
                {
                    row(ix, iy + 1, iz, rowBegin[nRows], rowEnd[nRows]);
                    perParticle += rowEnd[nRows] - rowBegin[nRows];
                    ++nRows;
                }
                if (iz + 1 < nz_)
                {
                    for (label jy = max(iy - 1, 0); jy <= min(iy + 1, ny_ - 1); ++jy)
                    {
                        row(ix, jy, iz + 1, rowBegin[nRows], rowEnd[nRows]);
                        perParticle += rowEnd[nRows] - rowBegin[nRows];
                        ++nRows;
                    }
                }

                // Room for every candidate of the bin: the capacity first,
                // then DynamicList's doubling
                const label need = n + (e - s)*perParticle;
                if (Emit && need > A.size())
                {
                    const label room = max(need, A.capacity());
                    A.setSize(room);
                    B.setSize(room);
                }
                label* __restrict__ a = A.data();
                label* __restrict__ b = B.data();

                for (label p = s; p < e; ++p)
                {
                    const vector xp = x[p];
                    const scalar rp = r[p];
                    const char lp = local[p];
                    const label ip = index[p];

                    // The test of the earlier pair loop, range (r_p + r_q)
                    // + skin: the same pairs to the last bit
                    auto scan = [&](const label q0, const label q1)
                    {
                        for (label q = q0; q < q1; ++q)
                        {
                            const scalar range = rp + r[q] + skin;
                            const bool within =
                                magSqr(xp - x[q]) < range*range;
                            const bool counts = within & ((lp | local[q]) != 0);
                            if (Emit)
                            {
                                const label iq = index[q];
                                a[n] = min(ip, iq);
                                b[n] = max(ip, iq);
                            }
                            n += counts;
                        }
                    };

                    scan(p + 1, ownEnd);
                    for (label k = 0; k < nRows; ++k)
                    {
                        scan(rowBegin[k], rowEnd[k]);
                    }
                }
            }
        }
    }
    return n;
}


void Foam::binGrid::pairs
(
    const demParticles& P,
    const label nLocal,
    const scalar skin,
    contactList& result
)
{
    copySorted(P, nLocal);
    const label n0 = result.size();
    const label n = scanPairs<true>(skin, result.first, result.second, n0);
    result.first.setSize(n);
    result.second.setSize(n);
    result.completeEntries();
}


Foam::label Foam::binGrid::countPairs
(
    const demParticles& P,
    const label nLocal,
    const scalar skin
)
{
    copySorted(P, nLocal);
    DynamicList<label> none;
    return scanPairs<false>(skin, none, none, 0);
}
