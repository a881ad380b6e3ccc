#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Module
#     foamio
#
# Description
#     Reads what the tests need from OpenFOAM cases written in ascii: the
#     internalField of volScalarField and volVectorField files, time folders,
#     and a uniform lattice view of a 2D or 3D case (cell centres to (i,j,k)).
#     Run with Debian's /usr/bin/python3 (numpy).
#------------------------------------------------------------------------------
import os
import re
import numpy as np


def _strip_comments(text):
    text = re.sub(r'/\*.*?\*/', ' ', text, flags=re.S)
    return re.sub(r'//[^\n]*', ' ', text)


_NCOMP = {'scalar': 1, 'vector': 3, 'symmTensor': 6, 'tensor': 9,
          'label': 1}


def _read_binary(raw, path):
    """internalField of a binary field file (double precision, 32-bit
    labels, as Debian's OpenFOAM writes them)."""
    i = raw.find(b'internalField')
    m = re.compile(rb'internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(')
    mm = m.search(raw, i)
    if not mm:
        u = re.compile(rb'internalField\s+uniform\s+([^;]*);').search(raw, i)
        vals = u.group(1).decode().strip('()').split()
        return np.array([float(v) for v in vals])
    kind, n = mm.group(1).decode(), int(mm.group(2))
    ncomp = _NCOMP[kind]
    dtype = np.int32 if kind == 'label' else np.float64
    data = np.frombuffer(raw, dtype=dtype, count=n * ncomp, offset=mm.end())
    return data.astype(float) if ncomp == 1 else \
        data.reshape(n, ncomp).astype(float)


def read_internal_field(path):
    """internalField of a field file (ascii or binary): shape (n,) or
    (n, ncomp)."""
    with open(path, 'rb') as f:
        raw = f.read()
    header = raw[:raw.find(b'internalField')] if b'internalField' in raw \
        else raw[:2000]
    if re.search(rb'format\s+binary', header):
        return _read_binary(raw, path)
    text = _strip_comments(raw.decode('utf-8', errors='replace'))
    m = re.search(r'\binternalField\s+', text)
    if not m:
        raise ValueError('%s: no internalField' % path)
    rest = text[m.end():]
    if rest.startswith('uniform'):
        value = rest[len('uniform'):].split(';', 1)[0].strip()
        value = value.strip('()').split()
        return np.array([float(v) for v in value])
    m2 = re.match(r'nonuniform\s+List<(\w+)>\s*(\d+)\s*\(', rest)
    if not m2:
        raise ValueError('%s: cannot parse internalField' % path)
    kind, n = m2.group(1), int(m2.group(2))
    body = rest[m2.end():]
    # The list ends at the first ')' followed by ';' at its level
    end = body.find(')\n;')
    if end < 0:
        end = body.rfind(')')
    numbers = np.array(body[:end].replace('(', ' ').replace(')', ' ').split(),
                       dtype=float)
    ncomp = _NCOMP[kind]
    if numbers.size != n * ncomp:
        raise ValueError('%s: expected %d values, read %d'
                         % (path, n * ncomp, numbers.size))
    return numbers if ncomp == 1 else numbers.reshape(n, ncomp)


def times(case):
    """Numeric time folders of a case, sorted (as strings and floats)."""
    out = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if os.path.isdir(os.path.join(case, d)):
            out.append((t, d))
    out.sort()
    return [d for _, d in out]


def latest_time(case):
    return times(case)[-1]


def read(case, time, name):
    return read_internal_field(os.path.join(case, str(time), name))


class Lattice(object):
    """Cell centres of a uniform mesh mapped to a (nx, ny, nz) array."""

    def __init__(self, centres):
        c = np.asarray(centres)
        self.lo = c.min(axis=0)
        hi = c.max(axis=0)
        diffs = np.diff(np.unique(np.round(c[:, 0], 12)))
        self.dx = diffs.min() if diffs.size else 1.0
        self.n = tuple(int(round(v)) + 1 for v in (hi - self.lo) / self.dx)
        self.ijk = np.rint((c - self.lo) / self.dx).astype(int)
        self.centres = c

    def grid(self, values):
        """Values per cell into an array indexed [i, j, k(, comp)]."""
        values = np.asarray(values)
        shape = self.n + values.shape[1:]
        out = np.full(shape, np.nan)
        out[self.ijk[:, 0], self.ijk[:, 1], self.ijk[:, 2]] = values
        return out

    def axis(self, d):
        return self.lo[d] + self.dx * np.arange(self.n[d])


def case_and_png(argv):
    """The case directory (default '.') and the picture's file of a
    script's command line CASE [--png FILE] (None without --png)."""
    args = list(argv)
    png = None
    if '--png' in args:
        i = args.index('--png')
        png = args[i + 1]
        del args[i:i + 2]
    return (args[0] if args else '.'), png


def check(ok, what, value=None):
    """Print a PASS:/FAIL: line; return ok."""
    suffix = '' if value is None else ' (%s)' % value
    print('%s: %s%s' % ('PASS' if ok else 'FAIL', what, suffix))
    return ok


def check_open(ok, what, value=None):
    """For a specification item the code does not meet yet: print OPEN:
    with the measured value, what is still to do (Alltest lists it, not a
    failure), and return True. Never a PASS: an item that holds prints a
    FAIL: asking to promote it to check() and returns False, so that a met
    item cannot stay open where nothing can fail."""
    suffix = '' if value is None else ' (%s)' % value
    if ok:
        print('FAIL: %s%s: met, an open item no longer: promote it to '
              'foamio.check' % (what, suffix))
        return False
    print('OPEN: %s%s' % (what, suffix))
    return True


_CLASS_NCOMP = {'scalarField': 1, 'vectorField': 3, 'symmTensorField': 6,
                'tensorField': 9, 'labelField': 1}


def read_list(path):
    """A lagrangian field file (IOField: scalarField, vectorField,
    symmTensorField, tensorField, labelField), ascii or binary: shape (n,)
    or (n, ncomp)."""
    with open(path, 'rb') as f:
        raw = f.read()
    head_end = raw.find(b'}')
    header = raw[:head_end]
    cls = re.search(rb'class\s+(\w+)\s*;', header).group(1).decode()
    ncomp = _CLASS_NCOMP[cls]
    binary = re.search(rb'format\s+binary', header) is not None
    body = raw[head_end + 1:]
    # Skip comment lines after the header
    m = re.search(rb'(\d+)\s*\(', body)
    if not m:
        # uniform list "N{value}"
        mm = re.search(rb'(\d+)\s*\{([^}]*)\}', body)
        n = int(mm.group(1))
        vals = np.array(mm.group(2).decode().strip('()').split(), dtype=float)
        return np.tile(vals, (n, 1)) if ncomp > 1 else np.full(n, vals[0])
    n = int(m.group(1))
    if binary:
        dtype = np.int32 if cls == 'labelField' else np.float64
        data = np.frombuffer(body, dtype=dtype, count=n * ncomp,
                             offset=m.end()).astype(float)
    else:
        text = _strip_comments(body[m.end():].decode())
        end = text.rfind(')')
        data = np.array(text[:end].replace('(', ' ').replace(')', ' ').split(),
                        dtype=float)
    return data if ncomp == 1 else data.reshape(n, ncomp)


_ORDER_CACHE = {}


def _identity_order(cloud_dir):
    """The permutation that puts the points of a written cloud in the order
    of their identity (origProcId, origId), or None without those files."""
    ids_path = os.path.join(cloud_dir, 'origId')
    if not os.path.isfile(ids_path):
        return None
    key = (cloud_dir, os.path.getmtime(ids_path))
    if key not in _ORDER_CACHE:
        ids = read_list(ids_path)
        procs_path = os.path.join(cloud_dir, 'origProcId')
        procs = (read_list(procs_path) if os.path.isfile(procs_path)
                 else np.zeros_like(ids))
        _ORDER_CACHE[key] = np.lexsort((ids, procs))
    return _ORDER_CACHE[key]


def read_cloud(case, time, field, cloud='materialPoints', by_identity=True):
    """A field of a written cloud. By default in the order of the points'
    identity (origProcId, origId), the same at every time: the solver
    keeps its points sorted by the cell that holds them, so their order in
    the files changes as they move (by_identity=False: the files' order)."""
    cloud_dir = os.path.join(case, str(time), 'lagrangian', cloud)
    data = read_list(os.path.join(cloud_dir, field))
    if by_identity:
        order = _identity_order(cloud_dir)
        if order is not None and len(order) == len(data):
            data = data[order]
    return data


def newest_file(folder, file):
    """folder/file, or the newest of it and its variants <stem>_<time><ext>:
    a run whose function object finds its file there already (a second
    restart from the same time) writes <stem>_<start time><ext> beside it,
    as OpenFOAM's writeFile does, rather than overwrite the first run's.
    None if there is none."""
    stem, ext = os.path.splitext(file)
    variant = re.compile(re.escape(stem) + r'_[-+0-9.eE]+' + re.escape(ext)
                         + '$') if ext else None
    candidates = [os.path.join(folder, f) for f in os.listdir(folder)
                  if f == file or (variant and variant.match(f))]
    candidates = [c for c in candidates if os.path.isfile(c)]
    # (a variant is written only where the file was there already: at the
    # same modification time, within a file system's resolution, it wins)
    return max(candidates, key=lambda c: (os.path.getmtime(c),
                                          os.path.basename(c) != file)) \
        if candidates else None


def post_processing(case, name, file):
    """The rows of postProcessing/<name>/<start>/<file> over every start
    folder in time order, as numbers (a vector's parentheses dropped): a
    restart writes a new start folder, whose rows replace the earlier
    ones from its start time on; in a folder, the newest run's file
    (newest_file). An empty array if there is none."""
    root = os.path.join(case, 'postProcessing', name)
    rows = []
    if not os.path.isdir(root):
        return np.zeros((0, 0))
    number = re.compile(r'[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?')
    for start in sorted(os.listdir(root), key=float):
        path = newest_file(os.path.join(root, start), file)
        if path is None:
            continue
        rows = [r for r in rows if r[0] <= float(start)]
        for line in open(path):
            if line.startswith('#') or not line.strip():
                continue
            values = [float(v) for v in number.findall(line)]
            if values and values[0] > float(start) - 1e-12 * max(1.0, abs(float(start))):
                rows.append(values)
    if not rows:
        return np.zeros((0, 0))
    width = min(len(r) for r in rows)
    return np.array([r[:width] for r in rows])
