// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "ironOxidePath.H"
#include "keywordRange.H"
#include "keywordSource.H"

// * * * * * * * * * * * * * * * Local constants * * * * * * * * * * * * * //

namespace
{

using Foam::scalar;

// Standard enthalpies of formation at 298.15 K [J/mol] (NIST-JANAF)
constexpr scalar HFe2O3 = -824.2e3;
constexpr scalar HFe3O4 = -1118.4e3;
constexpr scalar HFeO = -272.0e3;
constexpr scalar HH2O = -241.826e3;

constexpr scalar MFe = Foam::ironOxidePath::MFe;
constexpr scalar MO = Foam::ironOxidePath::MO;
constexpr scalar MFe2O3 = 2*MFe + 3*MO;
constexpr scalar MFe3O4 = 3*MFe + 4*MO;
constexpr scalar MFeO = MFe + MO;

// Densities of the dense phases [kg/m^3]: hematite and magnetite as the
// thesis's Table 2.4, wustite and iron the handbook values (CRC Handbook
// of Chemistry and Physics, physical constants of inorganic compounds)
constexpr scalar rhoFe2O3 = 5240;
constexpr scalar rhoFe3O4 = 5180;
constexpr scalar rhoFeO = 5745;
constexpr scalar rhoFe = 7874;

// Iron mass fractions of hematite and magnetite
constexpr scalar WFe2O3 = 2*MFe/MFe2O3;
constexpr scalar WFe3O4 = 3*MFe/MFe3O4;

} // End anonymous namespace


// The definitions of the constants (C++14: a constant bound to a reference
// needs one)
constexpr Foam::scalar Foam::ironOxidePath::MFe;
constexpr Foam::scalar Foam::ironOxidePath::MO;
constexpr Foam::scalar Foam::ironOxidePath::MH2;
constexpr Foam::scalar Foam::ironOxidePath::MH2O;
constexpr Foam::scalar Foam::ironOxidePath::TWustite;


const Foam::FixedList<Foam::word, 4> Foam::ironOxidePath::phaseNames
({
    "Fe2O3", "Fe3O4", "FeO", "Fe"
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ironOxidePath::ironOxidePath(const scalar W0)
:
    W0_(W0),
    nFe_(W0/MFe),
    nO_((1 - W0)/MO),
    nFeH_(hematiteFraction()*2/MFe2O3),
    X1_(nFeH_/(6*nO_)),
    X2_(X1_ + nFe_/(3*nO_))
{}


Foam::ironOxidePath::ironOxidePath(const dictionary& dict)
:
    ironOxidePath(dict.get<scalar>("ironContent"))
{
    // A little beyond the pure phases' 0.69943 and 0.72360 for rounding
    keywordRange::check
    (
        dict, "ironContent", W0_, WFe2O3 - 1e-4, WFe3O4 + 1e-4,
        "the iron mass fraction W0(TFe) of a hematite-magnetite powder,"
        " Fe2O3 to Fe3O4"
      + std::string(W0_ > 1 ? " (a mass fraction, not a percentage)" : "")
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::ironOxidePath::hematiteFraction() const
{
    return min(max((WFe3O4 - W0_)/(WFe3O4 - WFe2O3), scalar(0)), scalar(1));
}


Foam::label Foam::ironOxidePath::stages
(
    const scalar T,
    scalar bounds[3]
) const
{
    bounds[0] = X1_;
    if (T >= TWustite)
    {
        bounds[1] = X2_;
        bounds[2] = 1;
        return 3;
    }
    bounds[1] = 1;
    return 2;
}


Foam::scalar Foam::ironOxidePath::stageEnthalpy
(
    const label i,
    const bool wustitePath
)
{
    if (i == 0)
    {
        // 3 Fe2O3 + H2 -> 2 Fe3O4 + H2O
        return 2*HFe3O4 + HH2O - 3*HFe2O3;
    }
    if (!wustitePath)
    {
        // Fe3O4 + 4 H2 -> 3 Fe + 4 H2O, per O
        return (4*HH2O - HFe3O4)/4;
    }
    if (i == 1)
    {
        // Fe3O4 + H2 -> 3 FeO + H2O
        return 3*HFeO + HH2O - HFe3O4;
    }
    // FeO + H2 -> Fe + H2O
    return HH2O - HFeO;
}


Foam::FixedList<Foam::scalar, 4> Foam::ironOxidePath::phases
(
    const scalar X,
    const scalar T
) const
{
    const scalar x = min(max(X, scalar(0)), scalar(1));
    const scalar nFeM = nFe_ - nFeH_;

    // Moles of each phase per kilogram of oxide
    FixedList<scalar, 4> n(Zero);
    if (x <= X1_)
    {
        const scalar s = X1_ > 0 ? x/X1_ : 1;
        n[hematite] = nFeH_/2*(1 - s);
        n[magnetite] = nFeM/3 + nFeH_/3*s;
    }
    else if (T < TWustite)
    {
        const scalar f = (x - X1_)/(1 - X1_);
        n[magnetite] = nFe_*(1 - f)/3;
        n[iron] = nFe_*f;
    }
    else if (x <= X2_)
    {
        const scalar g = (x - X1_)/(X2_ - X1_);
        n[magnetite] = nFe_*(1 - g)/3;
        n[wustite] = nFe_*g;
    }
    else
    {
        const scalar h = (x - X2_)/(1 - X2_);
        n[wustite] = nFe_*(1 - h);
        n[iron] = nFe_*h;
    }

    const scalar mass = massRatio(x);
    FixedList<scalar, 4> w;
    w[hematite] = n[hematite]*MFe2O3/mass;
    w[magnetite] = n[magnetite]*MFe3O4/mass;
    w[wustite] = n[wustite]*MFeO/mass;
    w[iron] = n[iron]*MFe/mass;
    return w;
}


Foam::scalar Foam::ironOxidePath::metallicIron
(
    const scalar X,
    const scalar T
) const
{
    const scalar x = min(max(X, scalar(0)), scalar(1));
    const scalar start = T < TWustite ? X1_ : X2_;
    return x > start ? (x - start)/(1 - start) : 0;
}


Foam::scalar Foam::ironOxidePath::ironVolumeFraction
(
    const scalar X,
    const scalar T
) const
{
    const FixedList<scalar, 4> w(phases(X, T));
    const scalar vIron = w[iron]/rhoFe;
    const scalar v =
        w[hematite]/rhoFe2O3 + w[magnetite]/rhoFe3O4 + w[wustite]/rhoFeO
      + vIron;
    return vIron/v;
}


Foam::scalar Foam::ironOxidePath::enthalpy
(
    const scalar Xa,
    const scalar Xb,
    const scalar T
) const
{
    scalar bounds[3];
    const label nStages = stages(T, bounds);
    const bool wustitePath = nStages == 3;

    const scalar lo = min(max(min(Xa, Xb), scalar(0)), scalar(1));
    const scalar hi = min(max(max(Xa, Xb), scalar(0)), scalar(1));

    scalar H = 0;
    scalar start = 0;
    for (label i = 0; i < nStages; ++i)
    {
        const scalar a = max(lo, start);
        const scalar b = min(hi, bounds[i]);
        if (b > a)
        {
            H += (b - a)*nO_*stageEnthalpy(i, wustitePath);
        }
        start = bounds[i];
    }
    return Xb >= Xa ? H : -H;
}
