// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

// Eigen before OpenFOAM's headers, so that no OpenFOAM macro reaches it
#include <Eigen/Dense>

#include "linearLeastSquares.H"
#include "eigenViews.H"
#include "error.H"

Foam::scalarField Foam::linearLeastSquares
(
    const scalarRectangularMatrix& A,
    const scalarField& b
)
{
    if (A.m() != b.size() || A.m() < A.n() || A.n() < 1)
    {
        FatalErrorInFunction
            << "Least squares of a " << A.m() << " x " << A.n()
            << " matrix with " << b.size() << " right-hand sides: rows >="
            << " columns >= 1 and one right-hand side per row are needed"
            << exit(FatalError);
    }
    const auto M = eigenViews::view(A);
    // Columns scaled to unit norm: the rank test does not depend on units
    const Eigen::VectorXd s(eigenViews::columnNorms(M));
    const Eigen::MatrixXd Ms(M*s.cwiseInverse().asDiagonal());
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Ms);
    if (qr.rank() < A.n())
    {
        FatalErrorInFunction
            << "Least squares: the " << A.m() << " x " << A.n() << " matrix"
            << " has rank " << qr.rank() << ": the data do not fix the "
            << A.n() << " unknowns" << exit(FatalError);
    }
    return eigenViews::field
    (
        s.cwiseInverse().asDiagonal()*qr.solve(eigenViews::view(b))
    );
}
