#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     compareFields.py CASE_A CASE_B TIME TOLERANCE FIELD [FIELD ...] [-- LABEL]
#
# Description
#     Largest absolute difference between the internal fields of two cases at
#     one time (ascii); one PASS:/FAIL: line per field, passing when it is at
#     most TOLERANCE. Cell order must match (same mesh, or reconstructPar).
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import foamio

args = sys.argv[1:]
label = ''
if '--' in args:
    i = args.index('--')
    label = ' '.join(args[i + 1:])
    args = args[:i]
caseA, caseB, time, tol = args[0], args[1], args[2], float(args[3])
ok = True
for name in args[4:]:
    a = foamio.read(caseA, time, name)
    b = foamio.read(caseB, time, name)
    if a.shape != b.shape:
        ok &= foamio.check(False, '%s %s at %s: shapes %s and %s differ'
                           % (label, name, time, a.shape, b.shape))
        continue
    d = float(np.max(np.abs(a - b))) if a.size else 0.0
    scale = float(np.max(np.abs(a))) if a.size else 0.0
    ok &= foamio.check(np.isfinite(d) and d <= tol,
                       '%s %s at t = %s: max |difference| <= %g'
                       % (label, name, time, tol),
                       'max %.3e, field max %.3e' % (d, scale))
sys.exit(0 if ok else 1)
