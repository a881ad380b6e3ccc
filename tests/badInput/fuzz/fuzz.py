#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     tests/badInput/fuzz/fuzz.py [--full] [--seed N] [--count N] [--bases A,B]
#                                 [--timeout S] [--match TEXT] [--keep]
#                                 [--list]
#
# Description
#     Nothing a user or a crash can do to a case makes the solver crash,
#     lie, or lose soil. Small copies of the tutorials (base cases, each
#     run costs a fraction of a second) are damaged one change at a time
#     and run:
#
#     1. dictionaries: every entry (recursively) of every dictionary of
#        constant/, system/ (blockMeshDict and setExprFieldsDict excepted:
#        OpenFOAM's utilities; decomposeParDict in the parallel case only)
#        and of the initial fields written as text (0/U, 0/p)
#        set to nan, inf, -inf, 1e400, 1e300, -1e300, 0, its negative, a
#        word (banana), an empty list, an empty dictionary, wrong
#        dimensions, or deleted; then the utility the file belongs to
#        (setMaterialPoints, decomposePar) and the solver, from the initial
#        time;
#     2. written data: the files of the written time a restart reads (the
#        populations lbmF*, node fields, the cloud lagrangian/materialPoints,
#        U, p, uniform/time) and what the utilities wrote in 0/ (the cloud
#        of setMaterialPoints, binary fields of setExprFields and
#        decomposePar): one value set to nan / inf / 1e300 (a bad label in
#        label lists), a run of random bytes overwritten, the file
#        truncated or deleted, a processor's lagrangian folder or the whole
#        time deleted; the dictionaries of the written time (uniform/time,
#        cloudProperties) get the mutations of 1. Then the solver: a
#        restart (startFrom latestTime) for two steps, or the run from 0.
#
#     Each run is judged:
#     - crash (FAIL): a signal, exit code >= 124 (timeout), a stack trace
#       in the log, or a non-zero exit without FOAM FATAL (IO) ERROR;
#     - clean refusal: non-zero exit with a FOAM FATAL (IO) ERROR; whether
#       the message names the mutated file is counted (OPEN: not yet a
#       failure);
#     - valid run (exit 0): allowed for dictionaries (the value may be
#       legal); for written data only if the final written time equals,
#       byte for byte, the unmutated reference run's: otherwise a silent
#       change (FAIL: the solver lies);
#     - every file in the case before the run is hashed: changed or
#       removed after it (FAIL), except a file moved unchanged into the
#       latest time set aside as <time>.incomplete.
#
#     The CI run (no --full) takes a seeded sample of --count mutations
#     (default 300) holding every kind of change of every base case and a
#     change of every file; --full runs them all (11483; 47 minutes on 2
#     cores, by hand). Two serial runs at a time, or one 2-rank parallel
#     run. Cases are made in ./run (git-ignored);
#     failing ones are kept there, passing ones removed (--keep: all kept).
#     Each failing mutation prints a FAIL: line (base case, file, entry,
#     mutation, program, exit code, kept case) and what its log says (the
#     FATAL message, the first frames of a stack trace, or the last lines).
#     Exit status 1 on any failure.
#
#     Run with Debian's /usr/bin/python3 (foamio imports numpy) in the
#     environment of etc/bashrc.
#------------------------------------------------------------------------------
import argparse
import concurrent.futures
import hashlib
import os
import random
import re
import resource
import shutil
import signal
import struct
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.environ.get('MPMLBM_PROJECT_DIR')
if not PROJECT:
    sys.exit('fuzz.py: MPMLBM_PROJECT_DIR is not set: source etc/bashrc')
# The test library and the project's dictionary parser (the one setEntry
# uses: keeps the text's spans, so that a mutation changes one entry and
# nothing else of the file)
sys.path.insert(0, os.path.join(PROJECT, 'tests', 'lib'))
sys.path.insert(0, os.path.join(PROJECT, 'bin', 'tools'))
import foamio          # noqa: E402
import foamDictEdit    # noqa: E402

RUN = os.path.join(HERE, 'run')
TUTORIALS = os.path.join(PROJECT, 'tutorials')
SOLVER = 'mpmLbmFoam'
NPROCS = 2

# Signs of a crash in a log. The banner's "trapFpe: Floating point
# exception trapping enabled" is not one; mpirun reports a rank's signal as
# "exited on signal N (...)"
CRASH_PATTERNS = re.compile(
    r'#\d+\s+Foam::error::printStack|#\d+\s+Foam::sig(Fpe|Segv|Bus|Ill)|'
    r'\bsig(Fpe|Segv)\b|Segmentation fault|'
    r'Floating point exception(?! trapping)|core dumped|terminate called|'
    r'std::bad_alloc|exited on signal')
FATAL = re.compile(r'FOAM FATAL (IO )?ERROR')


#------------------------------------------------------------------------------
# Base cases: small copies of the tutorials
#------------------------------------------------------------------------------

class Base(object):
    """A tutorial made small: EDITS are (file, keypath, value) set with the
    project's setEntry; SOIL: setMaterialPoints makes a cloud; ZERO_ORIG:
    0.orig copied to 0 (restore0Dir); EXPR: setExprFields (hydrostatic
    water); PARALLEL: decomposed on 2 ranks, run with mpirun; UTILITIES:
    OpenFOAM's programs run after blockMesh (setFields for alpha.water);
    CI: in the CI sample (else only with --full or --bases)."""

    def __init__(self, name, tutorial, edits, soil=False, zero_orig=False,
                 expr=False, parallel=False, utilities=(), ci=True):
        self.name = name
        self.tutorial = tutorial
        self.edits = edits
        self.soil = soil
        self.zero_orig = zero_orig
        self.expr = expr
        self.utilities = utilities
        self.ci = ci
        self.parallel = parallel
        self.dir = os.path.join(RUN, 'base', name)
        self.ok = False
        self.t1 = self.t2 = None
        self.control_damage = []    # files the unmutated runs changed

    def state(self, name):
        return os.path.join(self.dir, name)


def _times(dt, steps):
    return '%.10g' % (dt * steps)


def _control(dt):
    """endTime four steps, a written time every two: the first run writes
    the restart data (two steps), the restart (from the latest time) runs
    the other two."""
    return [('system/controlDict', 'startFrom', 'latestTime'),
            ('system/controlDict', 'deltaT', '%.10g' % dt),
            ('system/controlDict', 'endTime', _times(dt, 4)),
            ('system/controlDict', 'writeInterval', _times(dt, 2))]


_COUPLED = [('system/blockMeshDict', 'dx', '2'),
            ('system/blockMeshDict', 'nx', '40'),
            ('system/blockMeshDict', 'ny', '25')] + _control(0.01)
# The twoWay variant of the flagship's Allrun (porous flow, buoyancy,
# water under gravity starting hydrostatic)
_TWO_WAY = [('constant/physicsProperties', 'effects',
             '(fluid soil drag porousFlow buoyancy gravity)'),
            ('constant/physicsProperties', 'gravityCoeffs',
             '{ phases (fluid soil); }'),
            ('constant/dragProperties', 'drag', 'twoWay'),
            ('constant/fluidProperties', 'smagorinskyConstant', '0'),
            ('system/setMaterialPointsDict',
             'regions/soilColumn/geostaticCoeffs/waterDensity', '1000')]

BASES = [
    Base('lidDrivenCavity2D', 'fluid/lidDrivenCavity2D',
         [('system/blockMeshDict', 'n', '8')] + _control(7.8125e-4)),
    Base('lidDrivenCavity3D', 'fluid/lidDrivenCavity3D',
         [('system/blockMeshDict', 'n', '6')] + _control(0.001)),
    Base('poiseuilleChannel', 'fluid/poiseuilleChannel',
         [('system/blockMeshDict', 'ny', '8'),
          ('system/blockMeshDict', 'L', '0.5')] + _control(0.00390625)),
    Base('elasticColumn', 'soil/elasticColumn',
         [('system/blockMeshDict', 'vertices',
           '((0 0 0) (1 0 0) (1 3 0) (0 3 0) (0 0 0.25) (1 0 0.25) '
           '(1 3 0.25) (0 3 0.25))'),
          ('system/blockMeshDict', 'ny', '12'),
          ('system/setMaterialPointsDict', 'regions/column/max', '(1 2 1)'),
          # (the tutorial's probes inside the shorter column)
          ('system/controlDict', 'functions/column/probeLocations',
           '((0.375 1.875 0.125) (0.375 1.125 0.125))')]
         + _control(0.01), soil=True),
    Base('granularCollapse', 'soil/granularCollapse',
         [('system/blockMeshDict', 'vertices',
           '((0 0 0) (10 0 0) (10 5 0) (0 5 0) (0 0 0.5) (10 0 0.5) '
           '(10 5 0.5) (0 5 0.5))'),
          ('system/blockMeshDict', 'blocks',
           '(hex (0 1 2 3 4 5 6 7) (20 10 1) simpleGrading (1 1 1))'),
          ('system/setMaterialPointsDict', 'regions/block/max', '(4 4 1)'),
          ('system/setMaterialPointsDict',
           'regions/block/geostaticCoeffs/surface', '4')]
         + _control(0.01), soil=True),
    Base('soilColumnCollapse', 'coupled/soilColumnCollapse', _COUPLED,
         soil=True, zero_orig=True),
    Base('soilColumnCollapseTwoWay', 'coupled/soilColumnCollapse',
         _COUPLED + _TWO_WAY, soil=True, zero_orig=True, expr=True),
    Base('soilColumnCollapseParallel', 'coupled/soilColumnCollapse',
         _COUPLED, soil=True, zero_orig=True, parallel=True),
    # The free surface (Martin & Moyce's column: alpha.water by setFields,
    # its hydrostatic pressure by setExprFields)
    Base('damBreak', 'fluid/damBreak',
         [('system/blockMeshDict', 'n', '4'),
          ('system/blockMeshDict', 'nx', '24'),
          ('system/blockMeshDict', 'ny', '10')] + _control(6.25e-4),
         zero_orig=True, expr=True, utilities=('setFields',)),
    # Surface erosion (the hole erosion test's slot: wall shear stress,
    # the suspension's lattice and its patches, the erosion's state files)
    Base('holeErosionTest', 'coupled/holeErosionTest', _control(5e-3),
         soil=True),
    # A solid body in the water and the forces on it
    Base('cylinder2D', 'fluid/cylinder2D',
         [('system/blockMeshDict', 'n', '10'),
          ('system/blockMeshDict', 'nx', '220'),
          ('system/blockMeshDict', 'ny', '41'),
          ('system/controlDict', 'functions/cylinderForces/writeInterval',
           '1')] + _control(1.0 / 300),
         zero_orig=True, expr=True),
    # Heavier scenes, by hand (--full or --bases): the levee overtopped
    # (free surface, soil, two-way drag, porous flow, buoyancy, erosion)
    # and Terzaghi's consolidation (the surfaceLoad effect)
    Base('leveeOvertopping', 'coupled/leveeOvertopping',
         [('system/blockMeshDict', 'n1', '10'),
          ('system/blockMeshDict', 'n2', '66'),
          ('system/blockMeshDict', 'n3', '4'),
          ('system/blockMeshDict', 'ny', '30'),
          ('system/blockMeshDict', 'dz', '0.02')] + _control(0.001),
         soil=True, zero_orig=True, expr=True, ci=False),
    Base('terzaghiConsolidation', 'coupled/terzaghiConsolidation',
         _control(1.25e-4), soil=True, zero_orig=True, expr=True, ci=False),
]

# Dictionaries that belong to OpenFOAM's mesh and field utilities, run once
# when the base case is made, not by the solver
SKIPPED_DICTS = ('system/blockMeshDict', 'system/setExprFieldsDict',
                 'system/setFieldsDict')


#------------------------------------------------------------------------------
# Running programs
#------------------------------------------------------------------------------

def _descendants(pid):
    """Processes started by PID, its children's children included (ranks
    that mpirun may have put into process groups of their own)."""
    children = {}
    for d in os.listdir('/proc'):
        if not d.isdigit():
            continue
        try:
            with open('/proc/%s/stat' % d) as f:
                ppid = int(f.read().rsplit(')', 1)[1].split()[1])
        except (OSError, IndexError, ValueError):
            continue
        children.setdefault(ppid, []).append(int(d))
    out, todo = [], [pid]
    while todo:
        p = todo.pop()
        for c in children.get(p, []):
            out.append(c)
            todo.append(c)
    return out


class Result(object):
    def __init__(self, program, rc, log, timed_out):
        self.program = program
        self.rc = rc
        self.log = log
        self.timed_out = timed_out

    def text(self):
        try:
            with open(self.log, errors='replace') as f:
                return f.read()
        except OSError:
            return ''


def run_program(case, args, parallel, timeout, tag=''):
    """Run ARGS in CASE (with mpirun on NPROCS ranks when PARALLEL), its
    output into log.fuzz.<program><tag>. A timeout kills the program and
    what it started and counts as exit code 124, as timeout(1) does."""
    program = args[0]
    log = os.path.join(case, 'log.fuzz.%s%s' % (program, tag))
    cmd = (['mpirun', '-np', str(NPROCS)] + args + ['-parallel']
           if parallel else list(args))
    # PWD as a shell would set it: OpenFOAM warns into the stack traces
    # otherwise. Open MPI may start more ranks than there are free cores,
    # and on one machine shared memory is all it needs: probing the network
    # transports costs 1.5 s a run
    env = dict(os.environ, PWD=os.path.abspath(case),
               OMPI_MCA_rmaps_base_oversubscribe='1',
               OMPI_MCA_btl='self,vader', OMPI_MCA_pml='ob1')
    with open(log, 'w') as out:
        proc = subprocess.Popen(cmd, cwd=case, stdin=subprocess.DEVNULL,
                                stdout=out, stderr=subprocess.STDOUT,
                                env=env, start_new_session=True)
        try:
            rc = proc.wait(timeout=timeout)
            timed_out = False
        except subprocess.TimeoutExpired:
            for pid in _descendants(proc.pid) + [proc.pid]:
                try:
                    os.kill(pid, signal.SIGKILL)
                except OSError:
                    pass
            proc.wait()
            rc, timed_out = 124, True
    return Result(program, rc, log, timed_out)


# The project's programs, decomposePar among them (bin/decomposePar checks
# the dictionary before OpenFOAM's runs): a crash of one of OpenFOAM's
# other utilities is reported apart
OURS = (SOLVER, 'setMaterialPoints', 'decomposePar')


def verdict(result):
    """'crash', 'foreign' (a crash of OpenFOAM's utility), 'refused' or
    'ok' for one program's run."""
    text = result.text()
    crashed = (result.rc < 0 or result.rc >= 124 or result.timed_out
               or CRASH_PATTERNS.search(text)
               or (result.rc != 0 and not FATAL.search(text)))
    if crashed:
        return 'crash' if result.program in OURS \
            or result.program == 'mpirun' else 'foreign'
    if result.rc != 0:
        return 'refused'
    return 'ok'


#------------------------------------------------------------------------------
# Case files: copies, hashes, comparisons
#------------------------------------------------------------------------------

def copy_case(src, dst):
    if os.path.exists(dst):
        shutil.rmtree(dst)
    shutil.copytree(src, dst, symlinks=True)


def is_time(name):
    try:
        float(name)
        return True
    except ValueError:
        return False


def time_dirs(case):
    return sorted((d for d in os.listdir(case) if is_time(d)
                   and os.path.isdir(os.path.join(case, d))), key=float)


def latest_time(case, parallel):
    where = os.path.join(case, 'processor0') if parallel else case
    t = time_dirs(where) if os.path.isdir(where) else []
    return t[-1] if t else None


def hash_files(case):
    """sha1 of every file of CASE by relative path, the fuzzer's own logs
    left out."""
    out = {}
    for root, dirs, files in os.walk(case):
        for f in files:
            if f.startswith('log.fuzz.'):
                continue
            path = os.path.join(root, f)
            if os.path.islink(path):
                continue
            h = hashlib.sha1()
            with open(path, 'rb') as fh:
                h.update(fh.read())
            out[os.path.relpath(path, case)] = h.hexdigest()
    return out


def damaged_files(before, after):
    """Files hashed BEFORE that are changed or gone AFTER, unless moved
    unchanged into their time's <time>.incomplete folder (the solver sets
    an incomplete latest time aside under that name)."""
    bad = []
    for path, digest in sorted(before.items()):
        if after.get(path) == digest:
            continue
        parts = path.split(os.sep)
        moved = False
        for i, p in enumerate(parts[:-1]):
            if is_time(p):
                alt = os.sep.join(parts[:i] + [p + '.incomplete']
                                  + parts[i + 1:])
                if after.get(alt) == digest:
                    moved = True
        if not moved:
            bad.append('%s %s' % (path, 'changed' if path in after
                                  else 'removed'))
    return bad


def final_files(case, t, parallel):
    """Relative paths of the files of time T (in every processor folder
    when PARALLEL)."""
    roots = ([d for d in sorted(os.listdir(case)) if d.startswith('processor')]
             if parallel else ['.'])
    out = []
    for r in roots:
        top = os.path.join(case, r, t)
        for root, dirs, files in os.walk(top):
            for f in files:
                out.append(os.path.normpath(os.path.relpath(
                    os.path.join(root, f), case)))
    return sorted(out)


def compare_final(ref, case, t, parallel):
    """Differences of CASE's time T from the reference's, byte for byte:
    a list of 'path: why' (empty when identical)."""
    a = final_files(ref, t, parallel)
    b = final_files(case, t, parallel)
    if not b:
        return ['no time %s written' % t]
    diffs = ['%s: missing' % p for p in sorted(set(a) - set(b))]
    diffs += ['%s: extra' % p for p in sorted(set(b) - set(a))]
    for p in sorted(set(a) & set(b)):
        with open(os.path.join(ref, p), 'rb') as f1, \
                open(os.path.join(case, p), 'rb') as f2:
            if f1.read() != f2.read():
                diffs.append('%s: differs' % p)
    return diffs


#------------------------------------------------------------------------------
# Preparing the base cases (once)
#------------------------------------------------------------------------------

class PrepError(Exception):
    pass


def _step(case, args, parallel=False, tag='', timeout=300):
    r = run_program(case, args, parallel, timeout, tag)
    if r.rc != 0:
        raise PrepError('%s in %s: exit %d; last lines of %s:\n%s'
                        % (' '.join(args), os.path.relpath(case, HERE), r.rc,
                           os.path.relpath(r.log, HERE),
                           '\n'.join(r.text().splitlines()[-12:])))


def _set(case, edits):
    for f, key, value in edits:
        foamDictEdit.set_entry(os.path.join(case, f), key, value)


def prepare(base, timeout):
    """The states a mutation starts from, each a complete case:
    bare (mesh and initial water, no cloud), initial (with the cloud),
    restart (initial run two steps: the written time t1 a restart reads),
    refInitial and refRestart (the unmutated runs to t2, each made twice to
    show they are reproducible bit for bit); for the parallel case,
    undecomposed (the serial initial state) and the bare and initial states
    decomposed."""
    os.makedirs(base.dir)
    bare = base.state('bare')
    src = os.path.join(TUTORIALS, base.tutorial)
    os.makedirs(bare)
    for d in ('constant', 'system', '0', '0.orig'):
        if os.path.isdir(os.path.join(src, d)):
            shutil.copytree(os.path.join(src, d), os.path.join(bare, d))
    _set(bare, base.edits)
    if base.zero_orig:
        shutil.copytree(os.path.join(bare, '0.orig'), os.path.join(bare, '0'))
    _step(bare, ['blockMesh'], tag='.prep')
    for utility in base.utilities:
        _step(bare, [utility], tag='.prep')
    if base.expr:
        _step(bare, ['setExprFields'], tag='.prep')
    initial = base.state('initial')
    copy_case(bare, initial)
    if base.soil:
        _step(initial, ['setMaterialPoints'], tag='.prep')
    if base.parallel:
        # decomposeParDict's mutations start from the serial case, the
        # others from the decomposed one (with, or for setMaterialPoints
        # -parallel without, the cloud)
        os.rename(initial, base.state('undecomposed'))
        copy_case(base.state('undecomposed'), initial)
        _step(initial, ['decomposePar'], tag='.prep')
        # Decomposed before seeding (setMaterialPoints -parallel follows):
        # no points to weigh the cells by, no cellWork field to read
        dict_path = os.path.join(bare, 'system', 'decomposeParDict')
        with open(dict_path) as f:
            text = f.read()
        with open(dict_path, 'w') as f:
            f.write(re.sub(r'(?m)^\s*weightField\s+\S+;\s*\n', '', text))
        _step(bare, ['decomposePar'], tag='.prep')
    par = base.parallel

    restart = base.state('restart')
    copy_case(initial, restart)
    end = foamDictEdit.get_entry(os.path.join(restart, 'system/controlDict'),
                                 'endTime')
    interval = foamDictEdit.get_entry(
        os.path.join(restart, 'system/controlDict'), 'writeInterval')
    _set(restart, [('system/controlDict', 'endTime', interval)])
    _step(restart, [SOLVER], par, tag='.prep', timeout=timeout)
    _set(restart, [('system/controlDict', 'endTime', end)])
    base.t1 = latest_time(restart, par)
    if base.t1 is None or float(base.t1) == 0:
        raise PrepError('%s: the first run wrote no time' % base.name)

    # The references, each run twice: the same run must give the same
    # bytes, or a silent change could not be told from noise
    for ref in ('refInitial', 'refRestart'):
        src = initial if ref == 'refInitial' else restart
        for k in ('', '2'):
            copy_case(src, base.state(ref + k))
            before = hash_files(base.state(ref + k))
            _step(base.state(ref + k), [SOLVER], par, tag='.prep',
                  timeout=timeout)
            # The unmutated run as the control of the written-files check
            base.control_damage += damaged_files(
                before, hash_files(base.state(ref + k)))
        t2 = latest_time(base.state(ref), par)
        if base.t2 not in (None, t2):
            raise PrepError('%s: %s ends at %s, not %s'
                            % (base.name, ref, t2, base.t2))
        base.t2 = t2
        if float(t2) <= float(base.t1):
            raise PrepError('%s: %s wrote no time after %s'
                            % (base.name, ref, base.t1))
        diffs = compare_final(base.state(ref), base.state(ref + '2'), t2, par)
        if diffs:
            raise PrepError('%s: %s is not reproducible: %s'
                            % (base.name, ref, ', '.join(diffs[:5])))
        shutil.rmtree(base.state(ref + '2'))
    base.ok = True


#------------------------------------------------------------------------------
# Dictionary mutations
#------------------------------------------------------------------------------

BAD_NUMBERS = ['nan', 'inf', '-inf', '1e400', '1e300', '-1e300', '0']
_NUMBER = re.compile(r'[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$')


class DictEntry(object):
    """An entry of a dictionary file: key path, the spans of its value and
    of the whole entry (for deletion), and its numbers (outside dimension
    sets, list sizes excluded)."""

    def __init__(self, text, toks, ent, keypath):
        self.keypath = keypath
        self.is_dict = text[ent.value_start] == '{'
        self.value = (ent.value_start, ent.value_end)
        if self.is_dict:
            self.entry = (ent.start, ent.value_end)
        else:
            semi = text.find(';', ent.value_end)
            self.entry = (ent.start, semi + 1 if semi >= 0 else ent.value_end)
        self.numbers = []
        self.dims = None
        if self.is_dict:
            return
        inside = [t for t in toks
                  if t[1] >= ent.value_start and t[2] <= ent.value_end]
        depth = 0
        for i, (kind, s, e) in enumerate(inside):
            w = text[s:e]
            if kind == 'punct' and w == '[':
                depth += 1
                if self.dims is None:
                    self.dims = [s, None]
            elif kind == 'punct' and w == ']':
                depth -= 1
                if self.dims is not None and self.dims[1] is None:
                    self.dims[1] = e
            elif kind == 'word' and depth == 0 and _NUMBER.match(w):
                nxt = inside[i + 1] if i + 1 < len(inside) else None
                if nxt and text[nxt[1]:nxt[2]] == '(':
                    continue    # a list's size
                self.numbers.append((s, e))

    def hows(self):
        if self.is_dict:
            return ['nan', 'banana', 'emptyList', 'emptyDict', 'delete']
        out = list(BAD_NUMBERS)
        if self.numbers:
            out.append('negative')
        out += ['banana', 'emptyList']
        if self.dims:
            out.append('wrongDims')
        return out + ['delete']

    def apply(self, text, how):
        """TEXT with this entry mutated by HOW."""
        vs, ve = self.value
        if how == 'delete':
            s, e = self.entry
            return text[:s] + text[e:]
        if self.is_dict:
            new = {'nan': 'nan;', 'banana': 'banana;', 'emptyList': '();',
                   'emptyDict': '{}'}[how]
            return text[:vs] + new + text[ve:]
        if how == 'banana':
            return text[:vs] + 'banana' + text[ve:]
        if how == 'emptyList':
            return text[:vs] + '()' + text[ve:]
        if how == 'wrongDims':
            s, e = self.dims
            old = re.sub(r'\s+', ' ', text[s:e])
            new = '[0 0 1 0 0 0 0]' if old != '[0 0 1 0 0 0 0]' \
                else '[1 0 0 0 0 0 0]'
            return text[:s] + new + text[e:]
        if how == 'negative':
            out = text
            for s, e in reversed(self.numbers):
                w = out[s:e]
                neg = w[1:] if w.startswith('-') else \
                    '-' + (w[1:] if w.startswith('+') else w)
                out = out[:s] + neg + out[e:]
            return out
        # A bad number: in place of every number of the value (a vector's
        # components, a uniform field's value), or of the whole value when
        # it has none (a word, a dimension set)
        if not self.numbers:
            return text[:vs] + how + text[ve:]
        out = text
        for s, e in reversed(self.numbers):
            out = out[:s] + how + out[e:]
        return out


def dict_entries(path, header=True):
    """DictEntry of every entry of the dictionary file PATH, sub-entries
    included (the FoamFile header's unless HEADER is False)."""
    with open(path, errors='replace') as f:
        text = f.read()
    toks = list(foamDictEdit._tokens(text))
    entries, _ = foamDictEdit._parse_entries(text, toks, 0, None)
    out = []

    def walk(ents, prefix):
        for e in ents:
            if e.value_start is None:
                continue
            key = prefix + e.keyword
            if not header and key.split('/')[0] == 'FoamFile':
                continue
            out.append(DictEntry(text, toks, e, key))
            walk(e.children, key + '/')
    walk(entries, '')
    return out


def is_dictionary(path):
    """A file in ascii: a dictionary, or a field file of the initial time
    as a user writes it (0/U, 0/p)."""
    try:
        with open(path, 'rb') as f:
            head = f.read(4000)
    except OSError:
        return False
    m = re.search(rb'FoamFile\s*\{([^}]*)\}', head)
    if not m or re.search(rb'format\s+binary', m.group(1)):
        return False
    return True


#------------------------------------------------------------------------------
# Data mutations (written files)
#------------------------------------------------------------------------------

_NCOMP = {'scalar': 1, 'vector': 3, 'symmTensor': 6, 'tensor': 9,
          'sphericalTensor': 1, 'label': 1}
_FIELD_NCOMP = {'scalarField': 1, 'vectorField': 3, 'symmTensorField': 6,
                'tensorField': 9, 'labelField': 1}
# A cloud's position records (OpenFOAM v1912): coordinates hold the
# barycentric coordinates (4 scalars) and cell, tetFace, tetPt (labels),
# positions the position (3 scalars) and cell
_CLOUD_SCALARS = {'coordinates': 4, 'positions': 3}
LABEL_VALUES = {'nan': -1, 'inf': 2147483647, '1e300': -2147483648}


class ListFile(object):
    """Where the data of a written list file is: the first list after the
    header (a field's internalField, an IOField, a cloud's records)."""

    def __init__(self, raw, name):
        self.raw = raw
        start = raw.find(b'FoamFile')
        self.header_end = raw.find(b'}', start) + 1 if start >= 0 else 0
        header = raw[:self.header_end]
        self.binary = re.search(rb'format\s+binary', header) is not None
        m = re.search(rb'class\s+([^;]+);', header)
        self.cls = m.group(1).decode(errors='replace').strip() if m else ''
        self.start = self.n = None
        self.ncomp, self.label, self.record = 1, False, None
        if self.cls.startswith('vol') or self.cls.startswith('surface'):
            m = re.compile(rb'internalField\s+nonuniform\s+List<(\w+)>'
                           rb'\s*(\d+)\s*\(').search(raw, self.header_end)
            if m:
                t = m.group(1).decode()
                self.ncomp = _NCOMP.get(t, 1)
                self.label = t == 'label'
        elif self.cls in _FIELD_NCOMP or self.cls.startswith('Cloud'):
            m = re.compile(rb'(\d+)\s*\(').search(raw, self.header_end)
            self.ncomp = _FIELD_NCOMP.get(self.cls, 1)
            self.label = self.cls == 'labelField'
        else:
            m = None
        if not m:
            return
        self.n = int(m.group(2) if m.lastindex == 2 else m.group(1))
        self.start = m.end()
        if self.cls.startswith('Cloud') and self.binary and self.n:
            self._records(name)
        self.end = self._end()

    def _records(self, name):
        """Size of a binary cloud's records '(' payload ')' '\\n'."""
        raw, n = self.raw, self.n
        rec0 = raw.find(b'(', self.start)
        for p in range(8, 400):
            step = p + 3
            if all(raw[rec0 + k * step:rec0 + k * step + 1] == b'('
                   and raw[rec0 + k * step + p + 1:
                           rec0 + k * step + p + 2] == b')'
                   for k in range(n)):
                self.record = (rec0, p, _CLOUD_SCALARS.get(name, p // 8))
                return

    def _end(self):
        if self.binary and self.record:
            rec0, p, _ = self.record
            return rec0 + self.n * (p + 3)
        if self.binary:
            size = 4 if self.label else 8
            return min(len(self.raw), self.start + self.n * self.ncomp * size)
        e = self.raw.find(b'\n)', self.start)
        return e if e >= 0 else len(self.raw)

    def has_values(self):
        return bool(self.n) and (not self.binary or not self.cls.startswith(
            'Cloud') or self.record is not None)

    def set_value(self, rng, how):
        """The file with one value set to HOW (a bad label in a label
        list); returns (raw, description)."""
        raw = self.raw
        if self.binary:
            if self.record:
                rec0, p, nscalar = self.record
                r, c = rng.randrange(self.n), rng.randrange(nscalar)
                off = rec0 + r * (p + 3) + 1 + 8 * c
                data = struct.pack('<d', float(how))
                where = 'record %d scalar %d' % (r, c)
            elif self.label:
                i = rng.randrange(self.n * self.ncomp)
                off = self.start + 4 * i
                data = struct.pack('<i', LABEL_VALUES[how])
                where = 'index %d = %d' % (i, LABEL_VALUES[how])
            else:
                i = rng.randrange(self.n * self.ncomp)
                off = self.start + 8 * i
                data = struct.pack('<d', float(how))
                where = 'index %d' % i
            return raw[:off] + data + raw[off + len(data):], where
        text = raw[self.start:self.end].decode(errors='replace')
        nums = list(re.finditer(r'(?<![\w.])[-+]?(\d+\.?\d*|\.\d+)'
                                r'([eE][-+]?\d+)?(?![\w.])', text))
        k = rng.randrange(len(nums))
        value = str(LABEL_VALUES[how]) if self.label else how
        m = nums[k]
        new = text[:m.start()] + value + text[m.end():]
        return (raw[:self.start] + new.encode() + raw[self.end:],
                'number %d (%s)' % (k, m.group(0)))


def overwrite_bytes(raw, rng, lo, hi):
    """A run of 1 to 16 random bytes written over RAW[lo:hi] (changed for
    sure)."""
    hi = max(hi, lo + 1)
    n = rng.randint(1, 16)
    off = rng.randrange(lo, max(lo + 1, min(hi, len(raw)) - n + 1))
    while True:
        data = bytes(rng.randrange(256) for _ in range(n))
        if data != raw[off:off + n]:
            break
    return raw[:off] + data + raw[off + n:], '%d bytes at %d' % (n, off)


#------------------------------------------------------------------------------
# Mutations
#------------------------------------------------------------------------------

class Mutation(object):
    """One change to one base case: KIND is 'dict' (an entry of a user's
    dictionary), 'data' (a written file or folder) or 'dataDict' (an entry
    of a written dictionary); STATE the base's state it starts from; FILE
    the path in the case; ENTRY the key path; HOW the change."""

    def __init__(self, base, kind, state, file, how, entry=None):
        self.base = base
        self.kind = kind
        self.state = state
        self.file = file
        self.how = how
        self.entry = entry
        self.key = '%s:%s:%s:%s:%s' % (base.name, state, file,
                                       entry.keypath if entry else '', how)
        self.detail = ''

    @property
    def group(self):
        """Stratum of the CI sample: every base case gets every kind of
        change."""
        return (self.base.name, self.kind, self.how.split(':')[0])

    @property
    def file_group(self):
        """Second stratum: every file (of some base case; its time and
        processor folders aside) gets some change."""
        parts = [p for p in self.file.split('/')
                 if not p.startswith('processor')]
        if self.kind != 'dict' and parts and is_time(parts[0]):
            parts = parts[1:]
        return (self.kind, '/'.join(parts) or '<time>')

    def label(self):
        entry = ' %s' % self.entry.keypath if self.entry else ''
        detail = ' (%s)' % self.detail if self.detail else ''
        return '%s %s%s %s%s' % (self.base.name, self.file, entry, self.how,
                                 detail)

    def names(self):
        """Names by which a refusal names the mutated file."""
        parts = self.file.split('/')
        out = {parts[-1], self.file}
        if parts[-1] in ('materialPoints', 'lagrangian'):
            out |= {'lagrangian', 'materialPoints'}
        if parts[-1] == 'cloudProperties':
            out.add('materialPoints')
        return out

    def judged_as_data(self):
        return self.kind in ('data', 'dataDict')

    def reference(self):
        return self.base.state('refRestart' if self.state == 'restart'
                               else 'refInitial')

    def programs(self):
        """(args, parallel) run in turn, from the first that applies."""
        par = self.base.parallel
        if self.state == 'bare':
            return [(['setMaterialPoints'], par), ([SOLVER], par)]
        if self.state == 'undecomposed':
            return [(['decomposePar'], False), ([SOLVER], True)]
        return [([SOLVER], par)]

    def apply(self, case, rng):
        path = os.path.join(case, self.file)
        if self.kind in ('dict', 'dataDict'):
            with open(path, errors='replace') as f:
                text = f.read()
            with open(path, 'w') as f:
                f.write(self.entry.apply(text, self.how))
            return
        if self.how == 'delete':
            os.remove(path)
            return
        if self.how == 'deleteDir':
            shutil.rmtree(path)
            return
        with open(path, 'rb') as f:
            raw = f.read()
        if self.how == 'truncate':
            size = rng.randrange(len(raw))
            self.detail = 'to %d of %d bytes' % (size, len(raw))
            raw = raw[:size]
        elif self.how == 'bytes':
            lf = ListFile(raw, os.path.basename(path))
            lo, hi = ((lf.start, lf.end) if lf.start is not None
                      else (lf.header_end, len(raw)))
            raw, self.detail = overwrite_bytes(raw, rng, lo, hi)
        elif self.how.startswith('value:'):
            lf = ListFile(raw, os.path.basename(path))
            raw, self.detail = lf.set_value(rng, self.how.split(':')[1])
        with open(path, 'wb') as f:
            f.write(raw)


def _rel_files(case, top):
    out = []
    for root, dirs, files in os.walk(os.path.join(case, top)):
        dirs.sort()
        for f in sorted(files):
            out.append(os.path.relpath(os.path.join(root, f), case))
    return out


def dict_mutations(base):
    """Every entry of every user dictionary, every mutation."""
    out = []
    files = []
    for d in ('constant', 'system'):
        top = os.path.join(base.state('initial'), d)
        for f in sorted(os.listdir(top)):
            rel = '%s/%s' % (d, f)
            if (not os.path.isfile(os.path.join(top, f))
                    or rel in SKIPPED_DICTS):
                continue
            if rel == 'system/decomposeParDict':
                if base.parallel:
                    files.append((rel, 'undecomposed'))
                continue
            if rel == 'system/setMaterialPointsDict':
                files.append((rel, 'bare'))
                continue
            files.append((rel, 'initial'))
    # The initial fields: 0/ (processor*/0/ in parallel), clouds aside
    zeros = (['processor%d/0' % i for i in range(NPROCS)] if base.parallel
             else ['0'])
    for z in zeros:
        top = os.path.join(base.state('initial'), z)
        for f in sorted(os.listdir(top)):
            if os.path.isfile(os.path.join(top, f)):
                files.append(('%s/%s' % (z, f), 'initial'))
    for rel, st in files:
        path = os.path.join(base.state(st), rel)
        if not is_dictionary(path):
            continue
        for e in dict_entries(path):
            for how in e.hows():
                out.append(Mutation(base, 'dict', st, rel, how, e))
    return out


def data_mutations(base):
    """The written data: the restart's time t1, and what the utilities
    wrote at time 0: the cloud of setMaterialPoints (with its uniform/
    properties), binary fields (setExprFields, decomposePar)."""
    out = []
    par = base.parallel
    roots = ['processor%d' % i for i in range(NPROCS)] if par else ['']
    for state, t in (('restart', base.t1), ('initial', '0')):
        case = base.state(state)
        for r in roots:
            tdir = os.path.join(r, t) if r else t
            if state == 'restart':
                tops = [tdir]
                dirs = [os.path.join(tdir, 'lagrangian', 'materialPoints'),
                        os.path.join(tdir, 'uniform'), tdir]
            else:
                # 0/ holds the user's fields (dictionary mutations) and
                # what setMaterialPoints wrote
                tops = [os.path.join(tdir, 'lagrangian'),
                        os.path.join(tdir, 'uniform')]
                dirs = [os.path.join(tdir, 'lagrangian', 'materialPoints')]
            files = []
            for top in tops:
                if os.path.isdir(os.path.join(case, top)):
                    files += _rel_files(case, top)
            if state == 'initial' and os.path.isdir(os.path.join(case, tdir)):
                # Binary initial fields (setExprFields' p, decomposePar's
                # processor fields): data, not a user's text
                files += [os.path.join(tdir, f)
                          for f in sorted(os.listdir(os.path.join(case, tdir)))
                          if os.path.isfile(os.path.join(case, tdir, f))
                          and not is_dictionary(os.path.join(case, tdir, f))]
            for rel in files:
                out += _file_mutations(base, state, rel)
            for d in dirs:
                if os.path.isdir(os.path.join(case, d)):
                    out.append(Mutation(base, 'data', state, d, 'deleteDir'))
    return out


def _file_mutations(base, state, rel):
    path = os.path.join(base.state(state), rel)
    with open(path, 'rb') as f:
        raw = f.read()
    lf = ListFile(raw, os.path.basename(rel))
    out = []
    if lf.cls == 'dictionary' and not lf.binary:
        for e in dict_entries(path, header=False):
            for how in e.hows():
                out.append(Mutation(base, 'dataDict', state, rel, how, e))
        hows = ['truncate', 'delete']
    else:
        hows = ['bytes', 'truncate', 'delete']
        if lf.has_values():
            hows = ['value:nan', 'value:inf', 'value:1e300'] + hows
    for how in hows:
        out.append(Mutation(base, 'data', state, rel, how))
    return out


def sample(mutations, count, seed):
    """COUNT mutations, seeded: one of every group (base case, kind,
    change), one of every file not yet changed, then at random from the
    rest."""
    rng = random.Random(seed)
    groups, files = {}, {}
    for m in mutations:
        groups.setdefault(m.group, []).append(m)
        files.setdefault(m.file_group, []).append(m)
    chosen = [rng.choice(groups[g]) for g in sorted(groups)]
    covered = set(m.file_group for m in chosen)
    chosen += [rng.choice(files[f]) for f in sorted(files)
               if f not in covered]
    picked = set(id(m) for m in chosen)
    rest = [m for m in mutations if id(m) not in picked]
    rng.shuffle(rest)
    chosen += rest[:max(0, count - len(chosen))]
    return chosen


#------------------------------------------------------------------------------
# Running and judging one mutation
#------------------------------------------------------------------------------

class Outcome(object):
    def __init__(self, mutation, case):
        self.m = mutation
        self.case = case
        self.verdict = None       # crash, refused, valid, silent
        self.names_file = None    # refused: whether the message names it
        self.result = None        # the last program run
        self.damaged = []
        self.diffs = []
        self.error = None         # the fuzzer could not apply it
        self.excerpt = []         # what the log says (the case may go)


def names_file(text, names):
    """Whether the FATAL message (from its first line to the end) names
    one of NAMES as a word or a path."""
    m = FATAL.search(text)
    msg = text[m.start():] if m else text
    for n in names:
        if re.search(r'(?<![\w.])%s(?![\w])' % re.escape(n), msg):
            return True
    return False


def warns_of(text, names):
    """Whether a FOAM Warning of the log names one of NAMES, or says the
    time's files are not checked (no restartManifest)."""
    for m in re.finditer(r'FOAM Warning', text):
        w = text[m.start():m.start() + 3000]
        if 'restartManifest' in w or any(
                re.search(r'(?<![\w.])%s(?![\w])' % re.escape(n), w)
                for n in names):
            return True
    return False


def run_mutation(m, index, seed, timeout):
    case = os.path.join(RUN, 'cases', '%04d' % index)
    out = Outcome(m, case)
    copy_case(m.base.state(m.state), case)
    try:
        m.apply(case, random.Random('%s:%s' % (seed, m.key)))
    except Exception as err:     # a bug of the fuzzer, not of the solver
        out.error = '%s: %s' % (type(err).__name__, err)
        out.verdict = 'error'
        return out
    before = hash_files(case)
    for i, (args, par) in enumerate(m.programs()):
        r = run_program(case, args, par, timeout)
        out.result = r
        v = verdict(r)
        if v != 'ok':
            out.verdict = v
            break
    else:
        out.verdict = 'valid'
    if out.verdict == 'refused':
        out.names_file = names_file(out.result.text(), m.names())
    if out.verdict == 'valid' and m.judged_as_data():
        out.diffs = compare_final(m.reference(), case, m.base.t2,
                                  m.base.parallel)
        if out.diffs:
            # A change the run reported (a warning naming the file, or
            # that the time's files are not checked) is not silent
            out.verdict = 'warned' if warns_of(out.result.text(), m.names()) \
                else 'silent'
    out.damaged = damaged_files(before, hash_files(case))
    if out.result:
        out.excerpt = excerpt(out.result.text())
        if out.result.timed_out:
            out.excerpt.append('(killed after %g s)' % timeout)
    return out


def failed(o):
    return o.verdict in ('crash', 'silent', 'error') or o.damaged


#------------------------------------------------------------------------------
# Report
#------------------------------------------------------------------------------

_FRAME = re.compile(r'^(\[(\d+)\] )?#\d+\s')
_HANDLER = re.compile(r'sigFpe::sigHandler|sigSegv::sigHandler|'
                      r'error::abort|#\d+\s+\? in /lib')


def excerpt(text, n=6):
    """What a log says went wrong: the first FOAM FATAL message (N lines)
    and the first stack trace (its first frames, of one rank), or, with
    neither, the last N lines."""
    lines = text.splitlines()
    out = []
    for i, line in enumerate(lines):
        if FATAL.search(line):
            out += [x for x in lines[i:i + n] if x.strip()]
            break
    frames = [x for x in lines if _FRAME.match(x)]
    if frames:
        # The frames of one rank below the handler: where it happened
        rank = _FRAME.match(frames[0]).group(2)
        frames = [x for x in frames if _FRAME.match(x).group(2) == rank]
        out += [frames[0]] + [x for x in frames[1:]
                              if not _HANDLER.search(x)][:8]
    for line in lines:
        if 'exited on signal' in line:
            out.append(line.strip())
    return out or lines[-n:]


def report_failure(o, what):
    r = o.result
    prog = ('%s exit %d%s' % (r.program, r.rc, ' (timeout)' if r.timed_out
                              else '')) if r else 'not run'
    print('FAIL: %s: %s: %s; case kept: %s'
          % (what, o.m.label(), prog, os.path.relpath(o.case, HERE)))
    if what == 'silent change':
        # uniform/ holds the run's bookkeeping (time index, the cloud's
        # particle count), the rest its results: told apart for the reader,
        # both a change the run did not report
        results = [d for d in o.diffs if '/uniform/' not in '/' + d]
        print('    %s at t = %s: %s'
              % ('results differ from the unmutated run' if results
                 else 'only uniform/ differs from the unmutated run',
                 o.m.base.t2, ', '.join(o.diffs[:4])
                 + (' ... (%d files)' % len(o.diffs) if len(o.diffs) > 4
                    else '')))
    if what == 'files damaged':
        print('    ' + ', '.join(o.damaged[:4])
              + (' ...' if len(o.damaged) > 4 else ''))
    if what == 'fuzzer error':
        print('    ' + o.error)
    for line in o.excerpt:
        print('    | ' + line)


def main():
    ap = argparse.ArgumentParser(description='Fuzz mpmLbmFoam cases.')
    ap.add_argument('--full', action='store_true',
                    help='every mutation of every entry (thousands)')
    ap.add_argument('--seed', type=int, default=1)
    ap.add_argument('--count', type=int, default=300,
                    help='mutations of the CI sample (without --full)')
    ap.add_argument('--timeout', type=float, default=None,
                    help='seconds per program run (default 20, 60 --full)')
    ap.add_argument('--bases', default=None,
                    help='only these base cases (comma-separated names)')
    ap.add_argument('--match', default=None,
                    help='only mutations whose description contains TEXT')
    ap.add_argument('--keep', action='store_true',
                    help='keep every case, not only the failing ones')
    ap.add_argument('--list', action='store_true',
                    help='list the mutations (after --match and the '
                    'sample) and stop')
    args = ap.parse_args()
    timeout = args.timeout or (60 if args.full else 20)
    t0 = time.time()

    for prog in (SOLVER, 'setMaterialPoints', 'blockMesh', 'decomposePar',
                 'setExprFields', 'mpirun'):
        if not shutil.which(prog):
            print('FAIL: %s is not on PATH (source etc/bashrc)' % prog)
            return 1
    # No core files, and a bound on what one run may take: a mutation that
    # asks for 1e300 points must not take the machine down with it
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    # (AddressSanitizer reserves terabytes of address space for its shadow:
    # the bound on memory is left to it there)
    if 'ASAN_OPTIONS' not in os.environ:
        resource.setrlimit(resource.RLIMIT_AS, (4 << 30, 4 << 30))
    resource.setrlimit(resource.RLIMIT_FSIZE, (1 << 30, 1 << 30))

    if os.path.exists(RUN):
        shutil.rmtree(RUN)
    os.makedirs(os.path.join(RUN, 'cases'))

    # The base cases, two at a time (the parallel one alone: two ranks)
    status = 0
    if args.bases:
        names = args.bases.split(',')
        unknown = sorted(set(names) - set(b.name for b in BASES))
        if unknown:
            print('FAIL: --bases: no base case %s (there are %s)'
                  % (', '.join(unknown), ', '.join(b.name for b in BASES)))
            return 1
        BASES[:] = [b for b in BASES if b.name in names]
    elif not args.full:
        BASES[:] = [b for b in BASES if b.ci]
    serial = [b for b in BASES if not b.parallel]
    errors = {}

    def prep(b):
        try:
            prepare(b, timeout)
        except (PrepError, foamDictEdit.DictEditError, OSError) as err:
            errors[b.name] = str(err)
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        list(pool.map(prep, serial))
    for b in BASES:
        if b.parallel:
            prep(b)
    for b in BASES:
        if b.ok:
            print('PASS: base case %s made (restart data at t = %s, '
                  'references to t = %s reproducible bit for bit)'
                  % (b.name, b.t1, b.t2))
            status |= not foamio.check(
                not b.control_damage, 'base case %s: the unmutated runs '
                'change no file that existed before' % b.name,
                ', '.join(b.control_damage[:4]) or None)
        else:
            print('FAIL: base case %s: %s' % (b.name, errors.get(b.name)))
            status = 1
    bases = [b for b in BASES if b.ok]

    mutations = []
    for b in bases:
        mutations += dict_mutations(b) + data_mutations(b)
    total = len(mutations)
    everything = list(mutations)
    if args.match:
        mutations = [m for m in mutations if args.match in m.label()]
    if not args.full and not args.match:
        mutations = sample(mutations, args.count, args.seed)
    groups = set(m.group for m in mutations)
    files = set(m.file_group for m in mutations)
    print('fuzz: %d mutations of %d (%s), %d groups, %d files, seed %d, '
          'timeout %g s' % (len(mutations), total,
                            'all' if args.full else 'sample', len(groups),
                            len(files), args.seed, timeout))
    sys.stdout.flush()
    if args.list:
        for m in mutations:
            print('    ' + m.label())
        return status

    # Serial cases two at a time, then the parallel ones one at a time
    outcomes = [None] * len(mutations)
    done = [0]
    lock = threading.Lock()

    def work(i):
        m = mutations[i]
        try:
            o = run_mutation(m, i, args.seed, timeout)
        except Exception as err:    # the fuzzer's fault: reported, not lost
            o = Outcome(m, os.path.join(RUN, 'cases', '%04d' % i))
            o.verdict = 'error'
            o.error = '%s: %s' % (type(err).__name__, err)
        outcomes[i] = o
        if not failed(o) and not args.keep:
            shutil.rmtree(o.case, ignore_errors=True)
        with lock:
            done[0] += 1
            if done[0] % 50 == 0:
                print('fuzz: %d of %d run (%.0f s)'
                      % (done[0], len(mutations), time.time() - t0))
                sys.stdout.flush()
    idx_serial = [i for i, m in enumerate(mutations) if not m.base.parallel]
    idx_par = [i for i, m in enumerate(mutations) if m.base.parallel]
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        list(pool.map(work, idx_serial))
    for i in idx_par:
        work(i)

    # Summary
    n = len(outcomes)
    count = {v: sum(1 for o in outcomes if o.verdict == v)
             for v in ('refused', 'valid', 'warned', 'crash', 'silent',
                       'error', 'foreign')}
    unnamed = [o for o in outcomes if o.verdict == 'refused'
               and not o.names_file]
    damaged = [o for o in outcomes if o.damaged]
    # The failures by category, each in the order of base case and file
    order = sorted(outcomes, key=lambda o: (o.m.base.name, o.m.file,
                                            o.m.label()))
    for verdict_, what in (('crash', 'crash'), ('silent', 'silent change'),
                           ('error', 'fuzzer error')):
        for o in order:
            if o.verdict == verdict_:
                report_failure(o, what)
    for o in order:
        if o.damaged:
            report_failure(o, 'files damaged')

    for o in order:
        if o.verdict == 'foreign':
            r = o.result
            print('fuzz: OpenFOAM\'s %s crashed (not this project\'s code): '
                  '%s, exit %d' % (r.program, o.m.label(), r.rc))
    print('mutations tried %d, refused cleanly %d (of which not naming the '
          'file %d), ran validly %d, ran with the change reported %d, '
          'crashed %d, silent changes %d, files damaged %d; OpenFOAM\'s '
          'utilities crashed %d' % (n, count['refused'], len(unnamed),
                                    count['valid'], count['warned'],
                                    count['crash'], count['silent'],
                                    len(damaged), count['foreign']))
    ok = []
    if not args.match:
        # Every base case got every kind of change, every file some change
        missing = sorted(set(m.group for m in everything) - groups) \
            + sorted(set(m.file_group for m in everything) - files)
        ok.append(foamio.check(
            not missing, 'the mutations cover every kind of change of every '
            'base case and every file',
            '%d bases, %d groups, %d files%s'
            % (len(bases), len(groups), len(files),
               ', missing %s' % missing[:5] if missing else '')))
    ok.append(foamio.check(count['error'] == 0,
                           'every mutation applied by the fuzzer',
                           '%d not applied' % count['error']))
    ok.append(foamio.check(count['crash'] == 0,
                           'no crash (signal, timeout, stack trace, exit '
                           'without FatalError)',
                           '%d of %d' % (count['crash'], n)))
    ok.append(foamio.check(count['silent'] == 0,
                           'no silent change (damaged written data run to '
                           'a different result without a word)',
                           '%d of %d' % (count['silent'], n)))
    ok.append(foamio.check(not damaged,
                           'no written file changed that existed before',
                           '%d of %d' % (len(damaged), n)))
    if args.match:
        print('fuzz: %d of %d refusals do not name the mutated file'
              % (len(unnamed), count['refused']))
    elif count['refused']:
        ok.append(foamio.check(
            not unnamed, 'refusals name the mutated file',
            '%d of %d refusals do not' % (len(unnamed), count['refused'])))
    for o in unnamed[:8]:
        first = [line.strip() for line in o.excerpt
                 if line.strip() and not FATAL.search(line)]
        print('    not named: %s: %s' % (o.m.label(), ' / '.join(first[:4])))
    print('fuzz: %.0f s' % (time.time() - t0))
    if not all(ok):
        status = 1
    return status


if __name__ == '__main__':
    sys.exit(main())
