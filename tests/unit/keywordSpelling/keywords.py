#!/usr/bin/python3
"""The keywords the project reads from users' dictionaries, from its source.

optional: keywords read with optionalEntry, readIfPresentEntry, foundEntry,
optionalDict or an optional selectEntry (absent, their dictionary is
searched for a near spelling, which is refused), and every model's
<Type>Coeffs (its TypeName: the families' bases read them with
optionalDict, the other models' of the family passed as siblings, which
are never taken for a misspelling); read: every identifier given to a
dictionary lookup, coefficient helper or TypeName. Shared with the test's
check of no two being near.
"""
import os
import re

CALL = re.compile(r'\b(\w+)\s*(?:<[^;()]*?>)?\s*\((?=\s*([^;]*?)\))', re.S)
LITERAL = re.compile(r'"([A-Za-z][A-Za-z0-9_]*)"')
OPTIONAL = {'optionalEntry', 'readIfPresentEntry', 'foundEntry', 'optionalDict'}
LOOKUP = OPTIONAL | {
    'get', 'getOrDefault', 'readIfPresent', 'readEntry', 'found', 'isDict',
    'subDict', 'subOrEmptyDict', 'optionalSubDict', 'lookup', 'selectEntry',
    'readPositive', 'readPositiveCoeff', 'positive', 'checkInPlane',
    'entryNotAllowed', 'TypeName', 'defineTypeNameAndDebug'}


def source_files(root):
    for top in ('src', 'applications'):
        for d, _, files in os.walk(os.path.join(root, top)):
            if 'lnInclude' in d or 'Make' in d:
                continue
            for f in files:
                if f.endswith(('.C', '.H')):
                    yield os.path.join(d, f)


def keywords(root):
    """(optional, read, coeffs): dicts keyword -> set of 'file:line' it is
    read at; coeffs: the models' <Type>Coeffs"""
    optional, read, coeffs = {}, {}, set()
    for path in source_files(root):
        text = open(path, errors='replace').read()
        # Comments (a Description's example) are not reads; their lines
        # are kept, for the line numbers
        text = re.sub(r'/\*.*?\*/', lambda c: '\n'*c.group(0).count('\n'),
                      text, flags=re.S)
        text = re.sub(r'//[^\n]*', '', text)
        rel = os.path.relpath(path, root)
        for m in CALL.finditer(text):
            name, args = m.group(1), m.group(2)
            if name not in LOOKUP:
                continue
            lit = LITERAL.search(args)
            if not lit:
                continue
            key = lit.group(1)
            model = name in ('TypeName', 'defineTypeNameAndDebug')
            if model:
                key += 'Coeffs'
                coeffs.add(key)
            where = '%s:%d' % (rel, text.count('\n', 0, m.start()) + 1)
            read.setdefault(key, set()).add(where)
            optional_select = name == 'selectEntry' and re.search(
                r',\s*true\s*,', args)
            if name in OPTIONAL or optional_select or model:
                optional.setdefault(key, set()).add(where)
    return optional, read, coeffs


def distance(a, b):
    """Optimal string alignment distance, case ignored (optionalEntry.C)"""
    a, b = a.lower(), b.lower()
    m, n = len(a), len(b)
    d = [[0]*(n + 1) for _ in range(m + 1)]
    for i in range(m + 1):
        d[i][0] = i
    for j in range(n + 1):
        d[0][j] = j
    for i in range(1, m + 1):
        for j in range(1, n + 1):
            cost = 0 if a[i-1] == b[j-1] else 1
            v = min(d[i-1][j] + 1, d[i][j-1] + 1, d[i-1][j-1] + cost)
            if i > 1 and j > 1 and a[i-1] == b[j-2] and a[i-2] == b[j-1]:
                v = min(v, d[i-2][j-2] + 1)
            d[i][j] = v
    return d[m][n]


def nearly_spelt(written, read):
    if written == read:
        return False
    if len(read) <= 4:
        return False
    return distance(written, read) <= (1 if len(read) < 8 else 2)
