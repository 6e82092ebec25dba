// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

// Eigen before OpenFOAM's headers, so that no OpenFOAM macro reaches it
#include <Eigen/Dense>

#include "levenbergMarquardt.H"
#include "eigenViews.H"
#include "error.H"

#include <cmath>
#include <limits>

// * * * * * * * * * * * * * * * Local functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam::eigenViews;

typedef Eigen::MatrixXd eMatrix;
typedef Eigen::VectorXd eVector;

bool allFinite(const Foam::scalarField& f)
{
    for (const Foam::scalar x : f)
    {
        if (!std::isfinite(x))
        {
            return false;
        }
    }
    return true;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::levenbergMarquardt::levenbergMarquardt
(
    const label nResiduals,
    const label nParameters,
    const residualFunction& residuals,
    const bool analyticJacobian
)
:
    nResiduals_(nResiduals),
    nParameters_(nParameters),
    residuals_(residuals),
    analyticJacobian_(analyticJacobian)
{
    if (nParameters_ < 1 || nResiduals_ < nParameters_)
    {
        FatalErrorInFunction
            << "Least squares with " << nParameters_ << " parameters and "
            << nResiduals_ << " residuals: at least one parameter and as"
            << " many residuals as parameters are needed"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::levenbergMarquardt::evaluate
(
    const scalarField& p,
    scalarField& r,
    scalarRectangularMatrix& J
) const
{
    r.setSize(nResiduals_);
    J.setSize(nResiduals_, nParameters_);
    if (analyticJacobian_)
    {
        residuals_(p, r, &J);
        return;
    }

    residuals_(p, r, nullptr);
    const scalar h0 = std::cbrt(std::numeric_limits<scalar>::epsilon());
    scalarField pp(p);
    scalarField rPlus(nResiduals_), rMinus(nResiduals_);
    for (label j = 0; j < nParameters_; ++j)
    {
        const scalar h = h0*max(mag(p[j]), scalar(1));
        pp[j] = p[j] + h;
        residuals_(pp, rPlus, nullptr);
        pp[j] = p[j] - h;
        residuals_(pp, rMinus, nullptr);
        pp[j] = p[j];
        for (label i = 0; i < nResiduals_; ++i)
        {
            J(i, j) = (rPlus[i] - rMinus[i])/(2*h);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::levenbergMarquardt::solution::correlation
(
    const label i,
    const label j
) const
{
    if (covariance.m() == 0)
    {
        return 0;
    }
    const scalar d = std::sqrt(covariance(i, i)*covariance(j, j));
    return d > 0 ? covariance(i, j)/d : 0;
}


Foam::levenbergMarquardt::solution
Foam::levenbergMarquardt::solve(const scalarField& p0) const
{
    return solve(p0, controls());
}


Foam::levenbergMarquardt::solution Foam::levenbergMarquardt::solve
(
    const scalarField& p0,
    const controls& c
) const
{
    if (p0.size() != nParameters_)
    {
        FatalErrorInFunction
            << "Start of " << p0.size() << " parameters for a problem of "
            << nParameters_ << exit(FatalError);
    }

    solution s;
    scalarField p(p0);
    scalarField r;
    scalarRectangularMatrix Jf;
    evaluate(p, r, Jf);
    if (!allFinite(r))
    {
        FatalErrorInFunction
            << "The residuals at the start " << p0 << " are not finite"
            << exit(FatalError);
    }

    eVector x(view(p));
    eMatrix J(view(Jf));
    eVector rv(view(r));
    scalar S = rv.squaredNorm();
    eMatrix A(J.transpose()*J);
    eVector g(J.transpose()*rv);

    // Damping mu times the diagonal of A (floored, so a parameter the
    // residuals do not depend on yet still gets a finite step)
    const auto scaling = [](const eMatrix& A)
    {
        eVector d(A.diagonal());
        const scalar dMax = d.maxCoeff();
        for (Eigen::Index j = 0; j < d.size(); ++j)
        {
            d(j) = max(d(j), 1e-30*max(dMax, scalar(1e-300)));
        }
        return d;
    };
    eVector D(scaling(A));
    scalar mu = 1e-3;
    scalar nu = 2;

    label iter = 0;
    for (; iter < c.maxIterations; ++iter)
    {
        // Stops: an exact solve, a vanishing gradient
        if (S == 0)
        {
            s.converged = true;
            break;
        }
        const eVector gScaled(g.cwiseQuotient(D.cwiseSqrt()));
        if (gScaled.lpNorm<Eigen::Infinity>() <= c.gradientTolerance*std::sqrt(S))
        {
            s.converged = true;
            break;
        }

        eMatrix M(A);
        M.diagonal() += mu*D;
        const eVector h(M.ldlt().solve(-g));

        if (h.norm() <= c.stepTolerance*(x.norm() + c.stepTolerance))
        {
            s.converged = true;
            break;
        }

        const eVector xNew(x + h);
        scalarField rNew;
        scalarRectangularMatrix JNew;
        evaluate(field(xNew), rNew, JNew);
        const scalar SNew =
            allFinite(rNew) ? view(rNew).squaredNorm() : GREAT;

        // Ratio of the actual to the predicted decrease
        const scalar predicted = h.dot(mu*D.cwiseProduct(h) - g);
        const scalar rho = predicted > 0 ? (S - SNew)/predicted : -1;

        if (rho > 0 && SNew < S)
        {
            x = xNew;
            J = view(JNew);
            rv = view(rNew);
            S = SNew;
            A = J.transpose()*J;
            g = J.transpose()*rv;
            D = D.cwiseMax(scaling(A));
            mu *= max(1.0/3, 1 - std::pow(2*rho - 1, 3));
            nu = 2;
        }
        else
        {
            mu *= nu;
            nu *= 2;
            if (!std::isfinite(mu) || mu > 1e300)
            {
                // No step lowers S: a minimum to round-off
                s.converged = true;
                break;
            }
        }
    }

    s.p = field(x);
    s.residuals = field(rv);
    s.sumOfSquares = S;
    s.iterations = iter;
    s.degreesOfFreedom = nResiduals_ - nParameters_;

    // Rank and covariance from the SVD of the column-scaled Jacobian
    const eVector colNorm(columnNorms(J));
    const eMatrix Js(J*colNorm.cwiseInverse().asDiagonal());
    Eigen::JacobiSVD<eMatrix> svd(Js, Eigen::ComputeThinV);
    const eVector sv(svd.singularValues());
    const scalar tol =
        max(nResiduals_, nParameters_)*std::numeric_limits<scalar>::epsilon()
       *1e3*sv(0);
    s.rank = 0;
    for (Eigen::Index j = 0; j < sv.size(); ++j)
    {
        if (sv(j) > tol)
        {
            ++s.rank;
        }
    }
    const scalar svMin = sv(sv.size() - 1);
    s.conditionNumber = svMin > 0 ? sv(0)/svMin : GREAT;

    if (s.rank < nParameters_)
    {
        s.nullDirection = field(svd.matrixV().col(nParameters_ - 1));
    }
    else if (s.degreesOfFreedom > 0)
    {
        // C = s^2 (J^T J)^-1 = s^2 S^-1 V Sigma^-2 V^T S^-1 (S: column norms)
        const scalar s2 = S/s.degreesOfFreedom;
        const eMatrix W
        (
            colNorm.cwiseInverse().asDiagonal()*svd.matrixV()
           *sv.cwiseInverse().asDiagonal()
        );
        const eMatrix C(s2*W*W.transpose());
        s.covariance.setSize(nParameters_);
        s.standardErrors.setSize(nParameters_);
        for (label i = 0; i < nParameters_; ++i)
        {
            for (label j = 0; j < nParameters_; ++j)
            {
                s.covariance(i, j) = C(i, j);
            }
            s.standardErrors[i] = std::sqrt(C(i, i));
        }
    }

    return s;
}
