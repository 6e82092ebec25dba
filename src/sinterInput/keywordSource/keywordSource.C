// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "keywordSource.H"
#include "OSspecific.H"
#include "stringOps.H"
#include "ITstream.H"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <vector>

// * * * * * * * * * * * * * * * Local functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- A file's lines with comments blanked (line i at index i - 1)
struct sourceFile
{
    fileName name;
    std::vector<std::string> lines;
};


std::vector<std::string> readLines(const fileName& f)
{
    std::vector<std::string> lines;
    std::ifstream is(f.c_str());
    std::string line;
    bool inBlock = false;
    while (std::getline(is, line))
    {
        std::string kept;
        for (std::size_t i = 0; i < line.size(); ++i)
        {
            if (inBlock)
            {
                if (line.compare(i, 2, "*/") == 0)
                {
                    inBlock = false;
                    ++i;
                }
            }
            else if (line.compare(i, 2, "/*") == 0)
            {
                inBlock = true;
                ++i;
            }
            else if (line.compare(i, 2, "//") == 0)
            {
                break;
            }
            else
            {
                kept += line[i];
            }
        }
        lines.push_back(kept);
    }
    return lines;
}


//- The words of a line, split at blanks, ';', braces and brackets
std::vector<std::string> words(const std::string& line)
{
    std::vector<std::string> w;
    std::string cur;
    for (const char c : line)
    {
        if (std::isspace(static_cast<unsigned char>(c)) || c == ';'
         || c == '{' || c == '}' || c == '(' || c == ')')
        {
            if (!cur.empty())
            {
                w.push_back(cur);
                cur.clear();
            }
        }
        else
        {
            cur += c;
        }
    }
    if (!cur.empty())
    {
        w.push_back(cur);
    }
    return w;
}


//- The included files of f, depth first, each once
void collect
(
    const fileName& f,
    const dictionary& top,
    std::vector<sourceFile>& files,
    const int depth
)
{
    for (const sourceFile& s : files)
    {
        if (s.name == f)
        {
            return;
        }
    }
    files.push_back(sourceFile{f, readLines(f)});
    if (depth > 8)
    {
        return;
    }
    const std::vector<std::string> lines = files.back().lines;

    for (const std::string& line : lines)
    {
        std::size_t p = line.find("#include");
        while (p != std::string::npos)
        {
            const std::size_t after = p + 8;
            const bool followed =
                line.compare(after, 3, "Etc") != 0
             && line.compare(after, 4, "Func") != 0;
            const std::size_t q0 = line.find('"', after);
            const std::size_t q1 =
                q0 == std::string::npos ? q0 : line.find('"', q0 + 1);
            if (followed && q1 != std::string::npos)
            {
                std::string name(line, q0 + 1, q1 - q0 - 1);
                stringOps::inplaceExpand(name, top, true, true);
                fileName inc(name);
                if (!inc.empty() && !inc.isAbsolute())
                {
                    inc = f.path()/inc;
                }
                if (!inc.empty() && isFile(inc, false))
                {
                    collect(inc, top, files, depth + 1);
                }
            }
            p = line.find("#include", after);
        }
    }
}


//- Does the raw word w stand for the token t?
bool matches(const std::string& w, const token& t)
{
    if (t.isNumber())
    {
        const char* s = w.c_str();
        char* end = nullptr;
        const double v = std::strtod(s, &end);
        if (end == s || *end != '\0')
        {
            return false;
        }
        const double n = t.number();
        return std::abs(v - n) <= 1e-12*std::max(std::abs(n), 1e-300);
    }
    if (t.isWord())
    {
        return w == t.wordToken();
    }
    if (t.isString())
    {
        return w == '"' + t.stringToken() + '"';
    }
    return false;
}


bool lineHas(const std::string& line, const token& t)
{
    for (const std::string& w : words(line))
    {
        if (matches(w, t))
        {
            return true;
        }
    }
    return false;
}


bool lineStartsWith(const std::string& line, const word& key)
{
    const std::vector<std::string> w = words(line);
    return !w.empty() && w.front() == key;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::fileName Foam::keywordSource::ownFile(const dictionary& dict)
{
    std::string s = dict.name();
    while (!s.empty())
    {
        if (isFile(s, false))
        {
            return s;
        }
        const std::size_t dot = s.rfind('.');
        const std::size_t slash = s.rfind('/');
        if (dot == std::string::npos
         || (slash != std::string::npos && dot < slash))
        {
            break;
        }
        s.resize(dot);
    }
    return fileName();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::keywordSource::keywordSource(const dictionary& dict, const word& key)
:
    file_(),
    line_(-1),
    elsewhere_(false)
{
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    const fileName own(ownFile(dict));
    if (!e || !e->isStream() || own.empty())
    {
        return;
    }
    const ITstream& is = e->stream();
    if (is.empty())
    {
        return;
    }
    const token& first = is[0];
    const label line = first.lineNumber();

    std::vector<sourceFile> files;
    collect(own, dict.topDict(), files, 0);
    const sourceFile& ownSource = files.front();

    auto lineOf = [](const sourceFile& s, const label l) -> const std::string*
    {
        return (l >= 1 && l <= label(s.lines.size())) ? &s.lines[l - 1] : nullptr;
    };

    label found = -1;
    label nFound = 0;
    if (line > 0)
    {
        const std::string* l0 = lineOf(ownSource, line);
        if (l0 && lineStartsWith(*l0, key))
        {
            found = 0;
            nFound = 1;
        }
        else
        {
            for (std::size_t i = 1; i < files.size(); ++i)
            {
                const std::string* l = lineOf(files[i], line);
                if (l && lineHas(*l, first))
                {
                    found = i;
                    ++nFound;
                }
            }
            if (nFound == 0 && l0 && lineHas(*l0, first))
            {
                found = 0;
                nFound = 1;
            }
        }
        if (nFound == 1)
        {
            line_ = line;
        }
    }
    else
    {
        // A computed value: the one line that starts with the keyword
        for (std::size_t i = 0; i < files.size(); ++i)
        {
            for (std::size_t l = 0; l < files[i].lines.size(); ++l)
            {
                if (lineStartsWith(files[i].lines[l], key))
                {
                    found = i;
                    line_ = l + 1;
                    ++nFound;
                }
            }
        }
    }

    if (nFound == 1)
    {
        file_ = files[found].name;
        elsewhere_ = found != 0;
    }
    else
    {
        line_ = -1;
    }
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::OSstream& Foam::keywordError
(
    const char* functionName,
    const char* sourceFileName,
    const int sourceFileLineNumber,
    const dictionary& dict,
    const word& key
)
{
    const keywordSource src(dict, key);
    if (src.file().empty())
    {
        return FatalIOError
        (
            functionName, sourceFileName, sourceFileLineNumber, dict
        );
    }
    const string ioName
    (
        src.elsewhere()
      ? string(dict.name() + '.' + key + ", set in " + src.file())
      : string(dict.name())
    );
    return FatalIOError
    (
        functionName, sourceFileName, sourceFileLineNumber,
        ioName, src.line(), src.line()
    );
}


// ************************************************************************* //
