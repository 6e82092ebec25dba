// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "reductionCurves.H"
#include "error.H"
#include "DynamicList.H"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * Local functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- A number, the whole token, finite
bool toNumber(const std::string& s, scalar& x)
{
    try
    {
        std::size_t used = 0;
        x = std::stod(s, &used);
        return used == s.size() && std::isfinite(x);
    }
    catch (...)
    {
        return false;
    }
}


std::string str(const scalar x)
{
    std::ostringstream os;
    os.precision(10);
    os << x;
    return os.str();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * //

void Foam::reductionCurves::error
(
    const fileName& file,
    const label line,
    const std::string& msg
)
{
    FatalErrorIn("Foam::reductionCurves")
        << "Reduction curves " << file;
    if (line > 0)
    {
        FatalError<< ", line " << line;
    }
    FatalError<< ": " << msg.c_str() << exit(FatalError);
    std::abort();
}


Foam::List<Foam::reductionCurve> Foam::reductionCurves::read
(
    const fileName& file
)
{
    std::ifstream is(file.c_str());
    if (!is.good())
    {
        error(file, 0, "cannot open the file");
    }

    DynamicList<reductionCurve> curves;
    std::string raw;
    label lineNo = 0;
    const std::string form =
        "a curve starts with 'curve <name> T <temperature> K H2 <fraction>'";

    while (std::getline(is, raw))
    {
        ++lineNo;
        std::string line = raw.substr(0, raw.find('#'));
        std::replace(line.begin(), line.end(), ',', ' ');
        std::replace(line.begin(), line.end(), '\t', ' ');
        std::replace(line.begin(), line.end(), '\r', ' ');
        std::istringstream ls(line);
        std::vector<std::string> tok;
        for (std::string s; ls >> s; )
        {
            tok.push_back(s);
        }
        if (tok.empty())
        {
            continue;
        }

        if (tok[0] == "curve")
        {
            if (tok.size() < 5 || tok[2] != "T")
            {
                error(file, lineNo, form + ", not '" + raw + "'");
            }
            reductionCurve c;
            c.name = word::validate(tok[1]);
            c.line = lineNo;
            if (c.name != tok[1])
            {
                error
                (
                    file, lineNo,
                    "curve name '" + tok[1] + "' must be one word"
                );
            }
            for (const reductionCurve& other : curves)
            {
                if (other.name == c.name)
                {
                    error
                    (
                        file, lineNo,
                        "curve " + c.name + " is named twice (also line "
                      + std::to_string(other.line) + ")"
                    );
                }
            }
            if (!toNumber(tok[3], c.T))
            {
                error
                (
                    file, lineNo,
                    "T '" + tok[3] + "' of curve " + c.name
                  + " is not a number; " + form
                );
            }
            const std::string unit = tok[4];
            if
            (
                unit == "C" || unit == "degC" || unit == "\u00b0C"
             || unit == "Celsius" || unit == "celsius"
            )
            {
                error
                (
                    file, lineNo,
                    "T of curve " + c.name + " is in " + unit
                  + ": temperatures are in kelvin (" + tok[3] + " " + unit
                  + " is T " + str(c.T + 273.15) + " K)"
                );
            }
            if (unit != "K")
            {
                error
                (
                    file, lineNo,
                    "T of curve " + c.name + " needs its unit, K: "
                  + form + ", not '" + raw + "'"
                );
            }
            if (!(c.T >= 200 && c.T <= 3000))
            {
                error
                (
                    file, lineNo,
                    "T " + tok[3] + " K of curve " + c.name
                  + " is outside [200, 3000] K"
                );
            }
            if (tok.size() != 7 || tok[5] != "H2")
            {
                error(file, lineNo, form + ", not '" + raw + "'");
            }
            if (!toNumber(tok[6], c.yH2))
            {
                error
                (
                    file, lineNo,
                    "H2 '" + tok[6] + "' of curve " + c.name
                  + " is not a number"
                );
            }
            if (!(c.yH2 > 0 && c.yH2 <= 1))
            {
                error
                (
                    file, lineNo,
                    "H2 " + tok[6] + " of curve " + c.name + " is the"
                    " hydrogen mole fraction, in (0, 1]"
                  + std::string(c.yH2 > 1 && c.yH2 <= 100 ? " (a percentage?)" : "")
                  + std::string(c.yH2 == 0 ? " (no hydrogen: nothing reduces)" : "")
                );
            }
            curves.append(c);
            continue;
        }

        // A point: time, X
        if (curves.empty())
        {
            error
            (
                file, lineNo,
                "a point before the first curve's header: " + form
            );
        }
        reductionCurve& c = curves.last();
        scalar t = 0, X = 0;
        if (tok.size() != 2 || !toNumber(tok[0], t) || !toNumber(tok[1], X))
        {
            error
            (
                file, lineNo,
                "a point of curve " + c.name + " is two numbers, time [s]"
                " and X [-], not '" + raw + "'"
            );
        }
        if (!(t >= 0))
        {
            error
            (
                file, lineNo,
                "time " + tok[0] + " s of curve " + c.name + " is negative"
            );
        }
        if (c.t.size() && !(t > c.t.last()))
        {
            error
            (
                file, lineNo,
                "time " + tok[0] + " s of curve " + c.name + " does not"
                " increase (the point before is at " + str(c.t.last())
              + " s)"
            );
        }
        if (!(X >= 0 && X <= 1))
        {
            error
            (
                file, lineNo,
                "X " + tok[1] + " of curve " + c.name + " is outside"
                " [0, 1] (a reduction degree, not a percentage)"
            );
        }
        if (t == 0 && X != 0)
        {
            error
            (
                file, lineNo,
                "curve " + c.name + " has X " + tok[1] + " at t = 0: the"
                " law starts from X = 0 at t = 0 (shift the curve's time to"
                " the start of the reduction, or leave the point out)"
            );
        }
        c.t.append(t);
        c.X.append(X);
    }

    if (curves.empty())
    {
        error(file, 0, "no curve in the file: " + form);
    }
    for (const reductionCurve& c : curves)
    {
        label n = 0;
        for (const scalar t : c.t)
        {
            n += t > 0;
        }
        if (n == 0)
        {
            error
            (
                file, c.line,
                "curve " + c.name + " has no point after t = 0"
            );
        }
    }

    return List<reductionCurve>(std::move(curves));
}
