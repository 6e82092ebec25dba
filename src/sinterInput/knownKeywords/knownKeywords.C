// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "knownKeywords.H"
#include "FlatOutput.H"
#include <algorithm>
#include <cctype>
#include <vector>
#include "keywordSource.H"

Foam::label Foam::knownKeywords::editDistance
(
    const std::string& a,
    const std::string& b
)
{
    // One row of the Levenshtein table at a time, case-insensitive
    std::vector<label> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = label(j);
    for (size_t i = 1; i <= a.size(); ++i)
    {
        label diagonal = row[0];
        row[0] = label(i);
        for (size_t j = 1; j <= b.size(); ++j)
        {
            const label above = row[j];
            const bool same =
                std::tolower(static_cast<unsigned char>(a[i - 1]))
             == std::tolower(static_cast<unsigned char>(b[j - 1]));
            row[j] = std::min({above + 1, row[j - 1] + 1, diagonal + !same});
            diagonal = above;
        }
    }
    return row[b.size()];
}


Foam::word Foam::knownKeywords::nearest
(
    const word& key,
    const wordList& valid
)
{
    word best;
    label bestDistance = labelMax;
    for (const word& v : valid)
    {
        const label d = editDistance(key, v);
        if (d < bestDistance)
        {
            best = v;
            bestDistance = d;
        }
    }
    const label allowed = (std::max(key.size(), best.size()) >= 12 ? 3 : 2);
    return bestDistance <= allowed ? best : word::null;
}


void Foam::knownKeywords::check
(
    const dictionary& dict,
    const wordList& valid
)
{
    for (const entry& e : dict)
    {
        const word key(e.keyword());
        if (key == "FoamFile" || valid.found(key))
        {
            continue;
        }
        const word guess(nearest(key, valid));
        FatalIOErrorInKeyword(dict, key)
            << "Unknown keyword " << key << " in " << dict.name();
        if (!guess.empty())
        {
            FatalIOError << ": did you mean " << guess << '?';
        }
        FatalIOError
            << nl << "Valid keywords are " << flatOutput(valid)
            << exit(FatalIOError);
    }
}


const Foam::dictionary& Foam::knownKeywords::checked
(
    const dictionary& dict,
    const wordList& valid
)
{
    check(dict, valid);
    return dict;
}
