// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "demWalls.H"

Foam::demWalls::demWalls
(
    const pointField& points,
    const faceList& faces,
    const labelUList& material
)
:
    points_(points),
    faces_(faces),
    normals_(faces.size()),
    boxes_(faces.size()),
    material_(material.empty() ? labelList(faces.size(), Zero) : labelList(material)),
    binnedRange_(-1),
    binWidth_(0),
    nx_(0),
    ny_(0),
    nz_(0)
{
    if (material_.size() != faces_.size())
    {
        FatalErrorInFunction
            << material_.size() << " wall materials for " << faces_.size()
            << " faces" << exit(FatalError);
    }
    cornerStart_.setSize(faces_.size() + 1);
    cornerStart_[0] = 0;
    forAll(faces_, f)
    {
        normals_[f] = faces_[f].unitNormal(points_);
        boxes_[f] = boundBox(points_, faces_[f], false);
        cornerStart_[f + 1] = cornerStart_[f] + faces_[f].size();
    }
    corners_.setSize(cornerStart_.last());
    forAll(faces_, f)
    {
        forAll(faces_[f], e)
        {
            corners_[cornerStart_[f] + e] = points_[faces_[f][e]];
        }
    }
}


bool Foam::demWalls::beyondPlane
(
    const label f,
    const point& x,
    const scalar reach
) const
{
    // The closest point lies in the plane, at least as far as the plane;
    // the margin covers the rounding of both distances
    const scalar above = (x - corners_[cornerStart_[f]]) & normals_[f];
    return mag(above) > (1 + 1e-9)*reach;
}


Foam::point Foam::demWalls::closestPoint
(
    const label f,
    const point& x,
    bool& interior
) const
{
    const point* __restrict__ corner = corners_.cdata() + cornerStart_[f];
    const label nc = cornerStart_[f + 1] - cornerStart_[f];
    const vector& n = normals_[f];
    const point& p0 = corner[0];

    // Projection onto the plane, inside if on the inner side of every edge
    const point proj = x - ((x - p0) & n)*n;
    interior = true;
    for (label e = 0; e < nc; ++e)
    {
        const point& a = corner[e];
        const point& b = corner[e + 1 < nc ? e + 1 : 0];
        if ((((b - a) ^ (proj - a)) & n) < 0)
        {
            interior = false;
            break;
        }
    }
    if (interior)
    {
        return proj;
    }

    // Nearest point on the boundary edges
    point best = p0;
    scalar bestDist2 = GREAT;
    for (label e = 0; e < nc; ++e)
    {
        const point& a = corner[e];
        const point& b = corner[e + 1 < nc ? e + 1 : 0];
        const vector ab = b - a;
        const scalar t =
            min(max(((x - a) & ab)/max(magSqr(ab), VSMALL), scalar(0)), scalar(1));
        const point c = a + t*ab;
        const scalar d2 = magSqr(x - c);
        if (d2 < bestDist2)
        {
            bestDist2 = d2;
            best = c;
        }
    }
    return best;
}


void Foam::demWalls::buildBins(const scalar range) const
{
    binnedRange_ = range;

    binBox_ = boundBox::invertedBox;
    for (const boundBox& bb : boxes_)
    {
        binBox_.add(bb);
    }
    binBox_.min() -= vector::uniform(range);
    binBox_.max() += vector::uniform(range);

    // Bins about twice the range wide, at most 64 along the longest side
    const vector span = binBox_.span();
    binWidth_ = max(2*range, cmptMax(span)/64);
    nx_ = label(span.x()/binWidth_) + 1;
    ny_ = label(span.y()/binWidth_) + 1;
    nz_ = label(span.z()/binWidth_) + 1;
    const label nBins = nx_*ny_*nz_;
    const labelVector nb(nx_, ny_, nz_);

    // Bins overlapped by each face's box widened by the range: counted in
    // the first pass, filled in the second
    binStart_.setSize(nBins + 1);
    binStart_ = 0;
    labelList fill;
    for (label pass = 0; pass < 2; ++pass)
    {
        if (pass == 1)
        {
            for (label b = 0; b < nBins; ++b)
            {
                binStart_[b + 1] += binStart_[b];
            }
            binFaces_.setSize(binStart_[nBins]);
            fill = SubList<label>(binStart_, nBins);
        }
        forAll(boxes_, f)
        {
            labelVector lo, hi;
            for (direction d = 0; d < 3; ++d)
            {
                const scalar o = binBox_.min()[d];
                lo[d] = max(label((boxes_[f].min()[d] - range - o)/binWidth_), 0);
                hi[d] =
                    min(label((boxes_[f].max()[d] + range - o)/binWidth_), nb[d] - 1);
            }
            for (label k = lo.z(); k <= hi.z(); ++k)
            {
                for (label j = lo.y(); j <= hi.y(); ++j)
                {
                    for (label i = lo.x(); i <= hi.x(); ++i)
                    {
                        const label b = i + nx_*(j + ny_*k);
                        if (pass == 0)
                        {
                            ++binStart_[b + 1];
                        }
                        else
                        {
                            binFaces_[fill[b]++] = f;
                        }
                    }
                }
            }
        }
    }
}


void Foam::demWalls::candidates
(
    const demParticles& P,
    const label n,
    const scalar skin,
    contactList& result
) const
{
    if (faces_.empty())
    {
        return;
    }

    scalar rMax = 0;
    for (label i = 0; i < n; ++i)
    {
        rMax = max(rMax, P.radius[i]);
    }
    if (rMax + skin > binnedRange_)
    {
        buildBins(1.1*(rMax + skin));
    }

    // The faces listed in the particle's bin, then the exact tests
    const point& o = binBox_.min();
    for (label i = 0; i < n; ++i)
    {
        const point& x = P.position[i];
        if (!binBox_.contains(x))
        {
            continue;
        }
        const label b =
            min(label((x.x() - o.x())/binWidth_), nx_ - 1)
          + nx_
           *(
                min(label((x.y() - o.y())/binWidth_), ny_ - 1)
              + ny_*min(label((x.z() - o.z())/binWidth_), nz_ - 1)
            );

        const scalar range = P.radius[i] + skin;
        for (label k = binStart_[b]; k < binStart_[b + 1]; ++k)
        {
            const label f = binFaces_[k];
            const boundBox& bb = boxes_[f];
            if
            (
                x.x() < bb.min().x() - range || x.x() > bb.max().x() + range
             || x.y() < bb.min().y() - range || x.y() > bb.max().y() + range
             || x.z() < bb.min().z() - range || x.z() > bb.max().z() + range
            )
            {
                continue;
            }
            if (beyondPlane(f, x, range))
            {
                continue;
            }
            bool interior;
            const point c = closestPoint(f, x, interior);
            if (magSqr(x - c) < range*range)
            {
                result.append(i, f);
            }
        }
    }
}


void Foam::demWalls::update
(
    const demParticles& P,
    contactList& contacts,
    const bool gaps
) const
{
    const label nc = contacts.size();

    // Where the closest points of one particle's contacts lie, and the
    // points
    DynamicList<char>& kind = kind_;
    DynamicList<point>& closest = closest_;

    label s = 0;
    while (s < nc)
    {
        const label i = contacts.first[s];
        label e = s;
        while (e < nc && contacts.first[e] == i)
        {
            ++e;
        }

        const point& x = P.position[i];
        const scalar r = P.radius[i];

        kind.clear();
        closest.clear();
        bool anyInterior = false;
        for (label k = s; k < e; ++k)
        {
            const label f = contacts.second[k];
            if (!gaps && beyondPlane(f, x, r))
            {
                closest.append(x);
                kind.append(offPlane);
                continue;
            }
            bool in;
            closest.append(closestPoint(f, x, in));
            const bool touching = magSqr(x - closest.last()) < r*r;
            kind.append(in ? inside : onEdge);
            anyInterior = anyInterior || (in && touching);
        }

        for (label k = s; k < e; ++k)
        {
            if (kind[k - s] == offPlane)
            {
                contacts.overlap[k] = -GREAT;
                continue;
            }
            const bool interior = (kind[k - s] == inside);
            const point& cp = closest[k - s];
            const vector d = x - cp;
            const scalar dist = mag(d);

            bool counts = dist < r;
            if (counts && !interior)
            {
                // Edge or corner: only without an interior contact, and
                // once per point
                counts = !anyInterior;
                for (label q = s; counts && q < k; ++q)
                {
                    if
                    (
                        contacts.overlap[q] > 0
                     && magSqr(closest[q - s] - cp) < sqr(1e-9*r)
                    )
                    {
                        counts = false;
                    }
                }
            }

            if (counts)
            {
                contacts.normal[k] =
                    (dist > VSMALL) ? d/dist : -normals_[contacts.second[k]];
                contacts.overlap[k] = r - dist;
            }
            else
            {
                // No contact: the gap of a face the particle lies over
                // (indirect conduction), none through an edge or corner
                contacts.overlap[k] = interior ? r - dist : -GREAT;
            }
        }

        s = e;
    }
}


void Foam::demWalls::setTemperature(const scalarField& T)
{
    if (T.size() != faces_.size())
    {
        FatalErrorInFunction
            << T.size() << " wall temperatures for " << faces_.size()
            << " wall faces" << exit(FatalError);
    }
    temperature_ = T;
}


void Foam::demWalls::setConducting(const boolList& conducting)
{
    if (conducting.size() != faces_.size())
    {
        FatalErrorInFunction
            << conducting.size() << " conduction flags for " << faces_.size()
            << " wall faces" << exit(FatalError);
    }
    conducting_ = conducting;
}
