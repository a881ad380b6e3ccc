#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkPerMaterial.py ONE PER T0
#
# Description
#     The suffusion column made of two materials alike (gravel upstream of
#     x = 0.32 m, gravelB downstream), eroding from T0, once with one
#     suspension (case ONE) and once with a suspension per material (case
#     PER, suspensionPerMaterial true: fines.gravel and fines.gravelB).
#     The suspensions are carried alike and the laws see their sum, so:
#     - PER's totals (eroded, suspended, out, deposited: the fines settle,
#       each kind hindered by all the grains) equal ONE's at every step
#       within 1e-12 of the eroded mass;
#     - PER's per-material columns add up to its totals (1e-13);
#     - each material's eroded mass is what its points lost, from the
#       clouds at T0 and at the end (1e-12);
#     - the two fields add up to ONE's fines at the end (1e-12 of its
#       largest);
#     - each material's balance (its defect) to 1e-12 at every step.
#     The suspensions' D is 0.02 m2/s here (tau 1.1): over-relaxed (tau
#     0.8 at D 0.01) the positivity limiter, which relaxes a node fully
#     where a population would turn negative, acts on each suspension
#     apart, and the sums part at 2e-9.
#     Prints PASS:/FAIL: lines.
#------------------------------------------------------------------------------
import os
import sys
import glob
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests',
                                'lib'))
import foamio

one, per, t0 = sys.argv[1], sys.argv[2], sys.argv[3]
mats = ['gravel', 'gravelB']


def balance(case):
    path = glob.glob(os.path.join(case, 'postProcessing', 'erosion', '*',
                                  'erosion*.dat'))[0]
    names = None
    rows = []
    for line in open(path):
        if line.startswith('#'):
            words = line[1:].split()
            if words and words[0] == 'Time':
                names = words
            continue
        if line.strip():
            rows.append([float(v) for v in line.split()])
    rows = np.array(rows)
    return {n: rows[:, i] for i, n in enumerate(names)}


A, B = balance(one), balance(per)
ok = True
scale = np.abs(A['eroded']).max()
columns = [c for c in ('eroded', 'suspended', 'out', 'deposited') if c in A]
diff = max(np.abs(A[c] - B[c]).max() for c in columns)
ok &= foamio.check(diff < 1e-12 * scale, 'suspension per material: the'
                   ' totals (%s) equal one suspension\'s at every step'
                   % ', '.join(columns),
                   '%.2e of %.4g kg' % (diff / scale, scale))
if 'deposited' in A:
    # Settling that the hindrance of each kind by its own grains alone
    # would make faster: the check above sees it only if grains deposit
    ok &= foamio.check(A['deposited'][-1] > 0.05 * scale, 'suspension per'
                       ' material: fines deposited by settling',
                       '%.3g kg of %.4g eroded'
                       % (A['deposited'][-1], scale))
sums = max(np.abs(sum(B[c + '.' + m] for m in mats) - B[c]).max()
           for c in columns)
ok &= foamio.check(sums < 1e-13 * scale, 'suspension per material: the'
                   ' materials\' columns add up to the totals',
                   '%.2e' % (sums / scale))

last = foamio.latest_time(per)
worst = 0.0
for i, m in enumerate(mats):
    mat0 = foamio.read_cloud(per, t0, 'material')
    mass0 = foamio.read_cloud(per, t0, 'mass')
    mat1 = foamio.read_cloud(per, last, 'material')
    mass1 = foamio.read_cloud(per, last, 'mass')
    lost = mass0[mat0 == i].sum() - mass1[mat1 == i].sum()
    worst = max(worst, abs(lost - B['eroded.' + m][-1]) / scale)
    print('  %s: eroded %.6g kg (its points lost %.6g), suspended %.6g,'
          ' out %.6g' % (m, B['eroded.' + m][-1], lost,
                         B['suspended.' + m][-1], B['out.' + m][-1]))
ok &= foamio.check(worst < 1e-12, 'suspension per material: each material\'s'
                   ' eroded mass is what its points lost', '%.2e' % worst)

lat = foamio.Lattice(foamio.read(one, '0', 'C'))
x = lat.axis(0)
cOne = np.atleast_2d(lat.grid(foamio.read(one, last, 'fines')))[:, :, 0]
cs = [np.atleast_2d(lat.grid(foamio.read(per, last, 'fines.' + m)))[:, :, 0]
      for m in mats]
d = np.abs(cs[0] + cs[1] - cOne).max() / np.abs(cOne).max()
ok &= foamio.check(d < 1e-12, 'suspension per material: fines.gravel +'
                   ' fines.gravelB = one suspension\'s fines', '%.2e' % d)
ok &= foamio.check(np.abs(B['defect']).max() < 1e-12, 'suspension per'
                   ' material: each material\'s balance to 1e-12 at every'
                   ' step', '%.2e over %d steps'
                   % (np.abs(B['defect']).max(), len(B['defect'])))
sys.exit(0 if ok else 1)
