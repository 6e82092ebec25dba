// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "gasLens.H"
#include "error.H"
#include "keywordSource.H"


Foam::indirectConductions::gasLens::gasLens
(
    const dictionary& dict,
    const scalar ks,
    const word& law
)
:
    indirectConduction(dict, ks),
    lensRadius_
    (
        dict.optionalSubDict(law + "Coeffs")
            .lookupOrDefault<scalar>("lensRadius", 1.4)
    )
{
    const dictionary& coeffs = dict.optionalSubDict(law + "Coeffs");
    if (!(lensRadius_ > 1))
    {
        FatalIOErrorInKeyword(coeffs, "lensRadius")
            << "Keyword lensRadius in " << coeffs.name() << " is r_lens/r_p"
            << " and must be > 1 (the lens surrounds the particle), not "
            << lensRadius_ << exit(FatalIOError);
    }
}
