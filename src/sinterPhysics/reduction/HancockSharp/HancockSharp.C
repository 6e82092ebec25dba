// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "HancockSharp.H"
#include "keywordSource.H"
#include "knownKeywords.H"
#include "keywordRange.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>

namespace Foam
{
namespace reductionLaws
{
    defineTypeNameAndDebug(HancockSharp, 0);
    addToRunTimeSelectionTable(reductionLaw, HancockSharp, dictionary);
}
}


constexpr Foam::scalar Foam::reductionLaws::HancockSharp::R;


// * * * * * * * * * * * * * * * Local functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The keywords of the law's dictionary
const Foam::wordList lawKeywords
({
    "law", "k0", "activationEnergy", "n", "hydrogenOrder"
});

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::reductionLaws::HancockSharp::HancockSharp(const dictionary& dict)
:
    k0_
    (
        keywordRange::get
        (
            knownKeywords::checked(dict, lawKeywords), "k0", 0, GREAT,
            "the pre-exponential factor [1/s] of eq 3.4", true
        )
    ),
    Ea_(keywordRange::get(dict, "activationEnergy", 0, 1e6, "E_a [J/mol]")),
    m_
    (
        keywordRange::get
        (
            dict, "hydrogenOrder", 0, 5,
            "the order of k in the hydrogen mole fraction"
        )
    ),
    nT_(),
    n_()
{
    if (Ea_ > 0 && Ea_ < 1e3)
    {
        FatalIOErrorInKeyword(dict, "activationEnergy")
            << "Keyword activationEnergy " << Ea_ << " in " << dict.name()
            << " is in J/mol: " << Ea_ << " J/mol is implausibly small"
            << " (given in kJ/mol? the thesis's 61.02 kJ/mol is 61.02e3)"
            << exit(FatalIOError);
    }

    // n: a value or (T n) pairs
    const ITstream& is = dict.lookup("n");
    if (is.size() == 1 && is[0].isNumber())
    {
        nT_.setSize(1, scalar(0));
        n_.setSize(1, is[0].number());
    }
    else
    {
        const List<FixedList<scalar, 2>> pairs
        (
            dict.get<List<FixedList<scalar, 2>>>("n")
        );
        nT_.setSize(pairs.size());
        n_.setSize(pairs.size());
        forAll(pairs, i)
        {
            nT_[i] = pairs[i][0];
            n_[i] = pairs[i][1];
            if (!(nT_[i] >= 200) || (i > 0 && !(nT_[i] > nT_[i-1])))
            {
                FatalIOErrorInKeyword(dict, "n")
                    << "Keyword n in " << dict.name() << ": the temperatures"
                    << " of its (T n) pairs are in kelvin, >= 200 K and"
                    << " increasing, not " << nT_[i] << " (pair " << i << ")"
                    << exit(FatalIOError);
            }
        }
        if (pairs.empty())
        {
            FatalIOErrorInKeyword(dict, "n")
                << "Keyword n in " << dict.name() << " must be a value or"
                << " (T n) pairs, not an empty list" << exit(FatalIOError);
        }
    }
    forAll(n_, i)
    {
        keywordRange::checkElement
        (
            dict, "n", n_.size() > 1 ? "pair " + std::to_string(i) : "n",
            n_[i], 0, 10, "the Avrami exponent [-]", true
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::reductionLaws::HancockSharp::k(const scalar T) const
{
    return T > 0 ? k0_*std::exp(-Ea_/(R*T)) : 0;
}


Foam::scalar Foam::reductionLaws::HancockSharp::kEffective
(
    const scalar T,
    const scalar yH2
) const
{
    const scalar y = min(max(yH2, scalar(0)), scalar(1));
    return y > 0 ? k(T)*std::pow(y, m_) : 0;
}


Foam::scalar Foam::reductionLaws::HancockSharp::n(const scalar T) const
{
    const label last = n_.size() - 1;
    if (last == 0 || T <= nT_[0])
    {
        return n_[0];
    }
    if (T >= nT_[last])
    {
        return n_[last];
    }
    label i = 1;
    while (T > nT_[i])
    {
        ++i;
    }
    const scalar w = (T - nT_[i-1])/(nT_[i] - nT_[i-1]);
    return (1 - w)*n_[i-1] + w*n_[i];
}


Foam::scalar Foam::reductionLaws::HancockSharp::advance
(
    const scalar X,
    const scalar T,
    const scalar yH2,
    const scalar dt
) const
{
    if (X >= 1)
    {
        return 1;
    }
    const scalar Xc = max(X, scalar(0));
    const scalar nT = n(T);
    const scalar theta =
        (Xc > 0 ? std::pow(-std::log1p(-Xc), 1/nT) : 0)
      + kEffective(T, yH2)*max(dt, scalar(0));
    return -std::expm1(-std::pow(theta, nT));
}


Foam::scalar Foam::reductionLaws::HancockSharp::rate
(
    const scalar X,
    const scalar T,
    const scalar yH2
) const
{
    if (X >= 1)
    {
        return 0;
    }
    const scalar nT = n(T);
    const scalar ke = kEffective(T, yH2);
    if (X <= 0)
    {
        if (ke == 0 || nT > 1)
        {
            return 0;
        }
        return nT == 1 ? ke : ROOTVGREAT;
    }
    const scalar L = -std::log1p(-X);
    return nT*ke*(1 - X)*std::pow(L, (nT - 1)/nT);
}
