#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkForces.py CASE
#     checkForces.py --compare REFCASE CASE TOL
#
# Description
#     Forces of the water at rest in the open tank of Alltest against
#     hydrostatics; or the last forces of CASE against REFCASE's (a restart,
#     a parallel run).
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

rho0, g, H, W, D = 1000.0, 9.81, 1.0, 1.0, 0.1
names = ('rightWall', 'leftWall', 'bottomWall', 'allPatches')


def table(case, name, file='force'):
    """Rows of postProcessing/<name>/<latest start>/<file>.dat"""
    root = os.path.join(case, 'postProcessing', name)
    start = sorted(os.listdir(root), key=float)[-1]
    return np.loadtxt(os.path.join(root, start, file + '.dat'), ndmin=2), start


if sys.argv[1] == '--compare':
    ref, case, tol = sys.argv[2], sys.argv[3], float(sys.argv[4])
    ok = True
    for name in names:
        a, _ = table(ref, name)
        b, start = table(case, name)
        fa, fb = a[-1, 1:], b[-1, 1:]
        err = np.max(np.abs(fa - fb)) / np.max(np.abs(fa))
        ok &= foamio.check(abs(a[-1, 0] - b[-1, 0]) < 1e-9 and err <= tol,
                           'latticeForces %s in %s (from %s) equals the '
                           'reference run within %.0e' % (name, case, start, tol),
                           'relative difference %.2e' % err)
    sys.exit(0 if ok else 1)

case = sys.argv[1]
t = foamio.latest_time(case)
rho = foamio.read(case, t, 'rho')
V = foamio.read(case, t, 'V')
# (the water's weight is rho_0 g V whatever the lattice's density)
weight = rho0 * np.sum(V) * g

right, _ = table(case, 'rightWall')
left, _ = table(case, 'leftWall')
bottom, _ = table(case, 'bottomWall')
total, _ = table(case, 'allPatches')
moment, _ = table(case, 'rightWall', 'moment')
coeff, _ = table(case, 'rightWall', 'coefficient')

side = rho0 * g * H * H * D / 2
errSide = abs(right[-1, 1] / side - 1)
ok = foamio.check(errSide <= 1e-4, 'latticeForces: side wall of a tank at '
                  'rest carries rho g H^2 D/2 within 1e-4',
                  '%.4f N vs %.4f N (%.2e)' % (right[-1, 1], side, errSide))
errSym = abs(right[-1, 1] + left[-1, 1]) / side
ok &= foamio.check(errSym <= 1e-12, 'latticeForces: left wall = -right wall',
                   'relative difference %.1e' % errSym)
Mz = rho0 * g * D * H ** 3 / 6
errM = abs(-moment[-1, 3] / Mz - 1)
ok &= foamio.check(errM <= 1e-4, 'latticeForces: moment of the side wall about '
                   'its foot rho g H^3 D/6 within 1e-4',
                   '%.4f N m vs %.4f (%.2e)' % (-moment[-1, 3], Mz, errM))
base = rho0 * g * H * W * D
errB = abs(-bottom[-1, 2] / base - 1)
ok &= foamio.check(errB <= 1e-4, 'latticeForces: bottom carries rho g H W D '
                   'within 1e-4', '%.4f N vs %.4f (%.2e)'
                   % (-bottom[-1, 2], base, errB))
errW = abs(-total[-1, 2] / weight - 1)
ok &= foamio.check(errW <= 1e-6 and abs(total[-1, 1]) <= 1e-9 * weight,
                   'latticeForces: all patches together carry the weight of '
                   'the water rho g V within 1e-6 (steady momentum balance)',
                   '%.6f N vs rho g V %.6f N (%.1e), Fx %.1e N'
                   % (-total[-1, 2], weight, errW, total[-1, 1]))
q = 0.5 * rho0 * 1.0 ** 2 * 0.1
errC = max(abs(coeff[-1, 1] - right[-1, 1] / q), abs(coeff[-1, 2] - right[-1, 2] / q)) \
    / abs(right[-1, 1] / q)
ok &= foamio.check(errC <= 1e-12, 'latticeForces: Cd, Cl = F/(rho U^2 A/2)',
                   'Cd %.6f, relative error %.1e' % (coeff[-1, 1], errC))
steps = int(round(2 / 0.0001953125))
ok &= foamio.check(len(right) == steps, 'latticeForces: force.dat has a row '
                   'per step', '%d rows for %d steps' % (len(right), steps))
sys.exit(0 if ok else 1)
