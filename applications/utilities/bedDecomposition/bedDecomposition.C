// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    bedDecomposition

Group
    sinterFoam/utilities

Description
    A decomposition of the mesh that balances the parcels, not the cells.

    In a fluidized bed the parcels carry the work (the DEM sub-steps and
    the contacts) and sit in the lower part of the column; a decomposition
    of the cells (simple, scotch on uniform weights) gives the subdomains
    equal cells and unequal parcels. This utility reads the parcels of a
    cloud at a time (a settled or bubbling bed), weighs each cell by

        w_c = 1 + parcelWeight n_c

    (n_c the parcels in cell c, parcelWeight the cost of a parcel against
    that of a gas cell), decomposes the mesh with these weights by the
    method named, and writes the result as constant/<dataFile>, the cell
    list that decomposePar reads with method manual:

        method          manual;
        manualCoeffs    { dataFile "cellDecomposition"; }

    The default method is hierarchical with n = (nx ny 1) (nx ny = N, ny
    the largest factor of N not above its square root): the column is cut
    in x into nx slabs of equal weight, each slab in y into ny: vertical
    cuts only, so that the bubbles and the parcels they carry, which rise
    and fall, cross no boundary on their way. (simple cuts x and y each
    once for the whole mesh and leaves the parcels of its pieces unequal
    beyond 2 subdomains. Debian's OpenFOAM ships scotch and metis as
    stubs; with a real scotch, -method scotch balances the same weights
    with fewest cut faces.)

    It prints, for the decomposition of system/decomposeParDict as it
    stands and for the weighted one: per subdomain the cells, the parcels
    and the halo parcels (the parcels in the cells of other subdomains
    that share a face with one of its cells: the ghosts it will receive,
    when the cells are about a contact range wide), and the largest over
    the mean of each. A bed that moves during a run unbalances again:
    -evaluate reports a written decomposition on the parcels of later
    times (the drift), and the utility run on a later time and
    decomposePar again (reconstructPar first) re-balance it at a restart.

Usage
    bedDecomposition [-time T] [-subdomains N] [-method hierarchical]
                     [-n "(4 2 1)"] [-parcelWeight 20] [-cloud cloud]
                     [-dataFile F] [-noWrite] [-evaluate] [-work [-skin 0.2]]

    \table
        Option        | Description                                   | Default
        -time         | the time of the parcels                       | latest
        -subdomains   | number of subdomains, >= 1                    | numberOfSubdomains of decomposeParDict
        -method       | a method that balances weights: hierarchical, simple (or scotch where it is not a stub) | hierarchical
        -n            | the cuts of hierarchical and simple, nx ny nz = N | (nx ny 1), nx ny = N
        -parcelWeight | a parcel's cost against a cell's [-], >= 0    | 20
        -cloud        | the cloud's name                              | the only cloud at that time
        -dataFile     | the file written in constant/                 | cellDecomposition
        -noWrite      | report only                                   | off
        -evaluate     | report the balance of constant/<dataFile> on the parcels of every time selected (-time 1:3) | off
        -work         | report the DEM engine's work per subdomain of the weighted decomposition, with its ghost rule (demHalo): parcels, ghosts received, neighbours, ghost bytes per sub-step, contacts, contacts across a boundary (evaluated on both sides), candidate pairs | off
        -skin         | with -work: the lists' skin over 2 r_max | 0.2
    \endtable

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "timeSelector.H"
#include "Time.H"
#include "polyMesh.H"
#include "IOdictionary.H"
#include "labelIOList.H"
#include "passiveParticleCloud.H"
#include "IOField.H"
#include "boundBox.H"
#include <cmath>
#include <cstdint>
#include <unordered_set>
#include "decompositionMethod.H"
#include "OSspecific.H"
#include "IOmanip.H"
#include <iomanip>
#include <sstream>

using namespace Foam;

namespace
{

//- Parcels per cell of a cloud at the mesh's current time
labelList parcelsPerCell(const polyMesh& mesh, const word& cloudName)
{
    passiveParticleCloud cloud(mesh, cloudName, false);
    labelList n(mesh.nCells(), 0);
    for (const passiveParticle& p : cloud)
    {
        ++n[p.cell()];
    }
    return n;
}


//- The name of the only cloud at the current time, or a fatal error
word onlyCloud(const polyMesh& mesh)
{
    const fileName dir(mesh.time().timePath()/cloud::prefix);
    const fileNameList clouds(readDir(dir, fileName::DIRECTORY));
    if (clouds.size() != 1)
    {
        FatalErrorInFunction
            << "Found " << clouds.size() << " clouds in " << dir
            << ": name one with -cloud. Clouds there: " << clouds
            << exit(FatalError);
    }
    return clouds[0];
}


//- Cells, parcels and halo parcels per subdomain, and max/mean of each
void report
(
    const word& what,
    const polyMesh& mesh,
    const labelList& domain,
    const label nDomains,
    const labelList& parcels
)
{
    labelList cells(nDomains, 0), own(nDomains, 0), halo(nDomains, 0);
    forAll(domain, celli)
    {
        ++cells[domain[celli]];
        own[domain[celli]] += parcels[celli];
    }

    // The cells of other subdomains next to each subdomain, each once
    List<labelHashSet> haloCells(nDomains);
    const labelList& owner = mesh.faceOwner();
    const labelList& neighbour = mesh.faceNeighbour();
    forAll(neighbour, facei)
    {
        const label a = owner[facei], b = neighbour[facei];
        if (domain[a] != domain[b])
        {
            haloCells[domain[a]].insert(b);
            haloCells[domain[b]].insert(a);
        }
    }
    forAll(haloCells, d)
    {
        for (const label celli : haloCells[d])
        {
            halo[d] += parcels[celli];
        }
    }

    auto imbalance = [nDomains](const labelList& v)
    {
        const scalar mean = scalar(sum(v))/nDomains;
        return mean > 0 ? max(v)/mean : 1.0;
    };

    Info<< what << nl
        << "    subdomain      cells    parcels  halo parcels" << nl;
    forAll(cells, d)
    {
        Info<< "    " << setw(9) << d << setw(11) << cells[d]
            << setw(11) << own[d] << setw(14) << halo[d] << nl;
    }
    // Three decimals, whatever the magnitude (1.005, 12.345)
    auto fixed3 = [](const scalar x)
    {
        std::ostringstream os;
        os << std::fixed << std::setprecision(3) << x;
        return word(os.str());
    };
    Info<< "    max/mean  " << setw(11) << fixed3(imbalance(cells))
        << setw(11) << fixed3(imbalance(own))
        << setw(14) << fixed3(imbalance(halo)) << nl
        << "    parcels in halos over all parcels: "
        << fixed3(sum(own) > 0 ? scalar(sum(halo))/sum(own) : 0.0) << nl
        << endl;
}

//- The DEM engine's work per subdomain with its ghost rule (demHalo): each
//  subdomain's region is the box of its cells and its parcels; it receives
//  as ghosts the other subdomains' parcels inside its region grown by the
//  contact range 2 r_max (1 + skin) that lie in one of the 27 bins (of the
//  range) around a bin holding one of its parcels; it evaluates every
//  pair with one of its own parcels, the pairs across a boundary on both
//  sides
void engineWork
(
    const polyMesh& mesh,
    const labelList& domain,
    const label nDomains,
    const word& cloudName,
    const scalar skinFraction
)
{
    passiveParticleCloud cloud(mesh, cloudName, false);
    IOField<scalar> d
    (
        IOobject
        (
            "d",
            mesh.time().timeName(),
            cloud::prefix/cloudName,
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    const label nP = cloud.size();
    if (d.size() != nP)
    {
        FatalErrorInFunction
            << "The cloud " << cloudName << " at " << mesh.time().timeName()
            << " has " << nP << " parcels and " << d.size() << " diameters"
            << exit(FatalError);
    }
    pointField x(nP);
    labelList proc(nP);
    scalar rMax = 0;
    {
        label i = 0;
        for (const passiveParticle& p : cloud)
        {
            x[i] = p.position();
            proc[i] = domain[p.cell()];
            rMax = max(rMax, d[i]/2);
            ++i;
        }
    }
    const scalar range = 2*rMax*(1 + skinFraction);

    // Regions: the boxes of the subdomains' cells (their faces' points)
    // and parcels
    List<boundBox> region(nDomains, boundBox::invertedBox);
    const labelList& owner = mesh.faceOwner();
    const labelList& neighbour = mesh.faceNeighbour();
    const pointField& pts = mesh.points();
    forAll(mesh.faces(), facei)
    {
        const face& f = mesh.faces()[facei];
        boundBox& a = region[domain[owner[facei]]];
        for (const label pi : f)
        {
            a.add(pts[pi]);
        }
        if (facei < neighbour.size())
        {
            boundBox& b = region[domain[neighbour[facei]]];
            for (const label pi : f)
            {
                b.add(pts[pi]);
            }
        }
    }
    forAll(x, i)
    {
        region[proc[i]].add(x[i]);
    }
    List<boundBox> grown(region);
    for (boundBox& b : grown)
    {
        b.min() -= vector::uniform(range);
        b.max() += vector::uniform(range);
    }

    // Ghosts received and neighbours (messages each way per sub-step)
    labelList ghosts(nDomains, 0), nbrs(nDomains, 0), own(nDomains, 0);
    forAll(x, i)
    {
        ++own[proc[i]];
    }
    for (label p = 0; p < nDomains; ++p)
    {
        for (label q = 0; q < nDomains; ++q)
        {
            if (q != p && grown[min(p, q)].overlaps(region[max(p, q)]))
            {
                ++nbrs[p];
            }
        }
    }
    // The engine's bins of the range, from the lowest corner of the
    // regions: a parcel is sent to a neighbour when it lies in the
    // neighbour's enlarged region and one of the 27 bins around its own
    // holds a parcel of the neighbour
    point origin(point::uniform(GREAT));
    for (const boundBox& b : region)
    {
        if (b.valid())
        {
            origin = min(origin, b.min());
        }
    }
    auto binKey = [&](const point& p, const label di, const label dj, const label dk)
    {
        const label i = label(std::floor((p.x() - origin.x())/range)) + di;
        const label j = label(std::floor((p.y() - origin.y())/range)) + dj;
        const label k = label(std::floor((p.z() - origin.z())/range)) + dk;
        return
            (std::uint64_t(i) & 0x1FFFFF)
          | ((std::uint64_t(j) & 0x1FFFFF) << 21)
          | ((std::uint64_t(k) & 0x1FFFFF) << 42);
    };
    List<std::unordered_set<std::uint64_t>> occupied(nDomains);
    forAll(x, i)
    {
        occupied[proc[i]].insert(binKey(x[i], 0, 0, 0));
    }
    labelList boxGhosts(nDomains, 0);
    forAll(x, i)
    {
        for (label p = 0; p < nDomains; ++p)
        {
            if
            (
                p != proc[i]
             && grown[min(p, proc[i])].overlaps(region[max(p, proc[i])])
             && grown[p].contains(x[i])
            )
            {
                ++boxGhosts[p];
                bool near = false;
                for (label dk = -1; dk <= 1 && !near; ++dk)
                for (label dj = -1; dj <= 1 && !near; ++dj)
                for (label di = -1; di <= 1 && !near; ++di)
                {
                    near = occupied[p].count(binKey(x[i], di, dj, dk));
                }
                if (near)
                {
                    ++ghosts[p];
                }
            }
        }
    }

    // Touching pairs (contacts) and candidate pairs (within the lists'
    // reach, r_i + r_j + skin), own and across a boundary, by binning
    const scalar skin = skinFraction*2*rMax;
    const scalar h = 2*rMax + skin;
    boundBox all(x);
    const vector span(all.span());
    const label nx = max(label(span.x()/h), label(1));
    const label ny = max(label(span.y()/h), label(1));
    const label nz = max(label(span.z()/h), label(1));
    auto binOf = [&](const point& p, label& i, label& j, label& k)
    {
        i = min(label((p.x() - all.min().x())/span.x()*nx), nx - 1);
        j = min(label((p.y() - all.min().y())/span.y()*ny), ny - 1);
        k = min(label((p.z() - all.min().z())/span.z()*nz), nz - 1);
        i = max(i, label(0)); j = max(j, label(0)); k = max(k, label(0));
    };
    labelListList bins(nx*ny*nz);
    {
        List<DynamicList<label>> b(nx*ny*nz);
        forAll(x, n)
        {
            label i, j, k;
            binOf(x[n], i, j, k);
            b[i + nx*(j + ny*k)].append(n);
        }
        forAll(b, n)
        {
            bins[n].transfer(b[n]);
        }
    }
    labelList contacts(nDomains, 0), cross(nDomains, 0);
    labelList candidates(nDomains, 0);
    label nContacts = 0, nCross = 0;
    // The ghosts a subdomain needs: the other subdomains' parcels in a
    // candidate pair with one of its own
    List<boolList> needed(nDomains, boolList(nP, false));
    forAll(x, a)
    {
        label i, j, k;
        binOf(x[a], i, j, k);
        for (label dk = -1; dk <= 1; ++dk)
        for (label dj = -1; dj <= 1; ++dj)
        for (label di = -1; di <= 1; ++di)
        {
            const label ii = i + di, jj = j + dj, kk = k + dk;
            if (ii < 0 || jj < 0 || kk < 0 || ii >= nx || jj >= ny || kk >= nz)
            {
                continue;
            }
            for (const label b : bins[ii + nx*(jj + ny*kk)])
            {
                if (b <= a)
                {
                    continue;
                }
                const scalar dist = mag(x[a] - x[b]);
                const scalar sumR = (d[a] + d[b])/2;
                if (dist < sumR + skin)
                {
                    ++candidates[proc[a]];
                    if (proc[b] != proc[a])
                    {
                        ++candidates[proc[b]];
                        needed[proc[a]][b] = true;
                        needed[proc[b]][a] = true;
                    }
                }
                if (dist < sumR)
                {
                    ++nContacts;
                    ++contacts[proc[a]];
                    if (proc[b] != proc[a])
                    {
                        ++contacts[proc[b]];
                        ++cross[proc[a]];
                        ++cross[proc[b]];
                        ++nCross;
                    }
                }
            }
        }
    }

    labelList neededGhosts(nDomains, 0);
    forAll(needed, p)
    {
        for (const bool b : needed[p])
        {
            neededGhosts[p] += b;
        }
    }

    auto ratio = [nDomains](const labelList& v)
    {
        const scalar mean = scalar(sum(v))/nDomains;
        std::ostringstream os;
        os << std::fixed << std::setprecision(3)
           << (mean > 0 ? max(v)/mean : 1.0);
        return word(os.str());
    };
    Info<< "The DEM engine's work per subdomain (ghost range 2 r_max (1 + "
        << skinFraction << ") = " << range << " m; " << nP << " parcels, "
        << nContacts << " contacts):" << nl
        << "    subdomain    parcels     ghosts  neighbours  ghost bytes/sub-step"
        << "   contacts  across a boundary  candidate pairs" << nl;
    for (label p = 0; p < nDomains; ++p)
    {
        Info<< "    " << setw(9) << p << setw(11) << own[p] << setw(11)
            << ghosts[p] << setw(12) << nbrs[p] << setw(22)
            << 9*sizeof(scalar)*ghosts[p] << setw(11) << contacts[p]
            << setw(19) << cross[p] << setw(17) << candidates[p] << nl;
    }
    Info<< "    max/mean  " << setw(11) << ratio(own) << setw(11)
        << ratio(ghosts) << setw(12) << ratio(nbrs) << setw(22)
        << ratio(ghosts) << setw(11) << ratio(contacts) << setw(19)
        << ratio(cross) << setw(17) << ratio(candidates) << nl;
    // One line to parse (validation/benchmarks/scaling)
    Info<< "work: subdomains " << nDomains << " parcels " << nP
        << " maxParcels " << max(own) << " maxGhosts " << max(ghosts)
        << " sumGhosts " << sum(ghosts) << " maxNeighbours " << max(nbrs)
        << " maxGhostBytes " << 9*sizeof(scalar)*max(ghosts)
        << " contacts " << nContacts << " crossContacts " << nCross
        << " maxContacts " << max(contacts)
        << " maxCandidates " << max(candidates)
        << " sumCandidates " << sum(candidates)
        << " sumBoxGhosts " << sum(boxGhosts)
        << " maxNeededGhosts " << max(neededGhosts)
        << " sumNeededGhosts " << sum(neededGhosts) << nl
        << "    (ghosts needed, in a candidate pair with an own parcel: "
        << sum(neededGhosts) << " of the " << sum(ghosts) << " sent; the"
        << " enlarged boxes alone, the rule before the bins, sent "
        << sum(boxGhosts) << ")" << nl
        << endl;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Decompose the mesh so that the subdomains hold equal parcels:"
        " writes constant/cellDecomposition for decomposePar's manual"
        " method"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    timeSelector::addOptions(false, false);
    argList::addOption("subdomains", "N", "number of subdomains");
    argList::addOption("method", "name", "the weighted method (hierarchical)");
    argList::addOption("n", "(nx ny nz)", "the method's cuts ((nx ny 1))");
    argList::addOption
    (
        "parcelWeight", "w", "a parcel's cost against a cell's (20)"
    );
    argList::addOption("cloud", "name", "the cloud (the only one)");
    argList::addOption
    (
        "dataFile", "name", "file written in constant/ (cellDecomposition)"
    );
    argList::addBoolOption("noWrite", "report only");
    argList::addBoolOption
    (
        "work",
        "also report the DEM engine's work per subdomain of the weighted"
        " decomposition: parcels, ghosts, neighbours, ghost bytes per"
        " sub-step, contacts and those across a boundary"
    );
    argList::addOption
    (
        "skin", "fraction", "with -work: the lists' skin over 2 r_max (0.2)"
    );
    argList::addBoolOption
    (
        "evaluate",
        "report constant/<dataFile>'s balance on the parcels of every time"
        " selected (a drift as the bed moves)"
    );

    #include "setRootCase.H"
    #include "createTime.H"

    instantList times = timeSelector::select0(runTime, args);
    runTime.setTime(times.last(), times.size() - 1);

    polyMesh mesh
    (
        IOobject
        (
            polyMesh::defaultRegion,
            runTime.timeName(),
            runTime,
            IOobject::MUST_READ
        )
    );

    IOdictionary decomposeDict
    (
        IOobject
        (
            "decomposeParDict",
            runTime.system(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );

    const label nDomains =
        args.found("subdomains")
      ? args.get<label>("subdomains")
      : decomposeDict.get<label>("numberOfSubdomains");
    if (nDomains < 1)
    {
        FatalErrorInFunction
            << "Option -subdomains of bedDecomposition must be >= 1, not "
            << nDomains << exit(FatalError);
    }
    const scalar parcelWeight = args.getOrDefault<scalar>("parcelWeight", 20);
    if (!(parcelWeight >= 0))
    {
        FatalErrorInFunction
            << "Option -parcelWeight of bedDecomposition must be >= 0, not "
            << parcelWeight << ": a parcel's cost against a gas cell's"
            << exit(FatalError);
    }
    const word methodName(args.getOrDefault<word>("method", "hierarchical"));
    Vector<label> n(nDomains, 1, 1);
    if (args.found("n"))
    {
        n = args.get<Vector<label>>("n");
        if (n.x()*n.y()*n.z() != nDomains || min(n.x(), min(n.y(), n.z())) < 1)
        {
            FatalErrorInFunction
                << "Option -n of bedDecomposition: " << n << " must be"
                << " positive with a product of " << nDomains
                << " (the subdomains)" << exit(FatalError);
        }
    }
    else
    {
        // nx ny = N with ny the largest factor of N not above sqrt(N)
        for (label ny = 1; ny*ny <= nDomains; ++ny)
        {
            if (nDomains % ny == 0)
            {
                n = Vector<label>(nDomains/ny, ny, 1);
            }
        }
    }
    const word cloudName
    (
        args.found("cloud") ? args.get<word>("cloud") : onlyCloud(mesh)
    );
    const fileName dataFile
    (
        args.getOrDefault<fileName>("dataFile", "cellDecomposition")
    );

    // An existing decomposition on the parcels of each time selected
    if (args.found("evaluate"))
    {
        const labelIOList domain
        (
            IOobject
            (
                dataFile,
                mesh.facesInstance(),
                mesh,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        );
        if (domain.size() != mesh.nCells() || min(domain) < 0)
        {
            FatalErrorInFunction
                << "The decomposition " << domain.objectPath() << " has "
                << domain.size() << " entries from " << min(domain)
                << ": it needs one subdomain >= 0 for each of the mesh's "
                << mesh.nCells() << " cells" << exit(FatalError);
        }
        const label nDom = max(domain) + 1;
        for (const instant& t : times)
        {
            runTime.setTime(t, 0);
            report
            (
                "The decomposition " + dataFile + " (" + Foam::name(nDom)
              + " subdomains) on the parcels at " + runTime.timeName()
              + " s:",
                mesh, domain, nDom, parcelsPerCell(mesh, cloudName)
            );
        }
        Info<< "End" << nl << endl;
        return 0;
    }

    const labelList parcels(parcelsPerCell(mesh, cloudName));
    Info<< "Cloud " << cloudName << " at " << runTime.timeName() << " s: "
        << sum(parcels) << " parcels in " << mesh.nCells() << " cells; "
        << nDomains << " subdomains" << nl << endl;

    // The decomposition of decomposeParDict as it stands, for comparison
    {
        dictionary asIs(decomposeDict);
        const word given(asIs.get<word>("method"));
        if (nDomains != asIs.get<label>("numberOfSubdomains"))
        {
            asIs.set("numberOfSubdomains", nDomains);
            // A split in one direction, along x, as the tutorials' n (2 1 1)
            for (const word& c : {word("coeffs"), word(given + "Coeffs")})
            {
                if (asIs.isDict(c) && asIs.subDict(c).found("n"))
                {
                    asIs.subDict(c).set("n", Vector<label>(nDomains, 1, 1));
                    Info<< "decomposeParDict: " << c << " n set to ("
                        << nDomains << " 1 1) for " << nDomains
                        << " subdomains" << nl;
                }
            }
        }
        if (given == "manual")
        {
            Info<< "decomposeParDict: method manual (this utility's own"
                << " result or another): not compared" << nl << endl;
        }
        else
        {
            autoPtr<decompositionMethod> m(decompositionMethod::New(asIs));
            report
            (
                "decomposeParDict as it stands (method " + given
              + ", cells unweighted):",
                mesh, m->decompose(mesh, mesh.cellCentres()), nDomains,
                parcels
            );
        }
    }

    // The parcels' weights
    scalarField weights(mesh.nCells(), 1);
    forAll(weights, celli)
    {
        weights[celli] += parcelWeight*parcels[celli];
    }

    dictionary weighted(decomposeDict);
    weighted.set("numberOfSubdomains", nDomains);
    weighted.set("method", methodName);
    {
        dictionary coeffs;
        coeffs.set("n", n);
        coeffs.set("order", word("xyz"));
        weighted.set("coeffs", coeffs);
        weighted.remove(methodName + "Coeffs");
    }
    autoPtr<decompositionMethod> method(decompositionMethod::New(weighted));
    const labelList domain
    (
        method->decompose(mesh, mesh.cellCentres(), weights)
    );
    report
    (
        "Weighted by the parcels (method " + methodName + ", n "
      + Foam::name(n) + ", cell weight 1 + " + Foam::name(parcelWeight)
      + " x parcels):",
        mesh, domain, nDomains, parcels
    );

    if (args.found("work"))
    {
        const scalar skin = args.getOrDefault<scalar>("skin", 0.2);
        if (!(skin >= 0))
        {
            FatalErrorInFunction
                << "Option -skin of bedDecomposition must be >= 0, not "
                << skin << exit(FatalError);
        }
        engineWork(mesh, domain, nDomains, cloudName, skin);
    }

    if (!args.found("noWrite"))
    {
        labelIOList out
        (
            IOobject
            (
                dataFile,
                mesh.facesInstance(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            domain
        );
        out.write();
        Info<< "Wrote " << out.objectPath() << nl
            << "decomposePar reads it with, in system/decomposeParDict:"
            << nl << "    numberOfSubdomains " << nDomains << ';' << nl
            << "    method          manual;" << nl
            << "    manualCoeffs    { dataFile " << dataFile << "; }"
            << nl << endl;
    }

    Info<< "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
