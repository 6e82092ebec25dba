// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "contactGraphComponents.H"
#include "Pstream.H"
#include "error.H"
#include <algorithm>
#include <unordered_map>
#include <vector>

namespace
{

//- Union-find with path halving and union by size
class disjointSets
{
    std::vector<Foam::label> parent_;
    std::vector<Foam::label> size_;

public:

    explicit disjointSets(const Foam::label n)
    :
        parent_(n),
        size_(n, 1)
    {
        for (Foam::label i = 0; i < n; ++i)
        {
            parent_[i] = i;
        }
    }

    Foam::label find(Foam::label i)
    {
        while (parent_[i] != i)
        {
            parent_[i] = parent_[parent_[i]];
            i = parent_[i];
        }
        return i;
    }

    void join(const Foam::label i, const Foam::label j)
    {
        Foam::label a = find(i);
        Foam::label b = find(j);
        if (a == b)
        {
            return;
        }
        if (size_[a] < size_[b])
        {
            std::swap(a, b);
        }
        parent_[b] = a;
        size_[a] += size_[b];
    }
};

} // End anonymous namespace


Foam::contactGraphComponents::contactGraphComponents
(
    const UList<demIdentity>& identity,
    const label nLocal,
    const labelUList& first,
    const labelUList& second,
    const boolUList& shared
)
:
    label_(nLocal),
    size_(nLocal, 0)
{
    const label nVertices = identity.size();
    if (first.size() != second.size() || nLocal > nVertices)
    {
        FatalErrorInFunction
            << "Inconsistent graph: " << first.size() << " first and "
            << second.size() << " second vertices of the edges, " << nLocal
            << " local of " << nVertices << " vertices" << abort(FatalError);
    }

    // 1. This processor's parts
    disjointSets sets(nVertices);
    forAll(first, k)
    {
        if (first[k] < nLocal || second[k] < nLocal)
        {
            sets.join(first[k], second[k]);
        }
    }

    // Per part (by its root): the smallest local identity, the local count
    // and whether it reaches another processor
    std::vector<demIdentity> partLabel(nVertices, -1);
    std::vector<label> partCount(nVertices, 0);
    std::vector<char> partBoundary(nVertices, 0);
    for (label i = 0; i < nLocal; ++i)
    {
        const label r = sets.find(i);
        if (partCount[r] == 0 || identity[i] < partLabel[r])
        {
            partLabel[r] = identity[i];
        }
        ++partCount[r];
        if (shared.size() && shared[i])
        {
            partBoundary[r] = 1;
        }
    }
    for (label g = nLocal; g < nVertices; ++g)
    {
        partBoundary[sets.find(g)] = 1;
    }

    for (label i = 0; i < nLocal; ++i)
    {
        const label r = sets.find(i);
        label_[i] = partLabel[r];
        size_[i] = partCount[r];
    }
    if (!Pstream::parRun())
    {
        return;
    }

    // 2. The parts that reach past the processor, to the master, as
    //    triples: (P, part label, local count) for each part,
    //    (G, part label, ghost identity) for each ghost in a part (a ghost
    //    without an edge is a part of its own, and skipped),
    //    (S, identity, part label) for each shared local particle
    const demIdentity partTag = 0, ghostTag = 1, sharedTag = 2;
    List<List<demIdentity>> sent(Pstream::nProcs());
    {
        DynamicList<demIdentity> mine;
        for (label v = 0; v < nVertices; ++v)
        {
            // Each part once, at its root
            if (sets.find(v) == v && partCount[v] > 0 && partBoundary[v])
            {
                mine.append(partTag);
                mine.append(partLabel[v]);
                mine.append(partCount[v]);
            }
        }
        for (label i = 0; i < nLocal; ++i)
        {
            if (shared.size() && shared[i])
            {
                mine.append(sharedTag);
                mine.append(identity[i]);
                mine.append(partLabel[sets.find(i)]);
            }
        }
        for (label g = nLocal; g < nVertices; ++g)
        {
            const label r = sets.find(g);
            if (partLabel[r] >= 0)
            {
                mine.append(ghostTag);
                mine.append(partLabel[r]);
                mine.append(identity[g]);
            }
        }
        sent[Pstream::myProcNo()].transfer(mine);
    }
    Pstream::gatherList(sent);

    // 3. On the master: join the parts through their ghosts
    List<demIdentity> result;
    if (Pstream::master())
    {
        std::unordered_map<demIdentity, label> partIndex;
        std::vector<demIdentity> parts;
        std::vector<label> counts;
        std::unordered_map<demIdentity, demIdentity> partOfShared;
        for (const List<demIdentity>& t : sent)
        {
            for (label k = 0; k + 2 < t.size(); k += 3)
            {
                if (t[k] == partTag)
                {
                    partIndex[t[k + 1]] = label(parts.size());
                    parts.push_back(t[k + 1]);
                    counts.push_back(label(t[k + 2]));
                }
                else if (t[k] == sharedTag)
                {
                    partOfShared[t[k + 1]] = t[k + 2];
                }
            }
        }
        disjointSets joined(label(parts.size()));
        for (const List<demIdentity>& t : sent)
        {
            for (label k = 0; k + 2 < t.size(); k += 3)
            {
                if (t[k] != ghostTag)
                {
                    continue;
                }
                const auto owner = partOfShared.find(t[k + 2]);
                if (owner == partOfShared.end())
                {
                    FatalErrorInFunction
                        << "Ghost " << identityProc(t[k + 2]) << ':'
                        << identityIndex(t[k + 2]) << " is not a shared"
                        << " particle of any processor" << abort(FatalError);
                }
                joined.join
                (
                    partIndex.at(t[k + 1]), partIndex.at(owner->second)
                );
            }
        }
        std::vector<demIdentity> rootLabel(parts.size(), -1);
        std::vector<label> rootCount(parts.size(), 0);
        for (size_t p = 0; p < parts.size(); ++p)
        {
            const label r = joined.find(label(p));
            if (rootLabel[r] < 0 || parts[p] < rootLabel[r])
            {
                rootLabel[r] = parts[p];
            }
            rootCount[r] += counts[p];
        }
        result.setSize(3*parts.size());
        for (size_t p = 0; p < parts.size(); ++p)
        {
            const label r = joined.find(label(p));
            result[3*p] = parts[p];
            result[3*p + 1] = rootLabel[r];
            result[3*p + 2] = rootCount[r];
        }
    }
    Pstream::scatter(result);

    // 4. Each part's component
    std::unordered_map<demIdentity, label> component;
    for (label k = 0; k + 2 < result.size(); k += 3)
    {
        component[result[k]] = k;
    }
    for (label i = 0; i < nLocal; ++i)
    {
        const auto c = component.find(label_[i]);
        if (c != component.end())
        {
            label_[i] = result[c->second + 1];
            size_[i] = label(result[c->second + 2]);
        }
    }
}
