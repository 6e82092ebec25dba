// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "demWalls.H"

Foam::demWalls::demWalls(const pointField& points, const faceList& faces)
:
    points_(points),
    faces_(faces),
    normals_(faces.size()),
    boxes_(faces.size())
{
    forAll(faces_, f)
    {
        normals_[f] = faces_[f].unitNormal(points_);
        boxes_[f] = boundBox(points_, faces_[f], false);
    }
}


Foam::point Foam::demWalls::closestPoint
(
    const label f,
    const point& x,
    bool& interior
) const
{
    const face& fc = faces_[f];
    const vector& n = normals_[f];
    const point& p0 = points_[fc[0]];

    // Projection onto the plane, inside if on the inner side of every edge
    const point proj = x - ((x - p0) & n)*n;
    interior = true;
    forAll(fc, e)
    {
        const point& a = points_[fc[e]];
        const point& b = points_[fc.nextLabel(e)];
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
    forAll(fc, e)
    {
        const point& a = points_[fc[e]];
        const point& b = points_[fc.nextLabel(e)];
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


void Foam::demWalls::candidates
(
    const demParticles& P,
    const scalar skin,
    DynamicList<wallContact>& result
) const
{
    if (faces_.empty())
    {
        return;
    }

    // Particles against each face's box widened by the largest range: with
    // the faces few, a loop over faces per particle after a box test is
    // cheap; the boxes are tested first
    for (label i = 0; i < P.size(); ++i)
    {
        const point& x = P.position[i];
        const scalar range = P.radius[i] + skin;
        forAll(faces_, f)
        {
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
            bool interior;
            const point c = closestPoint(f, x, interior);
            if (magSqr(x - c) < range*range)
            {
                wallContact w;
                w.i = i;
                w.face = f;
                result.append(w);
            }
        }
    }
}


void Foam::demWalls::update
(
    const demParticles& P,
    UList<wallContact>& contacts
) const
{
    // Interior flags and closest points of one particle's contacts
    DynamicList<bool> interior;
    DynamicList<point> closest;

    label s = 0;
    while (s < contacts.size())
    {
        const label i = contacts[s].i;
        label e = s;
        while (e < contacts.size() && contacts[e].i == i)
        {
            ++e;
        }

        const point& x = P.position[i];
        const scalar r = P.radius[i];

        interior.clear();
        closest.clear();
        bool anyInterior = false;
        for (label k = s; k < e; ++k)
        {
            bool in;
            closest.append(closestPoint(contacts[k].face, x, in));
            const bool touching = magSqr(x - closest.last()) < r*r;
            interior.append(in);
            anyInterior = anyInterior || (in && touching);
        }

        for (label k = s; k < e; ++k)
        {
            wallContact& c = contacts[k];
            const point& cp = closest[k - s];
            const vector d = x - cp;
            const scalar dist = mag(d);

            bool counts = dist < r;
            if (counts && !interior[k - s])
            {
                // Edge or corner: only without an interior contact, and
                // once per point
                counts = !anyInterior;
                for (label q = s; counts && q < k; ++q)
                {
                    if
                    (
                        contacts[q].overlap > 0
                     && magSqr(closest[q - s] - cp) < sqr(1e-9*r)
                    )
                    {
                        counts = false;
                    }
                }
            }

            if (counts)
            {
                c.normal =
                    (dist > VSMALL) ? d/dist : -normals_[c.face];
                c.overlap = r - dist;
            }
            else
            {
                c.overlap = 0;
            }
        }

        s = e;
    }
}
