// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "diffusionSmoother.H"
#include "fvm.H"
#include "zeroGradientFvPatchFields.H"
#include "laplacianScheme.H"
#include "IStringStream.H"
#include "surfaceFields.H"
#include "profiling.H"

template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::diffusionSmoother::smooth
(
    const Field<Type>& f,
    const word& name
) const
{
    typedef GeometricField<Type, fvPatchField, volMesh> fieldType;
    addProfiling(smoothing, "diffusionSmoother::smooth");

    // Unregistered work fields
    auto io = [&](const word& fieldName)
    {
        return IOobject
        (
            fieldName,
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        );
    };

    fieldType fs
    (
        io(name + ":smooth"),
        mesh_,
        dimensioned<Type>(dimless, Zero),
        zeroGradientFvPatchField<Type>::typeName
    );
    fs.primitiveFieldRef() = f;
    fs.correctBoundaryConditions();

    // The uncorrected Gauss Laplacian on every mesh: a symmetric M-matrix
    // (no explicit non-orthogonal correction), so the smoothing is bounded
    // and its own transpose in the volume-weighted product
    IStringStream schemeData("Gauss linear uncorrected");
    tmp<fv::laplacianScheme<Type, scalar>> laplacian
    (
        fv::laplacianScheme<Type, scalar>::New(mesh_, schemeData)
    );
    const surfaceScalarField L2
    (
        io("smoothingLength2"),
        mesh_,
        dimensionedScalar("L2", dimArea, sqr(length_))
    );

    fvMatrix<Type> eqn
    (
        fvm::Sp(dimensionedScalar("one", dimless, 1.0), fs)
      - laplacian.ref().fvmLaplacian(L2, fs)
    );
    eqn.source() += mesh_.V().field()*f;

    eqn.solve(solverControls_);

    return tmp<Field<Type>>::New(fs.primitiveField());
}
