#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     compareSoil.py CASE_A CASE_B TIME TOLERANCE [-ref CASE_C FACTOR]
#         ITEM [ITEM ...] [-- LABEL]
#
# Description
#     Compares two cases at one time, one PASS:/FAIL: line per item:
#         cloud:NAME[@SCALE]   a field of the material point cloud, point by
#                              point after matching the points by their
#                              identity (origId); the same points must be
#                              there (one more line)
#         field:NAME[@SCALE]   a volField (cells in the same order: same
#                              mesh, or reconstructPar)
#     The difference is the largest |a - b| over the points or cells (and
#     components) divided by SCALE, by default the largest |a|: it must be
#     at most TOLERANCE. With -ref, CASE_C is a reference run of CASE_A
#     (e.g. with one ulp changed at the start): the tolerance becomes at
#     least FACTOR times its difference from CASE_A, item by item.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests',
                                'lib'))
import foamio

args = sys.argv[1:]
label = ''
if '--' in args:
    i = args.index('--')
    label = ' '.join(args[i + 1:]) + ':'
    args = args[:i]
ref = None
if '-ref' in args:
    i = args.index('-ref')
    ref = (args[i + 1], float(args[i + 2]))
    args = args[:i] + args[i + 3:]
caseA, caseB, time, tol = args[0], args[1], args[2], float(args[3])
items = args[4:]


def cloud_order(case):
    ids = foamio.read_cloud(case, time, 'origId').astype(np.int64)
    return ids, np.argsort(ids, kind='stable')


def read(case, kind, name, order):
    if kind == 'cloud':
        return foamio.read_cloud(case, time, name)[order]
    return foamio.read(case, time, name)


def relative(a, b, scale):
    if a.shape != b.shape:
        return np.inf
    d = float(np.max(np.abs(a - b))) if a.size else 0.0
    return d / scale if scale > 0 else d


ok = True
orders = {}
if any(item.startswith('cloud:') for item in items):
    for case in [caseA, caseB] + ([ref[0]] if ref else []):
        orders[case] = cloud_order(case)
    idA, oA = orders[caseA]
    idB, oB = orders[caseB]
    same = idA.size == idB.size and np.unique(idA).size == idA.size \
        and np.array_equal(idA[oA], idB[oB])
    ok &= foamio.check(same, '%s the same %d material points at t = %s '
                       '(matched by origId)' % (label, idA.size, time),
                       '%d and %d points' % (idA.size, idB.size))
    if not same:
        sys.exit(1)

for item in items:
    kind, spec = item.split(':', 1)
    name, scale = (spec.split('@') + [None])[:2]
    a = read(caseA, kind, name, orders.get(caseA, (0, None))[1])
    b = read(caseB, kind, name, orders.get(caseB, (0, None))[1])
    s = float(scale) if scale else \
        (float(np.max(np.abs(a))) if a.size else 0.0)
    rel = relative(a, b, s)
    limit = tol
    what = '%g' % tol
    detail = '%.2e of %s %.3e' % (rel, 'scale' if scale else 'max', s)
    if ref:
        c = read(ref[0], kind, name, orders.get(ref[0], (0, None))[1])
        relRef = relative(a, c, s)
        limit = max(tol, ref[1] * relRef)
        what = '%g or %g x the reference run\'s %.2e' % (tol, ref[1], relRef)
    ok &= foamio.check(np.isfinite(rel) and rel <= limit,
                       '%s %s %s at t = %s within %s'
                       % (label, kind, name, time, what), detail)
sys.exit(0 if ok else 1)
