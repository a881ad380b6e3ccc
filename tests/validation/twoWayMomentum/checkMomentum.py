#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkMomentum.py CASE LABEL
#
# Description
#     Two-way drag in a fully periodic box, no gravity, no wall: nothing
#     outside the two phases acts on them, so the total momentum is
#     conserved exactly and the kinetic energy can only fall (drag and
#     viscosity dissipate; the elastic and acoustic energies start at 0).
#     Reads postProcessing/momentumBalance/0/momentum.dat (one row per step:
#     time waterX waterY waterZ soilX soilY soilZ totalX totalY totalZ),
#     the initial and final clouds, the final fields and the log. Checks:
#     - one row per lattice step, starting at t = 0 with the water at rest
#       and the soil's momentum sum m_p v_p of the initial cloud;
#     - the total momentum of every row equals the initial P0 within
#       1e-12 |P0| (each component);
#     - the exchange is real (the soil gives the water more than 10% of its
#       momentum), and the water gains exactly what the soil loses (1e-12);
#     - the soil sub-cycles (>= 4 sub-steps per lattice step, from the
#       log);
#     - the water's mass defect (log) <= 1e-12, the soil's mass (cloud)
#       exactly the initial;
#     - the kinetic energy at the end is below the initial one (water: a
#       lower bound, rho |U|^2/2 per volume with the written rho and the
#       superficial U; it is rho_w |U|^2/(2 n) with the water in the pores).
#------------------------------------------------------------------------------
import os
import re
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case, label = sys.argv[1], sys.argv[2]
log = open(os.path.join(case, 'log.mpmLbmFoam')).read()
ctrl = open(os.path.join(case, 'system', 'controlDict')).read()
dt = float(re.search(r'\ndeltaT\s+([0-9.eE+-]+)', ctrl).group(1))
endTime = float(re.search(r'\nendTime\s+([0-9.eE+-]+)', ctrl).group(1))
nSteps = int(round(endTime / dt))

m0 = foamio.read_cloud(case, '0', 'mass')
v0 = foamio.read_cloud(case, '0', 'U')
P0 = (m0[:, None] * v0).sum(axis=0)
scale = np.linalg.norm(P0)
KE0 = 0.5 * (m0 * (v0 ** 2).sum(axis=1)).sum()

ok = True
path = os.path.join(case, 'postProcessing', 'momentumBalance', '0', 'momentum.dat')
d = np.atleast_2d(np.loadtxt(path, comments='#'))
water, soil, total = d[:, 1:4], d[:, 4:7], d[:, 7:10]
ok &= foamio.check(d.shape[0] == nSteps + 1 and abs(d[0, 0]) < 1e-12
                   and np.abs(water[0]).max() == 0
                   and np.abs(soil[0] - P0).max() <= 1e-14 * scale,
                   '%s: momentum.dat has a row per step from t = 0 (water at rest, '
                   'soil sum m v)' % label, '%d rows for %d steps' % (d.shape[0], nSteps))
drift = np.abs(total - P0).max() / scale
ok &= foamio.check(drift <= 1e-12, '%s: total momentum conserved at every step (1e-12)'
                   % label, 'largest drift %.1e of |P0| = %.6g kg m/s over %d steps'
                   % (drift, scale, d.shape[0] - 1))
lost = soil[0] - soil[-1]
gained = water[-1] - water[0]
share = np.dot(lost, P0) / scale ** 2
ok &= foamio.check(share > 0.1 and np.abs(gained - lost).max() <= 1e-12 * scale,
                   '%s: the water gains what the soil loses' % label,
                   'soil lost %.1f%% of its momentum, mismatch %.1e of |P0|'
                   % (100 * share, np.abs(gained - lost).max() / scale))
sub = [int(v) for v in re.findall(r'soil sub-steps (\d+)', log)]
ok &= foamio.check(len(sub) > 0 and min(sub) >= 4, '%s: the soil sub-cycles in the lattice step'
                   % label, 'sub-steps %s' % (sorted(set(sub)) if sub else 'not in the log'))
defect = [abs(float(v)) for v in re.findall(r'mass defect ([-0-9.e+]+)', log)]
t = foamio.latest_time(case)
m1 = foamio.read_cloud(case, t, 'mass')
ok &= foamio.check(len(defect) > 0 and max(defect) <= 1e-12 and m1.sum() == m0.sum()
                   and m1.size == m0.size,
                   '%s: water mass (1e-12) and soil mass (exact) conserved' % label,
                   'largest water mass defect %.1e, soil %d points %.17g -> %.17g kg'
                   % (max(defect) if defect else float('nan'), m1.size, m0.sum(), m1.sum()))
v1 = foamio.read_cloud(case, t, 'U')
U = np.atleast_2d(foamio.read(case, t, 'U'))
rho = foamio.read(case, t, 'rho')
Vcell = foamio.read(case, t, 'V')
KEs = 0.5 * (m1 * (v1 ** 2).sum(axis=1)).sum()
KEw = 0.5 * (rho * (U ** 2).sum(axis=1) * Vcell).sum()
ok &= foamio.check(KEs + KEw <= KE0, '%s: kinetic energy falls' % label,
                   'initial %.4g J, final soil %.4g J + water >= %.4g J, largest water speed %.3g m/s'
                   % (KE0, KEs, KEw, np.sqrt((U ** 2).sum(axis=1)).max()))
sys.exit(0 if ok else 1)
