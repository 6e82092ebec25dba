// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

// Eigen before OpenFOAM's headers, so that no OpenFOAM macro reaches it
#include <Eigen/Dense>

#include "linearLeastSquares.H"
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
    Eigen::MatrixXd M(A.m(), A.n());
    Eigen::VectorXd v(b.size());
    for (label i = 0; i < A.m(); ++i)
    {
        for (label j = 0; j < A.n(); ++j)
        {
            M(i, j) = A(i, j);
        }
        v(i) = b[i];
    }
    // Columns scaled to unit norm: the rank test does not depend on units
    Eigen::VectorXd s(M.colwise().norm().transpose());
    for (Eigen::Index j = 0; j < s.size(); ++j)
    {
        if (!(s(j) > 0))
        {
            s(j) = 1;
        }
    }
    const Eigen::MatrixXd Ms(M*s.cwiseInverse().asDiagonal());
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Ms);
    if (qr.rank() < A.n())
    {
        FatalErrorInFunction
            << "Least squares: the " << A.m() << " x " << A.n() << " matrix"
            << " has rank " << qr.rank() << ": the data do not fix the "
            << A.n() << " unknowns" << exit(FatalError);
    }
    const Eigen::VectorXd x(s.cwiseInverse().asDiagonal()*qr.solve(v));
    scalarField out(A.n());
    for (label j = 0; j < A.n(); ++j)
    {
        out[j] = x(j);
    }
    return out;
}
