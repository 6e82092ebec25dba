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

        w_c = 1 + parcelWeight n_c + contactWeight k_c

    (n_c the parcels in cell c, k_c the contacts of its parcels, each
    contact counted half in the cell of each of its two parcels;
    parcelWeight and contactWeight the cost of a parcel and of a contact
    against that of a gas cell: the packed parts of a bubbling bed hold
    more contacts per parcel than the bubbles, and the contact loop is
    most of a DEM step), decomposes the mesh with these weights by the
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
                     [-n "(4 2 1)"] [-parcelWeight 20] [-contactWeight 0]
                     [-cloud cloud]
                     [-dataFile F] [-noWrite] [-evaluate] [-work [-skin 0.2]]

    \table
        Option        | Description                                   | Default
        -time         | the time of the parcels                       | latest
        -subdomains   | number of subdomains, >= 1                    | numberOfSubdomains of decomposeParDict
        -method       | a method that balances weights: hierarchical, simple (or scotch where it is not a stub) | hierarchical
        -n            | the cuts of hierarchical and simple, nx ny nz = N | (nx ny 1), nx ny = N
        -parcelWeight | a parcel's cost against a cell's [-], >= 0    | 20
        -contactWeight | a contact's cost against a cell's [-], >= 0 | 0
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

//- The value of a cost option (default if absent), fatal if negative
scalar costOption
(
    const argList& args,
    const word& name,
    const scalar deflt,
    const word& whose
)
{
    const scalar w = args.getOrDefault<scalar>(name, deflt);
    if (!(w >= 0))
    {
        FatalErrorInFunction
            << "Option -" << name << " of bedDecomposition must be >= 0, not "
            << w << ": " << whose << " cost against a gas cell's"
            << exit(FatalError);
    }
    return w;
}


#include "engineWork.H"

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
    argList::addOption
    (
        "contactWeight", "w",
        "a contact's cost against a cell's, each counted half in the cell"
        " of each of its parcels (0)"
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
    const scalar parcelWeight =
        costOption(args, "parcelWeight", 20, "a parcel's");
    const scalar contactWeight =
        costOption(args, "contactWeight", 0, "a contact's");
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

    // The parcels' positions and diameters, read once when needed
    autoPtr<bedParcels> bed;
    auto parcelData = [&]() -> const bedParcels&
    {
        if (!bed.valid())
        {
            bed.reset(new bedParcels(mesh, cloudName));
        }
        return *bed;
    };

    // The parcels' (and the contacts') weights
    scalarField weights(mesh.nCells(), 1);
    forAll(weights, celli)
    {
        weights[celli] += parcelWeight*parcels[celli];
    }
    if (contactWeight > 0)
    {
        const scalarField contacts(contactsPerCell(mesh, parcelData()));
        Info<< "Contacts of the parcels (touching pairs): "
            << label(sum(contacts) + 0.5) << ", weight " << contactWeight
            << " each" << nl << endl;
        weights += contactWeight*contacts;
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
      + " x parcels"
      + (
            contactWeight > 0
          ? string(" + " + Foam::name(contactWeight) + " x contacts")
          : string()
        )
      + "):",
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
        engineWork(mesh, domain, nDomains, parcelData(), skin);
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
