/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | mpmLbmFoam: material point + lattice Boltzmann
   \\    /   O peration     | soil-water interaction on OpenFOAM
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of mpmLbmFoam, distributed under the terms of the GNU
    General Public License version 3 or later, as OpenFOAM it builds on.

\*---------------------------------------------------------------------------*/

#include "optionalEntry.H"
#include <algorithm>
#include <cctype>
#include <vector>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::label Foam::keywordDistance(const word& a, const word& b)
{
    // Optimal string alignment (Damerau-Levenshtein without repeated
    // edits of one substring): the typing errors a user makes, a letter
    // wrong, missing, extra, or two swapped, count one each
    const label m = a.size();
    const label n = b.size();
    const auto lower = [](const char c)
    {
        return char(std::tolower(static_cast<unsigned char>(c)));
    };
    std::vector<label> d((m + 1)*(n + 1));
    const auto at = [&](const label i, const label j) -> label&
    {
        return d[i*(n + 1) + j];
    };
    for (label i = 0; i <= m; ++i) at(i, 0) = i;
    for (label j = 0; j <= n; ++j) at(0, j) = j;
    for (label i = 1; i <= m; ++i)
    {
        for (label j = 1; j <= n; ++j)
        {
            const label cost = (lower(a[i-1]) == lower(b[j-1])) ? 0 : 1;
            label v = std::min
            (
                {at(i-1, j) + 1, at(i, j-1) + 1, at(i-1, j-1) + cost}
            );
            if
            (
                i > 1 && j > 1
             && lower(a[i-1]) == lower(b[j-2])
             && lower(a[i-2]) == lower(b[j-1])
            )
            {
                v = std::min(v, at(i-2, j-2) + 1);
            }
            at(i, j) = v;
        }
    }
    return at(m, n);
}


bool Foam::nearlySpelt(const word& written, const word& read)
{
    if (written == read)
    {
        return false;
    }
    // Short keywords are one letter from others of another meaning
    // (pRef, Aref, lRef in a forces dictionary), and their case is their
    // meaning (d the grain diameter, D the diffusivity, in one
    // dictionary): not compared
    if (read.size() <= 4)
    {
        return false;
    }
    const label allowed = read.size() < 8 ? 1 : 2;
    return keywordDistance(written, read) <= allowed;
}


Foam::word Foam::nearKeyword
(
    const dictionary& dict,
    const word& key,
    const wordList& siblings
)
{
    word nearest;
    label best = labelMax;
    for (const entry& e : dict)
    {
        const word& k = e.keyword();
        if (nearlySpelt(k, key) && !siblings.found(k))
        {
            const label dist = keywordDistance(k, key);
            if (dist < best)
            {
                best = dist;
                nearest = k;
            }
        }
    }
    return nearest;
}


void Foam::checkSpelling
(
    const dictionary& dict,
    const word& key,
    const string& whatIfAbsent,
    const wordList& siblings
)
{
    const word written(nearKeyword(dict, key, siblings));
    if (written.empty())
    {
        return;
    }
    const entry* e = dict.findEntry(written, keyType::LITERAL);
    FatalIOError
    (
        FUNCTION_NAME, __FILE__, __LINE__,
        dict.name(),
        e ? e->startLineNumber() : -1,
        e ? e->endLineNumber() : -1
    )   << "keyword " << written << " is not one this dictionary is read"
        << " for: did you mean " << key << "? (" << key << " is optional,"
        << " " << whatIfAbsent.c_str() << ", which would hold unsaid)" << nl
        << "    Correct the spelling; a variable of your own must differ"
        << " from " << key << " by more than "
        << (key.size() < 8 ? "a letter" : "two letters")
        << exit(FatalIOError);
}


bool Foam::foundEntry(const dictionary& dict, const word& key)
{
    if (dict.found(key))
    {
        return true;
    }
    checkSpelling(dict, key, "left out by choice");
    return false;
}


const Foam::dictionary& Foam::optionalDict
(
    const dictionary& dict,
    const word& name,
    const wordList& siblings
)
{
    if (dict.isDict(name))
    {
        return dict.subDict(name);
    }
    checkSpelling
    (
        dict, name, "its entries then read from " + dict.dictName(), siblings
    );
    return dict;
}


// ************************************************************************* //
