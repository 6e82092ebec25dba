// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "keywordRange.H"
#include "keywordSource.H"

#include <cstdio>

// * * * * * * * * * * * * * * * Local functions * * * * * * * * * * * * * //

namespace
{

//- A bound as a person writes it: %g without the exponent's + and zeros
std::string shortNumber(const Foam::scalar x)
{
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%g", x);
    std::string s(buf);
    const std::size_t e = s.find('e');
    if (e != std::string::npos)
    {
        std::string mant(s, 0, e), expo(s, e + 1);
        const bool negative = !expo.empty() && expo[0] == '-';
        if (!expo.empty() && (expo[0] == '+' || expo[0] == '-'))
        {
            expo.erase(0, 1);
        }
        expo.erase(0, expo.find_first_not_of('0'));
        s = mant + 'e' + (negative ? "-" : "") + (expo.empty() ? "0" : expo);
    }
    return s;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions  * * * * * * * * * * * * * * * //

void Foam::keywordRange::check
(
    const dictionary& dict,
    const word& key,
    const scalar value,
    const scalar lo,
    const scalar hi,
    const std::string& what,
    const bool openLow,
    const bool openHigh
)
{
    const bool bounded = hi < GREAT;
    const bool above = openLow ? value > lo : value >= lo;
    const bool below = !bounded || (openHigh ? value < hi : value <= hi);
    if (above && below)
    {
        return;
    }

    std::string range;
    if (bounded)
    {
        range =
            "must lie in " + std::string(openLow ? "(" : "[")
          + shortNumber(lo) + ", " + shortNumber(hi) + (openHigh ? ")" : "]");
    }
    else
    {
        range = "must be " + std::string(openLow ? "> " : ">= ")
          + shortNumber(lo);
    }
    FatalIOErrorInKeyword(dict, key)
        << "Keyword " << key << " in " << dict.name() << ' ' << range.c_str()
        << ", not " << value << (what.empty() ? "" : ": ") << what.c_str()
        << exit(FatalIOError);
}


Foam::scalar Foam::keywordRange::get
(
    const dictionary& dict,
    const word& key,
    const scalar lo,
    const scalar hi,
    const std::string& what,
    const bool openLow,
    const bool openHigh
)
{
    const scalar value = dict.get<scalar>(key);
    check(dict, key, value, lo, hi, what, openLow, openHigh);
    return value;
}


Foam::scalar Foam::keywordRange::getOrDefault
(
    const dictionary& dict,
    const word& key,
    const scalar deflt,
    const scalar lo,
    const scalar hi,
    const std::string& what,
    const bool openLow,
    const bool openHigh
)
{
    const scalar value = dict.lookupOrDefault<scalar>(key, deflt);
    check(dict, key, value, lo, hi, what, openLow, openHigh);
    return value;
}
