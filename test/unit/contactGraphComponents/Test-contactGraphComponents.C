// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    Test-contactGraphComponents

Description
    contactGraphComponents on hand-built graphs with exact expected labels
    (the smallest identity of each component) and sizes.

    Serial: a chain of 5, a ring of 4, a star of 4 around a centre, a
    pair, a lone particle, and an edge between two ghosts (ignored).

    With -parallel on 2 processors, one global graph split over the two
    (particles p:i, p the processor): a chain 0:0-0:1-0:2-1:0-1:1 crossing
    once, a ring 0:3-1:3-1:4-0:4-0:3 crossing twice, 0:5-1:5-0:6 whose two
    parts on processor 0 meet only through processor 1, a chain
    1:6-1:7-0:7 whose smallest identity is on the other processor, and
    lone 1:2, 0:8. Each processor holds its own particles and, as ghosts,
    the other's particles its edges reach; the particles the other holds
    as ghosts are marked shared. The results must equal the serial run of
    the whole graph (all particles local), particle by particle.
*/

#include "argList.H"
#include "unitCheck.H"
#include "contactGraphComponents.H"
#include "IOstreams.H"
#include "Pstream.H"
#include <map>
#include <set>

using namespace Foam;

using unitTest::check;

namespace
{

typedef std::pair<demIdentity, demIdentity> edge2;

//- Components of a whole graph, every particle local (serial)
std::map<demIdentity, std::pair<demIdentity, label>> whole
(
    const std::vector<demIdentity>& ids,
    const std::vector<edge2>& edges
)
{
    std::map<demIdentity, label> index;
    for (size_t i = 0; i < ids.size(); ++i)
    {
        index[ids[i]] = label(i);
    }
    List<demIdentity> id(ids.size());
    forAll(id, i)
    {
        id[i] = ids[i];
    }
    labelList first(edges.size()), second(edges.size());
    forAll(first, k)
    {
        first[k] = index.at(edges[k].first);
        second[k] = index.at(edges[k].second);
    }
    const contactGraphComponents c(id, id.size(), first, second, boolList());
    std::map<demIdentity, std::pair<demIdentity, label>> out;
    forAll(id, i)
    {
        out[id[i]] = std::make_pair(c.labels()[i], c.sizes()[i]);
    }
    return out;
}


demIdentity I(const label p, const label i)
{
    return makeIdentity(p, i);
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::noCheckProcessorDirectories();
    argList args(argc, argv);

    if (!Pstream::parRun())
    {
        // Serial: ids 0..14 of processor 0, edges by hand
        std::vector<demIdentity> ids;
        for (label i = 0; i < 15; ++i)
        {
            ids.push_back(I(0, i));
        }
        const std::vector<edge2> edges =
        {
            // chain of 5: 0-1-2-3-4 (given out of order)
            {I(0, 3), I(0, 4)}, {I(0, 0), I(0, 1)}, {I(0, 2), I(0, 1)},
            {I(0, 2), I(0, 3)},
            // ring of 4: 5-6-7-8-5
            {I(0, 5), I(0, 6)}, {I(0, 6), I(0, 7)}, {I(0, 7), I(0, 8)},
            {I(0, 8), I(0, 5)},
            // star: centre 12, leaves 9, 10, 11
            {I(0, 12), I(0, 9)}, {I(0, 10), I(0, 12)}, {I(0, 12), I(0, 11)},
            // pair 13-14
            {I(0, 14), I(0, 13)}
        };
        const auto c = whole(ids, edges);
        const label expectLabel[15] =
            {0, 0, 0, 0, 0, 5, 5, 5, 5, 9, 9, 9, 9, 13, 13};
        const label expectSize[15] = {5, 5, 5, 5, 5, 4, 4, 4, 4, 4, 4, 4, 4, 2, 2};
        for (label i = 0; i < 15; ++i)
        {
            const auto& r = c.at(I(0, i));
            check("serial particle " + Foam::name(i) + ": label",
                identityIndex(r.first), expectLabel[i], 0);
            check("serial particle " + Foam::name(i) + ": size",
                r.second, expectSize[i], 0);
        }

        // Two ghosts (vertices 2, 3 of 4; 2 local) joined by an edge: left
        // to their owners, each local particle alone
        {
            List<demIdentity> id({I(0, 0), I(0, 1), I(1, 0), I(1, 1)});
            const labelList first({2}), second({3});
            const contactGraphComponents g(id, 2, first, second, boolList());
            check("edge between two ghosts ignored: size of local 0",
                g.sizes()[0], 1, 0);
            check("edge between two ghosts ignored: size of local 1",
                g.sizes()[1], 1, 0);
        }
        // A lone particle: itself, size 1
        {
            List<demIdentity> id({I(3, 7)});
            const contactGraphComponents g(id, 1, labelList(), labelList(), boolList());
            check("lone particle: its own label", scalar(g.labels()[0] == I(3, 7)), 1, 0);
            check("lone particle: size 1", g.sizes()[0], 1, 0);
        }
    }
    else
    {
        if (Pstream::nProcs() != 2)
        {
            FatalErrorInFunction << "Run on 2 processors" << exit(FatalError);
        }
        const label me = Pstream::myProcNo();

        // The global graph
        const std::vector<edge2> edges =
        {
            {I(0, 0), I(0, 1)}, {I(0, 1), I(0, 2)}, {I(0, 2), I(1, 0)},
            {I(1, 0), I(1, 1)},
            {I(0, 3), I(1, 3)}, {I(1, 3), I(1, 4)}, {I(1, 4), I(0, 4)},
            {I(0, 4), I(0, 3)},
            {I(0, 5), I(1, 5)}, {I(1, 5), I(0, 6)},
            {I(1, 6), I(1, 7)}, {I(1, 7), I(0, 7)}
        };
        std::vector<demIdentity> all;
        for (label i = 0; i < 9; ++i)
        {
            all.push_back(I(0, i));
        }
        for (label i = 0; i < 8; ++i)
        {
            all.push_back(I(1, i));
        }
        const auto expected = whole(all, edges);

        // This processor: its particles, then the other's its edges reach
        std::vector<demIdentity> ids;
        for (const demIdentity id : all)
        {
            if (identityProc(id) == me)
            {
                ids.push_back(id);
            }
        }
        const label nLocal = ids.size();
        std::set<demIdentity> ghosts, shared;
        for (const edge2& e : edges)
        {
            const bool a = identityProc(e.first) == me;
            const bool b = identityProc(e.second) == me;
            if (a != b)
            {
                ghosts.insert(a ? e.second : e.first);
                shared.insert(a ? e.first : e.second);
            }
        }
        ids.insert(ids.end(), ghosts.begin(), ghosts.end());
        std::map<demIdentity, label> index;
        for (size_t i = 0; i < ids.size(); ++i)
        {
            index[ids[i]] = label(i);
        }
        DynamicList<label> first, second;
        for (const edge2& e : edges)
        {
            if (index.count(e.first) && index.count(e.second))
            {
                first.append(index.at(e.first));
                second.append(index.at(e.second));
            }
        }
        List<demIdentity> id(ids.size());
        forAll(id, i)
        {
            id[i] = ids[i];
        }
        boolList isShared(nLocal, false);
        for (label i = 0; i < nLocal; ++i)
        {
            isShared[i] = shared.count(ids[i]) > 0;
        }
        const contactGraphComponents c(id, nLocal, first, second, isShared);

        for (label i = 0; i < nLocal; ++i)
        {
            const auto& r = expected.at(ids[i]);
            const string who =
                "processor " + Foam::name(me) + ", particle "
              + Foam::name(identityProc(ids[i])) + ':'
              + Foam::name(identityIndex(ids[i]));
            check(who + ": label as serial",
                scalar(c.labels()[i] == r.first), 1, 0);
            check(who + ": size as serial", c.sizes()[i], r.second, 0);
        }

        // And the expected values themselves, by hand
        const std::pair<demIdentity, label> hand[][2] =
        {
            {{I(0, 0), 0}, {I(0, 0), 5}}, {{I(1, 1), 0}, {I(0, 0), 5}},
            {{I(1, 4), 0}, {I(0, 3), 4}}, {{I(0, 6), 0}, {I(0, 5), 3}},
            {{I(1, 6), 0}, {I(0, 7), 3}}, {{I(1, 2), 0}, {I(1, 2), 1}},
            {{I(0, 8), 0}, {I(0, 8), 1}}
        };
        for (const auto& h : hand)
        {
            const auto& r = expected.at(h[0].first);
            check("by hand: label of " + Foam::name(identityProc(h[0].first))
                + ':' + Foam::name(identityIndex(h[0].first)),
                scalar(r.first == h[1].first), 1, 0);
            check("by hand: size", r.second, h[1].second, 0);
        }
    }

    const label nFailed = returnReduce(unitTest::nFailed(), sumOp<label>());
    Info<< nl << (nFailed ? "FAILED: " : "passed: ") << nFailed
        << " failed check(s)" << endl;
    return nFailed ? 1 : 0;
}
