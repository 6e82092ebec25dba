// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "RanzMarshall.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace convectionLaws
{
    defineTypeNameAndDebug(RanzMarshall, 0);
    addToRunTimeSelectionTable(convectionLaw, RanzMarshall, dictionary);
}
}


Foam::scalar Foam::convectionLaws::RanzMarshall::Nu
(
    const scalar,
    const scalar Re,
    const scalar Pr
) const
{
    return 2 + 0.6*std::sqrt(Re)*std::cbrt(Pr);
}
