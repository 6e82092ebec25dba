// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "BatchelorOBrien.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace directConductions
{
    defineTypeNameAndDebug(BatchelorOBrien, 0);
    addToRunTimeSelectionTable(directConduction, BatchelorOBrien, dictionary);
}
}
