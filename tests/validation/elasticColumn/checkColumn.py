#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkColumn.py CASE RHO G H E NU
#
# Description
#     Elastic column under self-weight, laterally confined, fixed base, at
#     rest (mpm-references.md 3.1). With y0 the initial height of a point:
#     - vertical Cauchy stress sigma_yy = -rho g (H - y0): the weight above
#       the point per unit area, which a confined column keeps whatever it
#       is made of, so exact at finite strain too;
#     - lateral stress sigma_xx = nu/(1 - nu) sigma_yy;
#     - settlement of the top: the small-strain rho g H^2/(2 M), with
#       M = E (1 - nu)/((1 + nu)(1 - 2 nu)), and the exact solution of the
#       model the solver integrates. linearElastic is a rate model,
#       dsigma = M sym(L) dt along the column (no spin), so
#       sigma_yy = M ln(stretch): the stretch at y0 is exp(-a (H - y0)),
#       a = rho g/M, and the settlement H - (1 - exp(-a H))/a
#       (= a H^2/2 (1 - a H/3 + ...): 4.4e-4 below the small-strain value
#       for the tutorial, more than the discretisation error at H/40).
#     Prints
#         <rms stress error> <max stress error> <settlement error against
#         rho g H^2/(2M)> <lateral ratio error> <rms stress error away from
#         the ends> <mean |stress error|> <settlement error against the
#         finite-strain solution, signed: + for too much settlement>
#     stress errors relative to rho g H, the others relative. The mean
#     |stress error| over the points (all of one volume) is the normalised
#     error sum_p |sigma_p - sigma_a(y0_p)| V_p/(rho g H V) that Coombs &
#     Augarde (2020, AMPLE, section 5.1) use for this benchmark. "Away from
#     the ends": the points with 0.2 H < y0 < 0.8 H.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case = sys.argv[1]
rho, g, H, E, nu = (float(v) for v in sys.argv[2:7])
M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
a = rho * g / M
t = foamio.latest_time(case)
x0 = foamio.read_cloud(case, '0', 'x')
x = foamio.read_cloud(case, t, 'x')
s = foamio.read_cloud(case, t, 'stress')
exact = -rho * g * (H - x0[:, 1])
err = (s[:, 3] - exact) / (rho * g * H)
top = x0[:, 1] > x0[:, 1].max() - 1e-9
settle = np.mean(x[top, 1] - x0[top, 1])
settleSmall = -a * H * H / 2
# Top row at y0 = H - h/(2 ppc), not at H: the finite-strain settlement there
y0 = x0[top, 1]
settleFinite = np.mean(-(y0 - (np.exp(-a * (H - y0)) - np.exp(-a * H)) / a))
# Lateral ratio from the points below the top quarter (stress well resolved)
deep = x0[:, 1] < 0.75 * H
ratio = np.sum(s[deep, 0] * s[deep, 3]) / np.sum(s[deep, 3] ** 2)
inner = (x0[:, 1] > 0.2 * H) & (x0[:, 1] < 0.8 * H)
print('%.6e %.6e %.6e %.6e %.6e %.6e %.6e' % (
      np.sqrt(np.mean(err ** 2)), np.abs(err).max(),
      abs(settle / settleSmall - 1), abs(ratio / (nu / (1 - nu)) - 1),
      np.sqrt(np.mean(err[inner] ** 2)), np.mean(np.abs(err)),
      settle / settleFinite - 1))
