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


//- Whether value lies in the range
bool inside
(
    const Foam::scalar value,
    const Foam::scalar lo,
    const Foam::scalar hi,
    const bool openLow,
    const bool openHigh
)
{
    const bool above = openLow ? value > lo : value >= lo;
    const bool below =
        !(hi < Foam::GREAT) || (openHigh ? value < hi : value <= hi);
    return above && below;
}


//- "must lie in [lo, hi]" or "must be > lo"
std::string rangeText
(
    const Foam::scalar lo,
    const Foam::scalar hi,
    const bool openLow,
    const bool openHigh
)
{
    if (hi < Foam::GREAT)
    {
        return
            "must lie in " + std::string(openLow ? "(" : "[")
          + shortNumber(lo) + ", " + shortNumber(hi) + (openHigh ? ")" : "]");
    }
    return "must be " + std::string(openLow ? "> " : ">= ") + shortNumber(lo);
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
    checkElement(dict, key, "", value, lo, hi, what, openLow, openHigh);
}


void Foam::keywordRange::checkElement
(
    const dictionary& dict,
    const word& key,
    const std::string& element,
    const scalar value,
    const scalar lo,
    const scalar hi,
    const std::string& what,
    const bool openLow,
    const bool openHigh
)
{
    if (inside(value, lo, hi, openLow, openHigh))
    {
        return;
    }
    FatalIOErrorInKeyword(dict, key)
        << "Keyword " << key << " in " << dict.name()
        << (element.empty() ? std::string(" ") : ": " + element + ' ').c_str()
        << rangeText(lo, hi, openLow, openHigh).c_str()
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
