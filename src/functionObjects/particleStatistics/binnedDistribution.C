// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "binnedDistribution.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "error.H"

Foam::binnedDistribution::binnedDistribution
(
    const scalar lo,
    const scalar hi,
    const label nBins
)
:
    lo_(lo),
    hi_(hi),
    weight_(nBins > 0 ? nBins : 0, Zero),
    below_(0),
    above_(0),
    sumW_(0),
    sumWx_(0),
    sumWd2_(0),
    min_(GREAT),
    max_(-GREAT)
{
    if (!(hi > lo) || nBins < 1)
    {
        FatalErrorInFunction
            << "A distribution needs hi > lo and at least one bin, not ["
            << lo << ", " << hi << ") in " << nBins << " bins"
            << abort(FatalError);
    }
}


void Foam::binnedDistribution::reduce()
{
    Pstream::listCombineGather(weight_, plusEqOp<scalar>());
    Pstream::listCombineScatter(weight_);
    Foam::reduce(below_, sumOp<scalar>());
    Foam::reduce(above_, sumOp<scalar>());
    Foam::reduce(sumW_, sumOp<scalar>());
    Foam::reduce(sumWx_, sumOp<scalar>());
    Foam::reduce(min_, minOp<scalar>());
    Foam::reduce(max_, maxOp<scalar>());
}


void Foam::binnedDistribution::reduceSpread()
{
    Foam::reduce(sumWd2_, sumOp<scalar>());
}


Foam::scalar Foam::binnedDistribution::mean() const
{
    return sumW_ > 0 ? sumWx_/sumW_ : 0;
}


Foam::scalar Foam::binnedDistribution::stdDev() const
{
    return sumW_ > 0 ? ::sqrt(sumWd2_/sumW_) : 0;
}


Foam::scalar Foam::binnedDistribution::min() const
{
    return min_ <= max_ ? min_ : 0;
}


Foam::scalar Foam::binnedDistribution::max() const
{
    return min_ <= max_ ? max_ : 0;
}


void Foam::binnedDistribution::write
(
    Ostream& os,
    const word& quantity,
    const word& unit
) const
{
    const scalar w = binWidth();
    const scalar W = sumW_ > 0 ? sumW_ : 1;
    os  << "# Distribution of " << quantity << " [" << unit << "]: "
        << nBins() << " bins over [" << lo_ << ", " << hi_ << ")" << nl
        << "# weight " << sumW_ << ", below " << below_ << ", above "
        << above_ << nl
        << "# lower\tupper\tcentre\tweight\tfraction\tpdf [1/(" << unit << ")]"
        << nl;
    forAll(weight_, b)
    {
        const scalar l = binLower(b);
        os  << l << tab << l + w << tab << l + 0.5*w << tab << weight_[b]
            << tab << weight_[b]/W << tab << weight_[b]/(W*w) << nl;
    }
}
