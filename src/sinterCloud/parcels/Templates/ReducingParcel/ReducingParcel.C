// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "ReducingParcel.H"

#include "ReducingParcelIO.C"
