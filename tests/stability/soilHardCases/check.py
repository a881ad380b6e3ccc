#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     check.py CASE NAME XMAX YMAX G [MIN_RUNOUT_FACTOR]
#
# Description
#     A hard soil case must end well: every point finite and inside the
#     domain [0, XMAX] x [0, YMAX], total mass unchanged, and the energy
#     bounded: kinetic energy at the end no larger than the initial kinetic
#     energy plus the potential energy released (gravity (0 -9.81 0)).
#     Optionally the run-out (largest x) at least MIN_RUNOUT_FACTOR times
#     the initial width.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case, name = sys.argv[1], sys.argv[2]
xmax, ymax = float(sys.argv[3]), float(sys.argv[4])
g = float(sys.argv[5])
runout = float(sys.argv[6]) if len(sys.argv) > 6 else None
log = open(os.path.join(case, 'log.mpmLbmFoam')).read()
t = foamio.latest_time(case)
m0 = foamio.read_cloud(case, '0', 'mass'); m = foamio.read_cloud(case, t, 'mass')
x0 = foamio.read_cloud(case, '0', 'x'); x = foamio.read_cloud(case, t, 'x')
v0 = foamio.read_cloud(case, '0', 'U'); v = foamio.read_cloud(case, t, 'U')
s = foamio.read_cloud(case, t, 'stress')
finite = np.all(np.isfinite(x)) and np.all(np.isfinite(v)) and np.all(np.isfinite(s))
inside = np.all((x[:, 0] >= 0) & (x[:, 0] <= xmax) & (x[:, 1] >= 0) & (x[:, 1] <= ymax))
ke0 = 0.5 * np.sum(m0 * (v0 ** 2).sum(axis=1))
ke = 0.5 * np.sum(m * (v ** 2).sum(axis=1))
released = g * np.sum(m0 * x0[:, 1]) - g * np.sum(m * x[:, 1])
ok = foamio.check('End' in log and finite,
                  '%s: runs to the end, every point finite' % name, 't = %s' % t)
ok &= foamio.check(inside, '%s: every point inside the domain' % name,
                   'x in [%.3g, %.3g], y in [%.3g, %.3g]'
                   % (x[:, 0].min(), x[:, 0].max(), x[:, 1].min(), x[:, 1].max()))
ok &= foamio.check(m.sum() == m0.sum() and len(m) == len(m0),
                   '%s: mass exact, no point lost' % name, '%d points' % len(m))
ok &= foamio.check(ke <= ke0 + released + 1e-9 * (ke0 + abs(released)),
                   '%s: energy bounded (kinetic <= initial + released by gravity)' % name,
                   'kinetic %.4g J, initial %.4g J, released %.4g J' % (ke, ke0, released))
if runout is not None:
    w0 = x0[:, 0].max()
    ok &= foamio.check(x[:, 0].max() >= runout * w0,
                       '%s: runs out at least %g times its initial width' % (name, runout),
                       'run-out %.3g m from width %.3g m' % (x[:, 0].max(), w0))
sys.exit(0 if ok else 1)
