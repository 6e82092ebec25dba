// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "diffusionSmoother.H"
#include "fvm.H"
#include "zeroGradientFvPatchFields.H"

template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::diffusionSmoother::smooth
(
    const Field<Type>& f,
    const word& name
) const
{
    typedef GeometricField<Type, fvPatchField, volMesh> fieldType;

    fieldType fs
    (
        IOobject
        (
            name + ":smooth",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh_,
        dimensioned<Type>(dimless, Zero),
        zeroGradientFvPatchField<Type>::typeName
    );
    fs.primitiveFieldRef() = f;
    fs.correctBoundaryConditions();

    fvMatrix<Type> eqn
    (
        fvm::Sp(dimensionedScalar("one", dimless, 1.0), fs)
      - fvm::laplacian
        (
            dimensionedScalar("L2", dimArea, sqr(length_)),
            fs,
            "laplacian(smoothing)"
        )
    );
    eqn.source() += mesh_.V().field()*f;

    eqn.solve(solverControls_);

    return tmp<Field<Type>>::New(fs.primitiveField());
}
