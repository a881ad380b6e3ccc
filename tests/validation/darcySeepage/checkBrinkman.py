#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkBrinkman.py CASE D MU N DP L W
#
# Description
#     The Darcy column of checkDarcy.py (Kozeny-Carman, grain diameter D,
#     water viscosity MU, porosity N, pressure DP over length L) between
#     no-slip side walls W apart, with the lattice viscosity raised for
#     stability (nu of constant/fluidProperties). The lattice's viscous
#     term in the pores is Brinkman's, nu q'' = (n nu_w/k) q - force, so
#     the flux falls from Darcy's to 0 at a wall across
#         delta = sqrt(nu k/(n nu_w)),  nu_w = MU/rho
#     and the mean flux of a channel W wide (Brinkman 1947; the
#     two-wall solution q(y) = q_D (1 - cosh(y/delta)/cosh(W/(2 delta))))
#         q/q_D = 1 - (2 delta/W) tanh(W/(2 delta))
#     Checks:
#     - the log gives delta for the material within 1% of the formula;
#     - a warning names the widened layer (nu/nu_w, the walls, slip);
#     - the mean flux through the middle sections / (k/mu) DP/L within
#       5% of the Brinkman channel's ratio (a new user's probe,
#       2026-12-07: 0.708 against 0.687; the layer is 0.63 cells).
#------------------------------------------------------------------------------
import os
import re
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case = sys.argv[1]
d, mu, n0, dp, L, W = (float(v) for v in sys.argv[2:8])
rhoF = 1000.0
log = open(os.path.join(case, 'log.mpmLbmFoam')).read()
nu = float(re.search(r'^nu\s+([0-9.eE+-]+);', open(os.path.join(
    case, 'constant', 'fluidProperties')).read(), re.M).group(1))
k = d * d * n0 ** 3 / (180 * (1 - n0) ** 2)
delta = np.sqrt(nu * k / (n0 * mu / rhoF))

ok = True
m = re.search(r'Brinkman layer at no-slip walls.*?: (\w+) ([0-9.eE+-]+) m', log)
logged = float(m.group(2)) if m else float('nan')
ok &= foamio.check(m is not None and abs(logged / delta - 1) <= 0.01,
                   'Brinkman layer: the log gives delta = sqrt(nu k/(n nu_w)) within 1%',
                   'logged %s, formula %.4e m (nu %g, k %.4e)' % (m.group(0) if m else
                                                                 'nothing', delta, nu, k))
flat = ' '.join(log.split())
warned = re.search(r'FOAM Warning.*?widens the Brinkman layer.*?no-slip walls.*?slip', flat)
ok &= foamio.check(warned is not None,
                   'Brinkman layer: the widened layer between no-slip walls is warned',
                   'no warning' if warned is None else 'warned')

t = foamio.latest_time(case)
lat = foamio.Lattice(foamio.read(case, t, 'C'))
U = np.atleast_2d(lat.grid(foamio.read(case, t, 'U')))[:, :, 0]
x = lat.axis(0)
mid = (x > 0.1 * L) & (x < 0.9 * L)
qm = U[mid][:, :, 0].mean()
qD = k / mu * dp / L
ratio = qm / qD
a = W / (2 * delta)
expected = 1 - np.tanh(a) / a
e = ratio / expected - 1
ok &= foamio.check(abs(e) <= 0.05,
                   'Brinkman layer: the column\'s flux between no-slip walls / Darcy\'s '
                   'within 5% of the Brinkman channel\'s 1 - (2 delta/W) tanh(W/(2 delta))',
                   'q/q_D %.4f, Brinkman %.4f (delta/dx %.2f), deviation %+.1e'
                   % (ratio, expected, delta / lat.dx, e))
sys.exit(0 if ok else 1)
