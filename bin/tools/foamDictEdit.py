#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Module
#     bin/tools/foamDictEdit.py
#
# Description
#     Edits one entry of an OpenFOAM dictionary file in place, by keyword,
#     and fails loudly (DictEditError naming the file and the keyword) when
#     the entry is not there or is there twice: a script that edits a case
#     can no longer do nothing silently when the dictionary's text changes.
#     The rest of the file is kept as it is, byte for byte: alignment,
#     comments, $macros and the values' precision (foamDictionary -set
#     expands the file's macros and keeps 6 significant digits).
#
#     set_entry(path, keypath, value)
#         keypath: keywords separated by '/' (walls/floor, FLIPCoeffs/ratio);
#         a named dictionary inside a list is reached by its name
#         (regions/block/min in setMaterialPointsDict's regions ( block
#         { ... } )). value: the new text, written as given ('(0 -9.81 0)',
#         '$dx', '{ type slip; }' for a dictionary entry).
#     replace_text(path, old, new, count=1)
#         for text that is not one entry (a blockMesh vertex list, a
#         patch's type in a list): replaces the exact text OLD, which must
#         occur exactly COUNT times (count=0: at least once, all of them).
#
#     bin/tools/setEntry is the command line (and RunFunctions' setEntry).
#------------------------------------------------------------------------------
import re


class DictEditError(Exception):
    pass


_PUNCT = '(){}[];'


def _tokens(text):
    """(kind, start, end) of the tokens of TEXT: comments skipped, strings
    whole, punctuation one character, anything else a word (a word that
    runs into a '(' without a space, like div(phi,U), keeps its balanced
    parentheses)."""
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c.isspace():
            i += 1
        elif text.startswith('//', i):
            j = text.find('\n', i)
            i = n if j < 0 else j + 1
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2)
            i = n if j < 0 else j + 2
        elif text.startswith('#{', i):
            j = text.find('#}', i + 2)
            j = n if j < 0 else j + 2
            yield ('word', i, j)
            i = j
        elif c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == '\\' else 1
            yield ('string', i, min(j + 1, n))
            i = j + 1
        elif c in _PUNCT:
            yield ('punct', i, i + 1)
            i += 1
        else:
            j = i
            depth = 0
            while j < n:
                d = text[j]
                if d == '(' and j > i:
                    depth += 1
                elif d == ')' and depth > 0:
                    depth -= 1
                elif depth == 0 and (d.isspace() or d in _PUNCT
                                     or text.startswith('//', j)
                                     or text.startswith('/*', j)):
                    break
                j += 1
            yield ('word', i, j)
            i = j


class _Entry(object):
    """keyword, the span of its value (from the first token to the last,
    ';' excluded; a dictionary's from '{' to '}'), its children (a
    dictionary's entries, or the named dictionaries in a list)."""

    def __init__(self, keyword, start):
        self.keyword = keyword
        self.start = start
        self.value_start = self.value_end = None
        self.children = []


def _parse_entries(text, toks, i, closing):
    """Entries from token I up to the token CLOSING ('}' or None: the end);
    returns (entries, index after the closing token)."""
    entries = []
    n = len(toks)
    while i < n:
        kind, s, e = toks[i]
        word = text[s:e]
        if kind == 'punct':
            if word == closing:
                return entries, i + 1
            if word == ';':
                i += 1
                continue
            raise DictEditError('unexpected %r at character %d' % (word, s))
        if word.startswith('#'):
            # a directive: #include "file", #inputMode merge, #remove key
            i += 2 if i + 1 < n and toks[i + 1][0] != 'punct' else 1
            continue
        if word.startswith('$'):
            # a macro line ($defaults;): no entry of its own
            i += 1
            if i < n and text[toks[i][1]:toks[i][2]] == ';':
                i += 1
            continue
        ent = _Entry(word.strip('"'), s)
        i += 1
        if i < n and text[toks[i][1]:toks[i][2]] == '{':
            ent.value_start = toks[i][1]
            ent.children, i = _parse_entries(text, toks, i + 1, '}')
            ent.value_end = toks[i - 1][2]
        else:
            depth = 0
            first = i
            while i < n:
                k, s2, e2 = toks[i]
                w = text[s2:e2]
                if k == 'punct':
                    if w in '([{':
                        depth += 1
                    elif w in ')]}':
                        if depth == 0:
                            break
                        depth -= 1
                    elif w == ';' and depth == 0:
                        break
                    # a named dictionary in a list: name { ... } (not a
                    # uniform list N { value })
                    if (w == '{' and depth == 2 and i > first
                            and toks[i - 1][0] == 'word'
                            and not text[toks[i - 1][1]:toks[i - 1][2]]
                            .isdigit()):
                        sub = _Entry(text[toks[i - 1][1]:toks[i - 1][2]],
                                     toks[i - 1][1])
                        sub.value_start = s2
                        sub.children, i = _parse_entries(text, toks, i + 1,
                                                         '}')
                        sub.value_end = toks[i - 1][2]
                        ent.children.append(sub)
                        depth -= 1
                        continue
                i += 1
            if i == first:
                raise DictEditError('entry %s has no value' % ent.keyword)
            ent.value_start = toks[first][1]
            ent.value_end = toks[i - 1][2]
        entries.append(ent)
    if closing is not None:
        raise DictEditError('a { is not closed')
    return entries, i


def find_entry(text, keypath):
    """The _Entry of KEYPATH in TEXT; DictEditError when absent or given
    more than once at its level."""
    toks = list(_tokens(text))
    entries, _ = _parse_entries(text, toks, 0, None)
    keys = [k for k in keypath.split('/') if k]
    if not keys:
        raise DictEditError('empty keyword')
    for depth, key in enumerate(keys):
        found = [e for e in entries if e.keyword == key]
        where = '/'.join(keys[:depth + 1])
        if not found:
            raise DictEditError('no entry %s' % where)
        if len(found) > 1:
            raise DictEditError('entry %s is given %d times'
                                % (where, len(found)))
        entries = found[0].children
    return found[0]


def set_entry(path, keypath, value):
    """Set the value of entry KEYPATH of the dictionary file PATH to the
    text VALUE (see the module's description)."""
    text = open(path).read()
    try:
        ent = find_entry(text, keypath)
    except DictEditError as err:
        raise DictEditError('%s: %s' % (path, err))
    value = str(value)
    is_dict = text[ent.value_start] == '{'
    if is_dict != value.lstrip().startswith('{'):
        raise DictEditError('%s: entry %s is %s: give %s'
                            % (path, keypath,
                               'a dictionary' if is_dict else 'not a dictionary',
                               "'{ ... }'" if is_dict else 'a value, not { }'))
    text = text[:ent.value_start] + value + text[ent.value_end:]
    open(path, 'w').write(text)


def get_entry(path, keypath):
    """The text of the value of entry KEYPATH of the dictionary file PATH."""
    text = open(path).read()
    try:
        ent = find_entry(text, keypath)
    except DictEditError as err:
        raise DictEditError('%s: %s' % (path, err))
    return text[ent.value_start:ent.value_end]


def replace_text(path, old, new, count=1):
    """Replace the exact text OLD of file PATH by NEW; OLD must occur
    exactly COUNT times (count=0: at least once, every occurrence)."""
    text = open(path).read()
    n = text.count(old)
    if n == 0 or (count and n != count):
        raise DictEditError('%s: %r found %d times, %s expected'
                            % (path, old, n, count or 'at least once'))
    open(path, 'w').write(text.replace(old, new))
