// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "HancockSharpFit.H"
#include "IOmanip.H"

#include <cmath>
#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::HancockSharpFit::exponentModel>
Foam::HancockSharpFit::exponentModelNames
({
    { exponentModel::perTemperature, "perTemperature" },
    { exponentModel::linear, "linear" },
    { exponentModel::constant, "constant" },
});


// * * * * * * * * * * * * * * * Local functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The unit of n(T)'s slope in the internal parameters
const scalar nSlopeScale = 100;

//- Two temperatures are the same within this relative difference
const scalar sameT = 1e-9;

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::HancockSharpFit::refuse
(
    const label line,
    const std::string& msg
) const
{
    reductionCurves::error(source_, line, msg);
}


void Foam::HancockSharpFit::unpack
(
    const scalarField& p,
    scalar& lnkRef,
    scalar& e,
    scalar& m
) const
{
    lnkRef = p[0];
    e = iE_ >= 0 ? p[iE_] : e0_;
    m = iM_ >= 0 ? p[iM_] : m0_;
}


Foam::scalar Foam::HancockSharpFit::n
(
    const scalarField& p,
    const label curvei
) const
{
    const label g = group_[curvei];
    if (!fitN_)
    {
        return n0_[g];
    }
    switch (nModel_)
    {
        case exponentModel::perTemperature:
            return p[iN_ + g];
        case exponentModel::linear:
            return p[iN_] + p[iN_ + 1]*(groupT_[g] - Tref_)/nSlopeScale;
        default:
            return p[iN_];
    }
}


void Foam::HancockSharpFit::residuals
(
    const scalarField& p,
    scalarField& r,
    scalarRectangularMatrix* J
) const
{
    scalar lnkRef, e, m;
    unpack(p, lnkRef, e, m);
    if (J)
    {
        *J = Zero;
    }

    label row = 0;
    forAll(curves_, ci)
    {
        const curve& c = curves_[ci];
        const scalar nc = n(p, ci);
        const scalar dLnkdE = -(Tref_/c.T - 1);
        const scalar lnk = lnkRef + e*dLnkdE + m*std::log(c.yH2);
        forAll(c.t, k)
        {
            if (!(c.t[k] > 0))
            {
                continue;
            }
            const scalar lnu = lnk + std::log(c.t[k]);
            const scalar z = std::exp(nc*lnu);
            r[row] = -std::expm1(-z) - c.X[k];

            if (J)
            {
                const scalar dXdz = std::exp(-z);
                // d/d ln k
                const scalar dlnk = dXdz*nc*z;
                (*J)(row, 0) = dlnk;
                if (iE_ >= 0)
                {
                    (*J)(row, iE_) = dlnk*dLnkdE;
                }
                if (iM_ >= 0)
                {
                    (*J)(row, iM_) = dlnk*std::log(c.yH2);
                }
                if (fitN_)
                {
                    const scalar dn = dXdz*z*lnu;
                    const label g = group_[ci];
                    switch (nModel_)
                    {
                        case exponentModel::perTemperature:
                            (*J)(row, iN_ + g) = dn;
                            break;
                        case exponentModel::linear:
                            (*J)(row, iN_) = dn;
                            (*J)(row, iN_ + 1) =
                                dn*(groupT_[g] - Tref_)/nSlopeScale;
                            break;
                        default:
                            (*J)(row, iN_) = dn;
                    }
                }
            }
            ++row;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::HancockSharpFit::HancockSharpFit
(
    const List<curve>& curves,
    const fileName& source,
    const reductionLaws::HancockSharp& start,
    const exponentModel nModel,
    const wordList& hold
)
:
    source_(source),
    curves_(curves),
    nModel_(nModel),
    fitEa_(true),
    fitM_(true),
    fitN_(true),
    groupT_(),
    group_(curves.size(), -1),
    Tref_(0),
    e0_(0),
    m0_(start.hydrogenOrder()),
    n0_(),
    lnkRef0_(0),
    nPoints_(0),
    iE_(-1),
    iM_(-1),
    iN_(-1),
    nFree_(0)
{
    const wordList holdable({"activationEnergy", "n", "hydrogenOrder"});
    for (const word& h : hold)
    {
        if (!holdable.found(h))
        {
            FatalErrorInFunction
                << "Cannot hold " << h << " (fitting " << source_ << ")"
                << nl << "Valid parameters to hold are " << holdable
                << exit(FatalError);
        }
    }
    fitEa_ = !hold.found("activationEnergy");
    fitN_ = !hold.found("n");
    fitM_ = !hold.found("hydrogenOrder");

    if (curves_.empty())
    {
        refuse(0, "no curve to fit");
    }

    // Temperatures, hydrogen fractions, points
    scalarList yDistinct;
    scalar invT = 0;
    forAll(curves_, ci)
    {
        const curve& c = curves_[ci];
        forAll(groupT_, g)
        {
            if (mag(groupT_[g] - c.T) <= sameT*c.T)
            {
                group_[ci] = g;
            }
        }
        if (group_[ci] < 0)
        {
            group_[ci] = groupT_.size();
            groupT_.append(c.T);
        }
        bool newY = true;
        for (const scalar y : yDistinct)
        {
            newY = newY && mag(y - c.yH2) > sameT;
        }
        if (newY)
        {
            yDistinct.append(c.yH2);
        }

        label nc = 0;
        for (const scalar t : c.t)
        {
            nc += t > 0;
        }
        if (fitN_ && nc < 2)
        {
            refuse
            (
                c.line,
                "curve " + c.name + " has one point (after t = 0): the"
                " exponent n cannot be fitted from one point per curve;"
                " give the curve's points, or hold n (-hold '(n)') at the"
                " value of the kinetics"
            );
        }
        nPoints_ += nc;
        invT += nc/c.T;
    }
    Tref_ = nPoints_/invT;

    if (fitEa_ && groupT_.size() < 2)
    {
        refuse
        (
            0,
            "every curve is at T = " + std::string(Foam::name(groupT_[0])) + " K: the"
            " activation energy E_a needs curves at two temperatures or"
            " more; hold it (-hold '(activationEnergy)') at the value of"
            " the kinetics"
        );
    }
    if (fitN_ && nModel_ == exponentModel::linear && groupT_.size() < 2)
    {
        refuse
        (
            0,
            "every curve is at T = " + std::string(Foam::name(groupT_[0])) + " K: n linear in"
            " T needs curves at two temperatures or more (-exponent"
            " constant, or hold n)"
        );
    }
    if (fitM_ && yDistinct.size() < 2)
    {
        refuse
        (
            0,
            "every curve is at H2 " + std::string(Foam::name(yDistinct[0])) + ": the hydrogen"
            " order m needs curves at two hydrogen fractions or more; hold"
            " it (-hold '(hydrogenOrder)') at the value of the kinetics"
        );
    }

    // The parameters' places and start
    label np = 1;
    if (fitEa_)
    {
        iE_ = np++;
    }
    if (fitM_)
    {
        iM_ = np++;
    }
    n0_.setSize(groupT_.size());
    forAll(groupT_, g)
    {
        n0_[g] = start.n(groupT_[g]);
    }
    if (fitN_)
    {
        iN_ = np;
        np +=
            nModel_ == exponentModel::perTemperature ? groupT_.size()
          : nModel_ == exponentModel::linear ? 2 : 1;
    }
    nFree_ = np;

    if (nPoints_ < nFree_)
    {
        refuse
        (
            0,
            std::to_string(nPoints_) + " points (after t = 0) for "
          + std::to_string(nFree_) + " free parameters: give more points"
            " or hold parameters (-hold)"
        );
    }

    e0_ = start.activationEnergy()/(reductionLaws::HancockSharp::R*Tref_);
    lnkRef0_ = std::log(start.k(Tref_));

    scalarField p0(nFree_, Zero);
    p0[0] = lnkRef0_;
    if (iE_ >= 0) p0[iE_] = e0_;
    if (iM_ >= 0) p0[iM_] = m0_;
    if (fitN_)
    {
        switch (nModel_)
        {
            case exponentModel::perTemperature:
                forAll(groupT_, g)
                {
                    p0[iN_ + g] = n0_[g];
                }
                break;
            case exponentModel::linear:
                p0[iN_] = start.n(Tref_);
                p0[iN_ + 1] = 0;
                break;
            default:
                p0[iN_] = start.n(Tref_);
        }
    }

    const levenbergMarquardt lm
    (
        nPoints_, nFree_,
        [this]
        (const scalarField& p, scalarField& r, scalarRectangularMatrix* J)
        {
            residuals(p, r, J);
        },
        true
    );
    solution_ = lm.solve(p0);

    if (solution_.rank < nFree_)
    {
        // Name the parameters of the direction the data leave free
        wordList names(nFree_);
        names[0] = "k0";
        if (iE_ >= 0) names[iE_] = "activationEnergy";
        if (iM_ >= 0) names[iM_] = "hydrogenOrder";
        for (label j = iN_; fitN_ && j < nFree_; ++j)
        {
            names[j] = "n";
        }
        std::string which;
        forAll(names, j)
        {
            if (mag(solution_.nullDirection[j]) > 0.1)
            {
                which += (which.empty() ? "" : ", ") + names[j];
            }
        }
        refuse
        (
            0,
            "the curves do not fix the parameters (the Jacobian's rank is "
          + std::to_string(solution_.rank) + " of "
          + std::to_string(nFree_) + "): a combination of " + which
          + " is free; hold one of them (-hold) or add curves"
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::HancockSharpFit::parameter>
Foam::HancockSharpFit::parameters() const
{
    const scalarField& p = solution_.p;
    const scalarSquareMatrix& C = solution_.covariance;
    const bool err = hasErrors();
    const scalar R = reductionLaws::HancockSharp::R;

    scalar lnkRef, e, m;
    unpack(p, lnkRef, e, m);

    DynamicList<parameter> out;
    const auto add = [&out]
    (
        const word& name,
        const word& unit,
        const scalar value,
        const scalar standardError,
        const bool fitted
    )
    {
        parameter q;
        q.name = name;
        q.unit = unit;
        q.value = value;
        q.standardError = standardError;
        q.fitted = fitted;
        out.append(q);
    };

    // ln k0 = ln k_ref + e, E_a = R T_ref e
    const scalar lnk0 = lnkRef + e;
    scalar varLnk0 = 0;
    if (err)
    {
        varLnk0 = C(0, 0);
        if (iE_ >= 0)
        {
            varLnk0 += 2*C(0, iE_) + C(iE_, iE_);
        }
    }
    const scalar k0 = std::exp(lnk0);
    add("k0", "1/s", k0, k0*std::sqrt(varLnk0), true);
    add("ln(k0)", "-", lnk0, std::sqrt(varLnk0), true);
    add
    (
            "activationEnergy", "J/mol", R*Tref_*e,
            err && iE_ >= 0 ? R*Tref_*std::sqrt(C(iE_, iE_)) : 0,
            iE_ >= 0
    );
    add
    (
            "hydrogenOrder", "-", m,
            err && iM_ >= 0 ? std::sqrt(C(iM_, iM_)) : 0,
            iM_ >= 0
    );

    if (!fitN_)
    {
        forAll(groupT_, g)
        {
            add
            ("n(" + Foam::name(groupT_[g]) + "K)", "-", n0_[g], 0, false);
        }
    }
    else if (nModel_ == exponentModel::perTemperature)
    {
        forAll(groupT_, g)
        {
            add
            (
                    "n(" + Foam::name(groupT_[g]) + "K)", "-", p[iN_ + g],
                    err ? std::sqrt(C(iN_ + g, iN_ + g)) : 0, true
            );
        }
    }
    else if (nModel_ == exponentModel::linear)
    {
        add
        (
                "n(" + Foam::name(Tref_) + "K)", "-", p[iN_],
                err ? std::sqrt(C(iN_, iN_)) : 0, true
        );
        add
        (
                "dn/dT", "1/K", p[iN_ + 1]/nSlopeScale,
                err ? std::sqrt(C(iN_ + 1, iN_ + 1))/nSlopeScale : 0, true
        );
    }
    else
    {
        add
        ("n", "-", p[iN_], err ? std::sqrt(C(iN_, iN_)) : 0, true);
    }

    return List<parameter>(std::move(out));
}


Foam::scalar Foam::HancockSharpFit::correlationLnK0Ea() const
{
    if (!hasErrors() || iE_ < 0)
    {
        return 0;
    }
    const scalarSquareMatrix& C = solution_.covariance;
    // cov(ln k_ref + e, e) / (sd(ln k0) sd(e))
    const scalar varLnk0 = C(0, 0) + 2*C(0, iE_) + C(iE_, iE_);
    const scalar cov = C(0, iE_) + C(iE_, iE_);
    return cov/std::sqrt(varLnk0*C(iE_, iE_));
}


Foam::scalar Foam::HancockSharpFit::X(const label curvei, const scalar t) const
{
    if (!(t > 0))
    {
        return 0;
    }
    const curve& c = curves_[curvei];
    scalar lnkRef, e, m;
    unpack(solution_.p, lnkRef, e, m);
    const scalar lnk = lnkRef - e*(Tref_/c.T - 1) + m*std::log(c.yH2);
    return -std::expm1(-std::exp(n(solution_.p, curvei)*(lnk + std::log(t))));
}


Foam::scalar Foam::HancockSharpFit::rms(const label curvei) const
{
    const curve& c = curves_[curvei];
    scalar s = 0;
    label k = 0;
    forAll(c.t, i)
    {
        if (c.t[i] > 0)
        {
            s += sqr(X(curvei, c.t[i]) - c.X[i]);
            ++k;
        }
    }
    return std::sqrt(s/max(k, label(1)));
}


Foam::scalar Foam::HancockSharpFit::maxResidual(const label curvei) const
{
    const curve& c = curves_[curvei];
    scalar s = 0;
    forAll(c.t, i)
    {
        s = max(s, mag(X(curvei, c.t[i]) - c.X[i]));
    }
    return s;
}


void Foam::HancockSharpFit::writeKinetics(Ostream& os) const
{
    const List<parameter> ps(parameters());
    scalar lnkRef, e, m;
    unpack(solution_.p, lnkRef, e, m);

    os  << "kinetics" << nl << "{" << nl
        << "    law              HancockSharp;" << nl
        << setprecision(10)
        << "    k0               " << ps[0].value << ";    // [1/s]" << nl
        << "    activationEnergy " << ps[2].value << ";    // E_a [J/mol]"
        << nl
        << "    n                ";

    // n: a value, or (T n) pairs at the curves' temperatures (linear:
    // at the lowest and highest, the law holds n beyond them)
    scalarList Ts(groupT_);
    Foam::sort(Ts);
    if (fitN_ && nModel_ == exponentModel::constant)
    {
        os  << solution_.p[iN_] << ";";
    }
    else
    {
        scalarList pairsT(Ts);
        if (fitN_ && nModel_ == exponentModel::linear)
        {
            pairsT = scalarList({Ts.first(), Ts.last()});
        }
        os  << "(";
        forAll(pairsT, i)
        {
            // The first curve at this temperature gives n there
            label ci = 0;
            forAll(curves_, cj)
            {
                if (mag(curves_[cj].T - pairsT[i]) <= sameT*pairsT[i])
                {
                    ci = cj;
                    break;
                }
            }
            os  << (i ? " " : "") << "(" << pairsT[i] << " "
                << n(solution_.p, ci) << ")";
        }
        os  << ");";
    }
    os  << "    // [-] at T [K]" << nl
        << "    hydrogenOrder    " << m << ";    // m [-]" << nl
        << "}" << nl << setprecision(6);
}
