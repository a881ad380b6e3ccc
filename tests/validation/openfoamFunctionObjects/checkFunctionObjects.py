#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkFunctionObjects.py CASE
#
# Description
#     OpenFOAM's function objects (probes, surfaceFieldValue, volFieldValue,
#     fieldMinMax, fieldAverage) run unchanged in the pressure-driven channel
#     (DP = 640 Pa over L = 8 m, H = 1 m, nu = 0.1, rho = 1000, 0.1 m thick):
#     - their values at the write times equal the solver's written fields
#       (to round-off): they read the fields of the step;
#     - the probes change at every step of the start-up (no step reads
#       the fields of an earlier one);
#     - against Poiseuille: the centreline probe u = DP H^2/(8 rho nu L)
#       and the outlet discharge DP H^3 D/(12 rho nu L) within 2.5% (the
#       pressure boundaries' extra resistance, as validation/pressureChannel);
#       the mean pressure DP/2 within 1%;
#     - fieldAverage of the steady flow (from 30 s) equals the field at
#       40 s within 1e-5 of the centreline speed;
#     - the project's latticeWallShearStress: the walls' shear integrated
#       carries DP H D within 1% and equals the walls' force of
#       latticeForces (momentum exchange) within 2% (the corners' diagonal
#       links share theirs with the pressure patches).
#------------------------------------------------------------------------------
import os
import re
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case = sys.argv[1]
dp, L, H, nu, rho0, D = 640.0, 8.0, 1.0, 0.1, 1000.0, 0.1
umax = dp * H * H / (8 * rho0 * nu * L)
Qexact = dp * H ** 3 * D / (12 * rho0 * nu * L)
pp = os.path.join(case, 'postProcessing')


def probeTable(field):
    """Time and values (probe x component) of postProcessing/probes/0/field"""
    times, rows = [], []
    for line in open(os.path.join(pp, 'probes', '0', field)):
        if line.startswith('#'):
            continue
        parts = line.split()
        times.append(float(parts[0]))
        nums = [float(v) for v in re.findall(r'[-+0-9.eE]+', ' '.join(parts[1:]))]
        rows.append(nums)
    return np.array(times), np.array(rows)


def datTable(name, file):
    rows = []
    for line in open(os.path.join(pp, name, '0', file)):
        if line.startswith('#'):
            continue
        rows.append([float(v) for v in re.findall(r'[-+]?[0-9.]+(?:[eE][-+]?[0-9]+)?',
                                                   line.split('\t')[0] + ' ' + ' '.join(
                                                       v for v in line.split('\t')[1:]
                                                       if not v.strip().startswith('mag')))])
    return rows


lat = foamio.Lattice(foamio.read(case, '40', 'C'))
cells = []
for x, y in ((4.03125, 0.53125), (4.03125, 0.28125)):
    i = int(round((x - lat.lo[0]) / lat.dx))
    j = int(round((y - lat.lo[1]) / lat.dx))
    cells.append((i, j))

tU, probeU = probeTable('U')
tp, probep = probeTable('p')
ok = True

# 1. At the write times the probes read the written fields
worst = 0.0
for t in ('10', '20', '30', '40'):
    U = lat.grid(foamio.read(case, t, 'U'))[:, :, 0, :]
    p = lat.grid(foamio.read(case, t, 'p'))[:, :, 0]
    k = int(np.argmin(np.abs(tU - float(t))))
    for n, (i, j) in enumerate(cells):
        worst = max(worst, np.max(np.abs(probeU[k, 3 * n:3 * n + 3] - U[i, j])) / umax,
                    abs(probep[k, n] - p[i, j]) / dp)
ok &= foamio.check(worst <= 1e-12, 'probes: U and p at the write times equal the '
                   'written fields', 'largest difference %.1e (of u_max, DP)' % worst)

# 2. ... and change at every step of the start-up
# (once the start-up's pressure wave has reached the probe: until then the
# water there is at rest)
early = probeU[(tU > 0) & (tU <= 10), 0]
moving = np.nonzero(early)[0]
still = int(np.sum(np.diff(early[moving[0]:]) == 0)) if moving.size else -1
ok &= foamio.check(len(early) == 2560 and moving.size > 2000 and still == 0,
                   'probes: a value every step and no step repeats the one '
                   'before (0 < t <= 10 s, once the water moves there)',
                   '%d values, moving from step %d, %d repeated'
                   % (len(early), moving[0] + 1 if moving.size else -1, still))

# 3. Poiseuille
errC = abs(probeU[-1, 0] / umax - 1)
ok &= foamio.check(errC <= 0.025, 'probes: centreline speed DP H^2/(8 rho nu L) '
                   'within 2.5%', '%.5f m/s vs %.5f (%.2e)' % (probeU[-1, 0], umax, errC))

flux = datTable('outletFlux', 'surfaceFieldValue.dat')
U40 = lat.grid(foamio.read(case, '40', 'U'))[:, :, 0, :]
own = np.sum(U40[-1, :, 0]) * lat.dx * D
errOwn = abs(flux[-1][1] - own) / Qexact
errQ = abs(flux[-1][1] / Qexact - 1)
ok &= foamio.check(abs(flux[-1][0] - 40) < 1e-9 and errOwn <= 1e-12,
                   'surfaceFieldValue: outlet discharge = sum of the written U '
                   'over the outlet cells', 'difference %.1e of Q' % errOwn)
ok &= foamio.check(errQ <= 0.025, 'surfaceFieldValue: outlet discharge '
                   'DP H^3 D/(12 rho nu L) within 2.5%', '%.6e m3/s vs %.6e (%.2e)'
                   % (flux[-1][1], Qexact, errQ))

pmean = datTable('meanPressure', 'volFieldValue.dat')
p40 = foamio.read(case, '40', 'p')
errP = abs(pmean[-1][1] - np.mean(p40)) / dp
ok &= foamio.check(errP <= 1e-12 and abs(pmean[-1][1] / (dp / 2) - 1) <= 0.01,
                   'volFieldValue: mean pressure = mean of the written p, '
                   'and DP/2 within 1%', '%.4f Pa (written %.4f, DP/2 %.1f)'
                   % (pmean[-1][1], np.mean(p40), dp / 2))

last = [l for l in open(os.path.join(pp, 'velocityMinMax', '0', 'fieldMinMax.dat'))
        if not l.startswith('#')][-1].split('\t')
magU = np.sqrt(np.sum(foamio.read(case, '40', 'U') ** 2, axis=1))
errMax = abs(float(last[4]) - magU.max()) / umax
ok &= foamio.check(abs(float(last[0]) - 40) < 1e-9 and errMax <= 1e-12,
                   'fieldMinMax: max |U| = that of the written U',
                   '%.6f m/s (written %.6f)' % (float(last[4]), magU.max()))

Umean = foamio.read(case, '40', 'UMean')
errAvg = np.max(np.abs(Umean - foamio.read(case, '40', 'U'))) / umax
ok &= foamio.check(errAvg <= 1e-5, 'fieldAverage: the mean of the steady flow '
                   '(30-40 s) equals the field within 1e-5 of u_max (the flow\'s '
                   'own drift over the window)', 'largest difference %.1e of u_max'
                   % errAvg)
# The project's latticeWallShearStress and latticeForces on the walls: the
# shear integrated over the walls (mean x area) and the walls' force by
# momentum exchange both carry the pressure drop's push DP H D (the
# steady water's momentum balance)
rowsWss = [l.split('\t') for l in open(os.path.join(pp, 'wallShear', '0', 'wallShearStress.dat'))
           if not l.startswith('#')]
last = [r for r in rowsWss if abs(float(r[0]) - 40) < 1e-9]
meanX = float(re.findall(r'[-+0-9.eE]+', last[0][2])[0]) if last else float('nan')
wallArea = 2 * L * D
friction = meanX * wallArea
force = np.loadtxt(os.path.join(pp, 'wallForce', '0', 'force.dat'), comments='#', ndmin=2)
push = dp * H * D
errF = abs(friction / push - 1)
errME = abs(friction / force[-1, 1] - 1)
# (the momentum exchange gives the x share of the diagonal links at the
# walls' ends, which also cross the pressure patches, to those patches: one
# end cell of 128 per wall end, about 1%)
ok &= foamio.check(errF <= 0.01 and errME <= 0.02, 'latticeWallShearStress: the shear '
                   'over the walls carries DP H D within 1%, and equals the walls\' '
                   'force by momentum exchange (latticeForces) within 2%',
                   '%.4f N vs DP H D %.1f N (%.1e), momentum exchange %.4f N (%.1e)'
                   % (friction, push, errF, force[-1, 1], errME))
sys.exit(0 if ok else 1)
