#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkColumn.py CASE RHO G H E NU
#
# Description
#     Elastic column under self-weight, laterally confined, fixed base, at
#     rest (exact small-strain solution, see mpm-references.md 3.1):
#         sigma_yy = -rho g (H - y0),  sigma_xx = nu/(1 - nu) sigma_yy
#         u_y(H) = -rho g H^2/(2 M),   M = E(1 - nu)/((1 + nu)(1 - 2 nu))
#     with y0 the initial height of a point. Prints
#         <rms stress error> <max stress error> <settlement error>
#         <lateral ratio error> <rms stress error away from the ends>
#     stress errors relative to rho g H, the others relative; "away from the
#     ends" is over the points with 0.2 H < y0 < 0.8 H (the free top and
#     the base have boundary layers a few points thick).
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case = sys.argv[1]
rho, g, H, E, nu = (float(v) for v in sys.argv[2:7])
M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
t = foamio.latest_time(case)
x0 = foamio.read_cloud(case, '0', 'x')
x = foamio.read_cloud(case, t, 'x')
s = foamio.read_cloud(case, t, 'stress')
exact = -rho * g * (H - x0[:, 1])
err = (s[:, 3] - exact) / (rho * g * H)
top = x0[:, 1] > x0[:, 1].max() - 1e-9
settle = np.mean(x[top, 1] - x0[top, 1])
settleExact = -rho * g * H * H / (2 * M)
# Lateral ratio from the points below the top quarter (stress well resolved)
deep = x0[:, 1] < 0.75 * H
ratio = np.sum(s[deep, 0] * s[deep, 3]) / np.sum(s[deep, 3] ** 2)
inner = (x0[:, 1] > 0.2 * H) & (x0[:, 1] < 0.8 * H)
print('%.6e %.6e %.6e %.6e %.6e' % (np.sqrt(np.mean(err ** 2)), np.abs(err).max(),
      abs(settle / settleExact - 1), abs(ratio / (nu / (1 - nu)) - 1),
      np.sqrt(np.mean(err[inner] ** 2))))
