// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "numberLiterals.H"
#include "OSspecific.H"
#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

namespace
{

bool isDigit(const char c)
{
    return std::isdigit(static_cast<unsigned char>(c));
}

//- A character that continues a word (so a digit after it is not a number)
bool isWordChar(const char c)
{
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'
        || c == ':' || c == '$';
}

//- The first word of the line around position pos (its keyword)
std::string lineKeyword(const std::string& text, const size_t pos)
{
    const size_t b = text.rfind('\n', pos);
    size_t i = (b == std::string::npos ? 0 : b + 1);
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    size_t j = i;
    while
    (
        j < text.size() && !std::isspace(static_cast<unsigned char>(text[j]))
     && text[j] != ';'
    )
    {
        ++j;
    }
    return text.substr(i, j - i);
}

} // End anonymous namespace


long Foam::numberLiterals::decimalExponent
(
    const std::string& text,
    const size_t start,
    size_t end
)
{
    long lead = 0;          // position of the leading non-zero digit
    long pointAt = -1;      // digits before the point
    long nDigits = 0;
    bool found = false;
    long exponent = 0;
    size_t i = start;
    if (i < end && (text[i] == '+' || text[i] == '-')) ++i;
    for (; i < end && text[i] != 'e' && text[i] != 'E'; ++i)
    {
        if (text[i] == '.')
        {
            pointAt = nDigits;
            continue;
        }
        if (!found && text[i] != '0')
        {
            found = true;
            lead = nDigits;
        }
        ++nDigits;
    }
    if (pointAt < 0) pointAt = nDigits;
    if (i < end)
    {
        ++i;
        bool negative = false;
        if (i < end && (text[i] == '+' || text[i] == '-'))
        {
            negative = (text[i] == '-');
            ++i;
        }
        for (; i < end; ++i)
        {
            if (exponent < 100000) exponent = 10*exponent + (text[i] - '0');
        }
        if (negative) exponent = -exponent;
    }
    if (!found) return -1000000000L;
    return exponent + pointAt - lead - 1;
}


bool Foam::numberLiterals::beyondDouble
(
    const std::string& text,
    const size_t start,
    const size_t end
)
{
    const long e = decimalExponent(text, start, end);
    if (e != 308) return e > 308;

    // Its significant digits against those of the largest double
    std::string digits;
    for (size_t i = start; i < end; ++i)
    {
        const char c = text[i];
        if (c == 'e' || c == 'E') break;
        if (isDigit(c) && (!digits.empty() || c != '0')) digits += c;
    }
    const std::string largest("17976931348623157");
    digits.resize(std::max(digits.size(), largest.size()), '0');
    const int cmp = digits.compare(0, largest.size(), largest);
    return cmp > 0
        || (
               cmp == 0
            && digits.find_first_not_of('0', largest.size())
               != std::string::npos
           );
}


void Foam::numberLiterals::checkFile(const fileName& file)
{
    std::ifstream is(file.c_str(), std::ios::binary);
    if (!is.good()) return;
    std::ostringstream buf;
    buf << is.rdbuf();
    const std::string text(buf.str());
    const size_t n = text.size();

    size_t i = 0;
    while (i < n)
    {
        const char c = text[i];
        if (c == '/' && i + 1 < n && text[i + 1] == '/')
        {
            i = text.find('\n', i);
            if (i == std::string::npos) return;
            continue;
        }
        if (c == '/' && i + 1 < n && text[i + 1] == '*')
        {
            i = text.find("*/", i + 2);
            if (i == std::string::npos) return;
            i += 2;
            continue;
        }
        if (c == '"')
        {
            ++i;
            while (i < n && text[i] != '"')
            {
                i += (text[i] == '\\' ? 2 : 1);
            }
            ++i;
            continue;
        }
        const bool startsNumber =
            (isDigit(c) || (c == '.' && i + 1 < n && isDigit(text[i + 1])))
         && (i == 0 || !isWordChar(text[i - 1]));
        if (!startsNumber)
        {
            ++i;
            continue;
        }
        size_t j = i;
        while (j < n && (isDigit(text[j]) || text[j] == '.')) ++j;
        if
        (
            j < n && (text[j] == 'e' || text[j] == 'E')
         && (
                (j + 1 < n && isDigit(text[j + 1]))
             || (
                    j + 2 < n && (text[j + 1] == '+' || text[j + 1] == '-')
                 && isDigit(text[j + 2])
                )
            )
        )
        {
            j += 2;
            while (j < n && isDigit(text[j])) ++j;
        }
        if (j < n && isWordChar(text[j]))
        {
            // part of a word (a version, a name): not a number
            while (j < n && isWordChar(text[j])) ++j;
            i = j;
            continue;
        }
        if (beyondDouble(text, i, j))
        {
            const label line =
                1 + std::count(text.begin(), text.begin() + i, '\n');
            FatalErrorInFunction
                << "The number " << text.substr(i, j - i).c_str()
                << " of keyword " << lineKeyword(text, i).c_str() << " in "
                << file << " (line " << line << ") is beyond the range of"
                << " a double (1.797e308)"
                << nl << "Give it in SI units; OpenFOAM would stop with a"
                << " floating-point trap while reading it"
                << exit(FatalError);
        }
        i = j;
    }
}


void Foam::numberLiterals::checkCase(const argList& args)
{
    const fileName root(args.rootPath()/args.globalCaseName());
    const fileName dirs[] = {root/"system", root/"constant", root/"0"};
    for (const fileName& dir : dirs)
    {
        for (const fileName& f : readDir(dir, fileName::FILE))
        {
            checkFile(dir/f);
        }
    }
    for (const fileName& sub : readDir(root/"constant", fileName::DIRECTORY))
    {
        if (sub == "polyMesh") continue;
        for (const fileName& f : readDir(root/"constant"/sub, fileName::FILE))
        {
            checkFile(root/"constant"/sub/f);
        }
    }
}
