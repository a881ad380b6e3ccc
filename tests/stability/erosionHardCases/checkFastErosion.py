#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     tests/stability/erosionHardCases/checkFastErosion.py
#
# Description
#     Fast surface erosion that empties and removes points: every written
#     field and cloud file finite, the soil's solid conserved (the points'
#     mass plus the eroded mass equals the points' initial mass, 1e-12),
#     the balance eroded = suspended + out at every step (1e-12), the
#     suspension never negative, and points removed (more than min).
#
# Usage
#     checkFastErosion.py CASE MIN_REMOVED
#------------------------------------------------------------------------------
import numpy as np
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio
from foamio import check

case, minRemoved = sys.argv[1], int(sys.argv[2])
times = foamio.times(case)


def finite(values):
    return bool(np.all(np.isfinite(np.asarray(values, dtype=float))))


bad = []
for t in times:
    for name in ('U', 'p', 'rho', 'soilFraction', 'fines', 'wallShearStress'):
        path = os.path.join(case, t, name)
        if os.path.exists(path) and not finite(foamio.read(case, t, name)):
            bad.append(path)
    for name in ('mass', 'volume', 'stress', 'porosity'):
        path = os.path.join(case, t, 'lagrangian', 'materialPoints', name)
        if os.path.exists(path) and not finite(foamio.read_cloud(case, t, name)):
            bad.append(path)
check(not bad, 'every field and cloud file finite at %d written times' % len(times),
      ' '.join(bad) or None)

rows = [list(map(float, l.split())) for l in
        open(os.path.join(case, 'postProcessing', 'erosion', '0', 'erosion.dat'))
        if not l.startswith('#')]
worst = max(abs(r[-1]) for r in rows)
check(worst < 1e-12, 'eroded = suspended + out at all %d steps' % len(rows),
      'largest defect %.3g' % worst)
eroded = {('%g' % r[0]): r[1] for r in rows}

m0 = float(np.sum(foamio.read_cloud(case, times[0], 'mass')))
last = times[-1]
m = float(np.sum(foamio.read_cloud(case, last, 'mass')))
e = eroded['%g' % float(last)]
defect = (m + e - m0)/m0
check(abs(defect) < 1e-12,
      'solid conserved: points %.6g kg + eroded %.6g kg = initial %.6g kg' % (m, e, m0),
      'defect %.3g' % defect)

fines = foamio.read(case, last, 'fines')
check(float(np.min(fines)) >= 0, 'suspension never negative',
      'min %.3g' % float(np.min(fines)))

log = open(os.path.join(case, 'log.mpmLbmFoam')).read()
removed = [int(x) for x in re.findall(r'(\d+) points removed', log)]
n = removed[-1] if removed else 0
check(n > minRemoved, 'points emptied and removed', '%d removed' % n)
print('removed %d' % n)
