// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "linearSpringDashpot.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "keywordSource.H"

namespace Foam
{
namespace contactLaws
{
    defineTypeNameAndDebug(linearSpringDashpot, 0);
    addToRunTimeSelectionTable(contactLaw, linearSpringDashpot, dictionary);
}
}


namespace
{

Foam::scalar readNonNegative
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const bool strictlyPositive
)
{
    const Foam::scalar value = dict.get<Foam::scalar>(key);
    if (strictlyPositive ? !(value > 0) : !(value >= 0))
    {
        FatalIOErrorInKeyword(dict, key)
            << "Keyword " << key << " in " << dict.name() << " must be "
            << (strictlyPositive ? "positive" : "non-negative")
            << ", not " << value << Foam::exit(Foam::FatalIOError);
    }
    return value;
}

} // End anonymous namespace


Foam::contactLaws::linearSpringDashpot::linearSpringDashpot
(
    const dictionary& dict,
    const contactMaterials& materials,
    const scalar coarseGrainFactor,
    contactSlots& slots
)
:
    contactLawTemplate<linearSpringDashpot>
    (
        dict,
        materials,
        coarseGrainFactor,
        slots,
        false
    )
{
    const dictionary& coeffs = dict.subDict(typeName + "Coeffs");
    const scalar K = coarseGrainFactor;
    kn_ = K*readNonNegative(coeffs, "kn", true);
    kt_ = K*readNonNegative(coeffs, "kt", false);
    gammaN_ = sqr(K)*readNonNegative(coeffs, "gammaN", false);
    gammaT_ = sqr(K)*readNonNegative(coeffs, "gammaT", false);
}


Foam::scalar Foam::contactLaws::linearSpringDashpot::collisionTime
(
    const scalar,
    const scalar m,
    const scalar
) const
{
    const scalar mStar = 0.5*m;
    const scalar w2 = kn_/mStar - sqr(0.5*gammaN_/mStar);
    return constant::mathematical::pi/sqrt(max(w2, VSMALL));
}
