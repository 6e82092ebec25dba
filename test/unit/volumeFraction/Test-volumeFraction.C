// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    Test-volumeFraction

Description
    Checks of the volumeFraction methods (parcel volume -> cell solid
    volume fraction theta) on the mesh of the case:

    1. conservation: sum_c theta_c V_c = sum_p V_p over 300 particles at
       random positions, for every method, to 1e-12 relative (round-off);
    2. continuity: one particle moved in 4000 equal steps along a path that
       crosses faces (and processor boundaries when run in parallel).
       Per step, the largest change of theta_c V_c / V_p over the cells:
         - barycentric: must stay below 0.05. Its weights are linear in the
           position inside a tetrahedron and continuous across
           tetrahedra, so the change per step is of order
           step / (tetrahedron height), 0.0026 measured on this mesh; a jump at a
           face would be O(0.1 - 1);
         - cell: must reach 1 (the whole volume changes cell at a face),
           which shows that the check sees a jump when there is one.
    3. writes theta of the random particles as volScalarFields
       thetaBarycentric and thetaCell at the start time, for the
       serial / parallel comparison done by the run script.

    Exit code 0 when every check passes.
*/

#include "fvCFD.H"
#include "particle.H"
#include "Random.H"
#include "volumeFractionModel.H"
#include "diffusionSmoother.H"
#include "laplacianScheme.H"
#include "IStringStream.H"

using namespace Foam;

namespace
{

// Keep the particles (of the given positions) that lie on this processor
void locate
(
    const fvMesh& mesh,
    const List<point>& positions,
    PtrList<particle>& particles,
    List<label>& index
)
{
    particles.clear();
    DynamicList<label> found;
    forAll(positions, i)
    {
        const label celli = mesh.findCell(positions[i]);
        if (celli >= 0)
        {
            particles.append(new particle(mesh, positions[i], celli));
            found.append(i);
        }
    }
    index.transfer(found);
}


UPtrList<const particle> pointers(const PtrList<particle>& particles)
{
    UPtrList<const particle> ptrs(particles.size());
    forAll(particles, i)
    {
        ptrs.set(i, &particles[i]);
    }
    return ptrs;
}

} // End anonymous namespace


//- The smoothing of one field as OpenFOAM solves it alone:
//  f - div(L^2 grad f) = f0 (Gauss linear uncorrected, zero gradient on
//  the walls) with PCG/DIC to 1e-12, the smoother's controls
template<class Type>
Field<Type> smoothAlone
(
    const fvMesh& mesh,
    const Field<Type>& f0,
    const scalar L,
    const word& name
)
{
    GeometricField<Type, fvPatchField, volMesh> f
    (
        IOobject(name, mesh.time().timeName(), mesh),
        mesh,
        dimensioned<Type>(dimless, Zero),
        zeroGradientFvPatchField<Type>::typeName
    );
    f.primitiveFieldRef() = f0;
    f.correctBoundaryConditions();
    const surfaceScalarField L2
    (
        IOobject("L2", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar("L2", dimArea, sqr(L))
    );
    IStringStream scheme("Gauss linear uncorrected");
    tmp<fv::laplacianScheme<Type, scalar>> laplacian
    (
        fv::laplacianScheme<Type, scalar>::New(mesh, scheme)
    );
    fvMatrix<Type> eqn
    (
        fvm::Sp(dimensionedScalar("one", dimless, 1.0), f)
      - laplacian.ref().fvmLaplacian(L2, f)
    );
    eqn.source() += mesh.V().field()*f0;
    dictionary controls;
    controls.add("solver", "PCG");
    controls.add("preconditioner", "DIC");
    controls.add("tolerance", 1e-12);
    controls.add("relTol", 0.0);
    eqn.solve(controls);
    return Field<Type>(f.primitiveField());
}


int main(int argc, char *argv[])
{
    argList::noFunctionObjects();
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    bool ok = true;
    const boundBox bb(mesh.bounds());
    const scalar meanCellVolume =
        gSum(mesh.V().field())/returnReduce(mesh.nCells(), sumOp<label>());

    // The same random particles on every processor; each keeps its own
    Random rng(1234);
    const label nParticles = 300;
    List<point> positions(nParticles);
    scalarField volumes(nParticles);
    forAll(positions, i)
    {
        // Draw in the bounding box until the point lies in the mesh
        do
        {
            positions[i] =
                bb.min() + cmptMultiply(rng.sample01<vector>(), bb.span());
        }
        while (!returnReduce(mesh.findCell(positions[i]) >= 0, orOp<bool>()));

        volumes[i] = (0.5 + rng.sample01<scalar>())*1e-2*meanCellVolume;
    }

    PtrList<particle> particles;
    List<label> index;
    locate(mesh, positions, particles, index);
    const scalarField localVolumes(volumes, index);

    const label nFound = returnReduce(particles.size(), sumOp<label>());
    if (nFound != nParticles)
    {
        Info<< "FAIL: located " << nFound << " of " << nParticles
            << " particles" << endl;
        ok = false;
    }

    const wordList methods({"barycentric", "cell"});
    const wordList fieldNames({"thetaBarycentric", "thetaCell"});

    forAll(methods, methodi)
    {
        const word& method = methods[methodi];

        dictionary dict;
        dict.add("volumeFraction", method);
        autoPtr<volumeFractionModel> model(volumeFractionModel::New(mesh, dict));

        // 1. Conservation
        const scalarField theta(model->theta(pointers(particles), localVolumes));
        const scalar meshSolid = gSum(theta*mesh.V().field());
        const scalar particleSolid = sum(volumes);
        const scalar relErr = mag(meshSolid - particleSolid)/particleSolid;

        Info<< method << ": sum(theta V) = " << meshSolid
            << ", sum(V_p) = " << particleSolid
            << ", relative difference " << relErr << endl;

        if (relErr > 1e-12)
        {
            Info<< "FAIL: " << method << " does not conserve volume" << endl;
            ok = false;
        }

        // 2. Smoothing over two mean cell widths (eq 4.4): conservative to
        //    the solver tolerance and bounded by the unsmoothed extremes
        dictionary smoothDict;
        smoothDict.add("smoothingLength", 2*Foam::cbrt(meanCellVolume));
        const diffusionSmoother smoother(mesh, smoothDict);
        const scalarField thetaS(smoother.smooth<scalar>(theta, "theta"));
        const scalar smoothErr =
            mag(gSum(thetaS*mesh.V().field()) - meshSolid)/meshSolid;
        const scalar lo = gMin(theta);
        const scalar hi = gMax(theta);
        const scalar tolBound = 1e-12*hi;
        const bool bounded =
            gMin(thetaS) >= lo - tolBound && gMax(thetaS) <= hi + tolBound;

        Info<< method << ": smoothing changes sum(theta V) by " << smoothErr
            << " relative (tolerance 1e-10); theta " << lo << ".." << hi
            << " -> " << gMin(thetaS) << ".." << gMax(thetaS) << endl;

        if (smoothErr > 1e-10 || !bounded)
        {
            Info<< "FAIL: " << method << " smoothing not conservative or"
                << " not bounded" << endl;
            ok = false;
        }

        // 3. A cell field gathered to the particles with the transpose of
        //    (spreading, smoothing) gives exactly the cells' sum weighted by
        //    the smoothed theta: sum_p V_p g(x_p) = sum_c theta_c V_c g_c
        //    (the pressure-gradient force against the gas's, eq 5.5/5.2)
        vectorField g(mesh.nCells());
        {
            Random grng(77 + Pstream::myProcNo());
            forAll(g, celli)
            {
                g[celli] = grng.sample01<vector>() - 0.5*vector::one;
            }
        }
        const vectorField gS(smoother.smooth<vector>(g, "g"));
        const vectorField gPoints(model->pointValues(gS));
        vector parcelSum = Zero;
        forAll(particles, i)
        {
            parcelSum += localVolumes[i]*model->gather(particles[i], gS, gPoints);
        }
        reduce(parcelSum, sumOp<vector>());
        const vector cellSum = gSum(thetaS*mesh.V().field()*g);
        const scalar gatherErr = mag(parcelSum - cellSum)/mag(cellSum);

        Info<< method << ": sum_p V_p g(x_p) = " << parcelSum
            << ", sum_c theta V g = " << cellSum << ", relative difference "
            << gatherErr << " (tolerance 1e-9)" << endl;

        if (gatherErr > 1e-9)
        {
            Info<< "FAIL: " << method << " gather is not the transpose of"
                << " the spreading" << endl;
            ok = false;
        }

        // 4. Several fields smoothed as one block (diffusionSmoother's
        //    block solve) equal, to the bit, OpenFOAM's PCG/DIC solve of
        //    each alone (fvMatrix::solve of f - div(L^2 grad f) = f0 with
        //    the smoother's controls), serially and across processors
        {
            const scalar L = smoother.length();
            scalarField a(theta);
            scalarField b(sqr(theta) + 0.1);
            vectorField c(g);
            const scalarField aRef(smoothAlone(mesh, a, L, "a"));
            const scalarField bRef(smoothAlone(mesh, b, L, "b"));
            const vectorField cRef(smoothAlone(mesh, c, L, "c"));
            UPtrList<scalarField> scalars(2);
            scalars.set(0, &a);
            scalars.set(1, &b);
            UPtrList<vectorField> vectors(1);
            vectors.set(0, &c);
            smoother.smooth
            (
                scalars, wordList({"a", "b"}), vectors, wordList({"c"})
            );
            label differ = 0;
            forAll(a, celli)
            {
                differ +=
                    (a[celli] != aRef[celli]) + (b[celli] != bRef[celli])
                  + (c[celli] != cRef[celli]);
            }
            reduce(differ, sumOp<label>());
            Info<< method << ": two scalars and a vector smoothed as one"
                << " block: " << differ << " cell values differ from each"
                << " field's own PCG solve (tolerance 0: bit-identical)"
                << endl;
            if (differ != 0)
            {
                Info<< "FAIL: " << method << " block smoothing is not the"
                    << " fields' own solves" << endl;
                ok = false;
            }
        }

        volScalarField thetaField
        (
            IOobject
            (
                fieldNames[methodi],
                runTime.timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::AUTO_WRITE
            ),
            mesh,
            dimensionedScalar(dimless, Zero)
        );
        thetaField.primitiveFieldRef() = theta;
        thetaField.write();

        // 2. Continuity along a path through the mesh, off the diagonals
        const point start(bb.min() + cmptMultiply(vector(0.03, 0.11, 0.07), bb.span()));
        const point end(bb.min() + cmptMultiply(vector(0.95, 0.91, 0.87), bb.span()));
        const label nSteps = 4000;
        const scalar Vp = 1e-2*meanCellVolume;

        scalarField previous;
        scalar maxChange = 0;
        for (label stepi = 0; stepi <= nSteps; ++stepi)
        {
            const List<point> where(1, start + (end - start)*stepi/nSteps);
            PtrList<particle> one;
            List<label> oneIndex;
            locate(mesh, where, one, oneIndex);

            const scalarField thetaV
            (
                model->theta(pointers(one), scalarField(one.size(), Vp))
               *mesh.V().field()/Vp
            );

            if (stepi > 0)
            {
                maxChange = max(maxChange, gMax(mag(thetaV - previous)));
            }
            previous = thetaV;
        }

        Info<< method << ": largest change of theta V/V_p in one of "
            << nSteps << " steps along the path: " << maxChange << endl;

        if (method == "barycentric" && maxChange > 0.05)
        {
            Info<< "FAIL: barycentric theta jumps along the path" << endl;
            ok = false;
        }
        if (method == "cell" && maxChange < 1 - 1e-12)
        {
            Info<< "FAIL: the cell method should jump by 1 at a face" << endl;
            ok = false;
        }
    }

    if (!ok)
    {
        // (returning non-zero from main is lost: argList's clean-up exits 0)
        FatalErrorInFunction << "FAIL" << exit(FatalError);
    }

    Info<< "PASS" << endl;

    return 0;
}
