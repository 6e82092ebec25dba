// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "diffusionSmoother.H"
#include "keywordSource.H"
#include "fvm.H"
#include "zeroGradientFvPatchFields.H"
#include "laplacianScheme.H"
#include "IStringStream.H"
#include "surfaceFields.H"
#include "profiling.H"
#include "SolverPerformance.H"
#include "diffusionSmootherKernels.H"

namespace
{

using namespace Foam;
using namespace Foam::diffusionSmootherKernels;

//- The smoothing matrix, with the patches' parts that fvMatrix's own
//  solve adds (protected there)
class smoothingMatrix
:
    public fvScalarMatrix
{
public:

    explicit smoothingMatrix(const tmp<fvScalarMatrix>& t)
    :
        fvScalarMatrix(t)
    {}

    //- The patches' diagonal coefficients added to the diagonal
    void addPatchDiagonal()
    {
        addBoundaryDiag(diag(), 0);
    }

    //- The patches' source added (and, with couples, the coupled
    //  patches' neighbour values times their coefficients)
    void addPatchSource(scalarField& source, const bool couples) const
    {
        addBoundarySource(source, couples);
    }
};


//- Each entry summed over the processors, one message for all
void sumOverProcessors(List<scalar>& values)
{
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(values, plusEqOp<scalar>());
        Pstream::listCombineScatter(values);
    }
}


//- sum_i |a_i|, in order (as OpenFOAM's sumMag)
scalar sumMagnitude(const scalarField& a)
{
    scalar s = 0;
    for (const scalar x : a)
    {
        s += mag(x);
    }
    return s;
}


} // End anonymous namespace


Foam::diffusionSmoother::diffusionSmoother
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    mesh_(mesh),
    length_(dict.get<scalar>("smoothingLength")),
    tolerance_(1e-12),
    maxIter_(1000)
{
    if (!(length_ > 0))
    {
        FatalIOErrorInKeyword(dict, "smoothingLength")
            << "smoothingLength " << length_ << " must be > 0 [m]"
            << exit(FatalIOError);
    }
    // Longer than the domain's diagonal smooths the whole domain to its
    // mean: a length in other units than metres, or a slip
    const scalar diagonal = mesh.bounds().mag();
    if (length_ > diagonal)
    {
        FatalIOErrorInKeyword(dict, "smoothingLength")
            << "smoothingLength " << length_ << " [m] is longer than the"
            << " domain's diagonal " << diagonal << " m" << nl
            << "It would spread every source over the whole domain (lengths"
            << " are in metres)" << exit(FatalIOError);
    }
}


void Foam::diffusionSmoother::smooth
(
    UPtrList<scalarField>& scalars,
    const UList<word>& scalarNames,
    UPtrList<vectorField>& vectors,
    const UList<word>& vectorNames
) const
{
    addProfiling(smoothing, "diffusionSmoother::smooth");
    const label nScalars = scalars.size();
    const label nRhs = nScalars + 3*vectors.size();
    if (nRhs == 0)
    {
        return;
    }

    // The matrix M = V + L^2 A on a scalar work field: zero gradient at
    // the walls, the processor patches coupled
    volScalarField work
    (
        IOobject
        (
            "smoothing",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh_,
        dimensionedScalar(dimless, Zero),
        zeroGradientFvPatchScalarField::typeName
    );
    // The uncorrected Gauss Laplacian on every mesh: a symmetric M-matrix
    // (no explicit non-orthogonal correction), so the smoothing is bounded
    // and its own transpose in the volume-weighted product
    IStringStream schemeData("Gauss linear uncorrected");
    tmp<fv::laplacianScheme<scalar, scalar>> laplacian
    (
        fv::laplacianScheme<scalar, scalar>::New(mesh_, schemeData)
    );
    const surfaceScalarField L2
    (
        IOobject
        (
            "smoothingLength2",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh_,
        dimensionedScalar("L2", dimArea, sqr(length_))
    );
    smoothingMatrix M
    (
        fvm::Sp(dimensionedScalar("one", dimless, 1.0), work)
      - laplacian.ref().fvmLaplacian(L2, work)
    );
    M.addPatchDiagonal();

    const FieldField<Field, scalar>& bouCoeffs = M.boundaryCoeffs();
    const lduInterfaceFieldPtrsList interfaces =
        work.boundaryField().scalarInterfaces();
    const scalarField& V = mesh_.V().field();
    const label nCells = V.size();

    // Every right-hand side as OpenFOAM's segregated solve of the field
    // alone makes it: the field as the first guess, V f as the source (a
    // vector's: plus the coupled patches' neighbour values, minus them
    // again through the interfaces, as fvMatrix<vector> does)
    PtrList<scalarField> psi(nRhs);
    PtrList<scalarField> source(nRhs);
    wordList names(nRhs);
    for (label s = 0; s < nScalars; ++s)
    {
        psi.set(s, new scalarField(scalars[s]));
        source.set(s, new scalarField(V*scalars[s]));
        M.addPatchSource(source[s], false);
        names[s] = scalarNames[s] + ":smooth";
    }
    forAll(vectors, v)
    {
        for (direction c = 0; c < vector::nComponents; ++c)
        {
            const label m = nScalars + 3*v + c;
            psi.set(m, new scalarField(vectors[v].component(c)));
            source.set(m, new scalarField(V*psi[m]));
            names[m] =
                vectorNames[v] + ":smooth" + vector::componentNames[c];

            work.primitiveFieldRef() = psi[m];
            work.correctBoundaryConditions();
            M.addPatchSource(source[m], true);
            M.initMatrixInterfaces
            (
                true, bouCoeffs, interfaces, psi[m], source[m], c
            );
            M.updateMatrixInterfaces
            (
                true, bouCoeffs, interfaces, psi[m], source[m], c
            );
        }
    }

    // The diagonal-incomplete-Cholesky factor's reciprocal diagonal
    const label* const __restrict__ lo = M.lduAddr().lowerAddr().cdata();
    const label* const __restrict__ up = M.lduAddr().upperAddr().cdata();
    const scalar* const __restrict__ upper = M.upper().cdata();
    const label nFaces = M.upper().size();
    scalarField rD(M.diag());
    {
        scalar* __restrict__ d = rD.data();
        for (label face = 0; face < nFaces; ++face)
        {
            d[up[face]] -= upper[face]*upper[face]/d[lo[face]];
        }
        for (label cell = 0; cell < nCells; ++cell)
        {
            d[cell] = 1.0/d[cell];
        }
    }

    // The conjugate gradients of every field side by side
    List<solverPerformance> perf(nRhs);
    PtrList<scalarField> rA(nRhs);
    PtrList<scalarField> wA(nRhs);
    PtrList<scalarField> pA(nRhs);
    List<scalar> normFactor(nRhs);
    List<scalar> wArA(nRhs, solverPerformance::great_);
    List<scalar> sums(nRhs);
    boolList active(nRhs, false);
    const label nTotal = returnReduce(nCells, sumOp<label>());

    scalarField sumA(nCells);
    M.sumA(sumA, bouCoeffs, interfaces);

    // A psi, the residual, and the normalisation factor of lduMatrix's
    // solvers: sum |A psi - A xRef| + |b - A xRef|, xRef the mean of psi
    forAll(psi, m)
    {
        perf[m] = solverPerformance("DICPCG", names[m]);
        wA.set(m, new scalarField(nCells));
        pA.set(m, new scalarField(nCells));
        M.Amul(wA[m], psi[m], bouCoeffs, interfaces, 0);
        rA.set(m, new scalarField(source[m] - wA[m]));
        scalar s = 0;
        for (const scalar x : psi[m])
        {
            s += x;
        }
        sums[m] = s;
    }
    sumOverProcessors(sums);
    forAll(psi, m)
    {
        const scalar xRef = nTotal > 0 ? sums[m]/nTotal : scalar(0);
        const scalarField& Apsi = wA[m];
        const scalarField& b = source[m];
        scalar s = 0;
        for (label cell = 0; cell < nCells; ++cell)
        {
            const scalar ref = sumA[cell]*xRef;
            s += mag(Apsi[cell] - ref) + mag(b[cell] - ref);
        }
        sums[m] = s;
    }
    sumOverProcessors(sums);
    forAll(psi, m)
    {
        normFactor[m] = sums[m] + solverPerformance::small_;
        sums[m] = sumMagnitude(rA[m]);
    }
    sumOverProcessors(sums);
    label nActive = 0;
    forAll(psi, m)
    {
        perf[m].initialResidual() = sums[m]/normFactor[m];
        perf[m].finalResidual() = perf[m].initialResidual();
        active[m] = !perf[m].checkConvergence(tolerance_, 0);
        nActive += active[m];
    }

    // One iteration of every field still iterating, stage by stage, the
    // fields side by side in groups of up to four (each field's
    // arithmetic as in OpenFOAM's PCG with DIC: bit-identical)
    const scalar* const __restrict__ d = rD.cdata();
    const scalar* const __restrict__ lower = M.lower().cdata();
    const scalar* const __restrict__ diagonal = M.diag().cdata();
    bool coupled = false;
    forAll(interfaces, patchi)
    {
        coupled = coupled || interfaces.set(patchi);
    }
    labelList act(nRhs);
    List<scalar*> wMut(nRhs);
    List<scalar*> xMut(nRhs);
    List<scalar*> rMut(nRhs);
    List<const scalar*> wOf(nRhs);
    List<const scalar*> rOf(nRhs);
    List<const scalar*> pOf(nRhs);
    List<scalar> alpha(nRhs);
    List<scalar> out;
    List<scalar> buffer;
    while (nActive > 0)
    {
        label k = 0;
        forAll(psi, m)
        {
            if (active[m])
            {
                act[k] = m;
                wMut[k] = wA[m].data();
                wOf[k] = wA[m].cdata();
                rOf[k] = rA[m].cdata();
                pOf[k] = pA[m].cdata();
                ++k;
            }
        }
        out.setSize(k);

        // w = (L D L^T)^-1 r
        forGroupsOfFour
        (
            k, preconditionDIC,
            nCells, nFaces, lo, up, upper, d, wMut.cdata(), rOf.cdata(),
            buffer
        );

        // The search directions, p = w + beta p, and A p
        forGroupsOfFour
        (
            k, sumProducts, nCells, wOf.cdata(), rOf.cdata(), out.data()
        );
        sumOverProcessors(out);
        for (label j = 0; j < k; ++j)
        {
            const label m = act[j];
            // beta is the new w.r over the last one
            const scalar beta = out[j]/wArA[m];
            wArA[m] = out[j];
            scalar* __restrict__ p = pA[m].data();
            const scalar* __restrict__ w = wA[m].cdata();
            if (perf[m].nIterations() == 0)
            {
                for (label cell = 0; cell < nCells; ++cell)
                {
                    p[cell] = w[cell];
                }
            }
            else
            {
                for (label cell = 0; cell < nCells; ++cell)
                {
                    p[cell] = w[cell] + beta*p[cell];
                }
            }
        }
        // A p: the interior of all the fields side by side, then each
        // field's coupled patches (a processor patch's exchange serves
        // one field at a time)
        forGroupsOfFour
        (
            k, interiorProducts,
            nCells, nFaces, lo, up, lower, upper, diagonal, pOf.cdata(),
            wMut.cdata()
        );
        if (coupled)
        {
            for (label j = 0; j < k; ++j)
            {
                const label m = act[j];
                M.initMatrixInterfaces
                (
                    true, bouCoeffs, interfaces, pA[m], wA[m], 0
                );
                M.updateMatrixInterfaces
                (
                    true, bouCoeffs, interfaces, pA[m], wA[m], 0
                );
            }
        }

        // The step along them (a field whose step is singular stops), and
        // the new residuals
        forGroupsOfFour
        (
            k, sumProducts, nCells, wOf.cdata(), pOf.cdata(), out.data()
        );
        sumOverProcessors(out);
        label kStep = 0;
        for (label j = 0; j < k; ++j)
        {
            const label m = act[j];
            const scalar wApA = out[j];
            if (perf[m].checkSingularity(mag(wApA)/normFactor[m]))
            {
                active[m] = false;
                --nActive;
                continue;
            }
            act[kStep] = m;
            alpha[kStep] = wArA[m]/wApA;
            xMut[kStep] = psi[m].data();
            rMut[kStep] = rA[m].data();
            pOf[kStep] = pA[m].cdata();
            wOf[kStep] = wA[m].cdata();
            ++kStep;
        }
        out.setSize(kStep);
        forGroupsOfFour
        (
            kStep, stepAndResidual,
            nCells, xMut.cdata(), rMut.cdata(), pOf.cdata(), wOf.cdata(),
            alpha.cdata(), out.data()
        );
        sumOverProcessors(out);
        for (label j = 0; j < kStep; ++j)
        {
            const label m = act[j];
            perf[m].finalResidual() = out[j]/normFactor[m];
            if
            (
                ++perf[m].nIterations() >= maxIter_
             || perf[m].checkConvergence(tolerance_, 0)
            )
            {
                active[m] = false;
                --nActive;
            }
        }
    }

    // The results, and each solve's line and record, in order
    for (label s = 0; s < nScalars; ++s)
    {
        scalars[s] = psi[s];
        if (solverPerformance::debug)
        {
            perf[s].print(Info.masterStream(mesh_.comm()));
        }
        mesh_.setSolverPerformance(names[s], perf[s]);
    }
    forAll(vectors, v)
    {
        SolverPerformance<vector> perfVector
        (
            "fvMatrix<Type>::solveSegregated", vectorNames[v] + ":smooth"
        );
        for (direction c = 0; c < vector::nComponents; ++c)
        {
            const label m = nScalars + 3*v + c;
            vectors[v].replace(c, psi[m]);
            if (SolverPerformance<vector>::debug)
            {
                perf[m].print(Info.masterStream(mesh_.comm()));
            }
            perfVector.replace(c, perf[m]);
            perfVector.solverName() = perf[m].solverName();
        }
        mesh_.setSolverPerformance(vectorNames[v] + ":smooth", perfVector);
    }
}


namespace Foam
{

template<>
tmp<Field<scalar>> diffusionSmoother::smooth
(
    const Field<scalar>& f,
    const word& name
) const
{
    tmp<Field<scalar>> tresult(new Field<scalar>(f));
    UPtrList<scalarField> scalars(1);
    scalars.set(0, &tresult.ref());
    UPtrList<vectorField> vectors;
    smooth(scalars, wordList(1, name), vectors, wordList());
    return tresult;
}


template<>
tmp<Field<vector>> diffusionSmoother::smooth
(
    const Field<vector>& f,
    const word& name
) const
{
    tmp<Field<vector>> tresult(new Field<vector>(f));
    UPtrList<scalarField> scalars;
    UPtrList<vectorField> vectors(1);
    vectors.set(0, &tresult.ref());
    smooth(scalars, wordList(), vectors, wordList(1, name));
    return tresult;
}

} // End namespace Foam
