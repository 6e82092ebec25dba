// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "surfaceDiffusion.H"
#include "FixedList.H"
#include "keywordSource.H"

namespace
{
    // Molar gas constant [J/(mol K)] (SI 2019, exact)
    constexpr Foam::scalar Rgas = 8.314462618;
}

Foam::surfaceDiffusion::surfaceDiffusion(const dictionary& dict)
{
    const List<FixedList<scalar, 3>> ranges
    (
        dict.get<List<FixedList<scalar, 3>>>("surfaceDiffusion")
    );

    if (ranges.empty())
    {
        FatalIOErrorInKeyword(dict, "surfaceDiffusion")
            << "surfaceDiffusion: give at least one range"
               " (T_upper [K] D_0s [m^2/s] E_s [J/mol])"
            << exit(FatalIOError);
    }

    Tupper_.setSize(ranges.size());
    D0_.setSize(ranges.size());
    E_.setSize(ranges.size());

    forAll(ranges, i)
    {
        Tupper_[i] = ranges[i][0];
        D0_[i] = ranges[i][1];
        E_[i] = ranges[i][2];

        if
        (
            Tupper_[i] <= 0 || D0_[i] <= 0 || E_[i] < 0
         || (i > 0 && Tupper_[i] <= Tupper_[i-1])
        )
        {
            FatalIOErrorInKeyword(dict, "surfaceDiffusion")
                << "surfaceDiffusion: range " << i << " " << ranges[i]
                << " invalid: need T_upper > 0 and increasing [K],"
                   " D_0s > 0 [m^2/s], E_s >= 0 [J/mol]"
                << exit(FatalIOError);
        }
    }
}


Foam::scalar Foam::surfaceDiffusion::D(const scalar T) const
{
    forAll(Tupper_, i)
    {
        if (T <= Tupper_[i])
        {
            return D0_[i]*exp(-E_[i]/(Rgas*T));
        }
    }

    FatalErrorInFunction
        << "Temperature " << T << " K above the last surfaceDiffusion range "
        << Tupper_.last() << " K" << exit(FatalError);

    return 0;
}
