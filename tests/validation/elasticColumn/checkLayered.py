#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkLayered.py CASE
#
# Description
#     The elastic column in two layers of two models (layered/: Drucker-
#     Prager sand, rho 2000, E 200 MPa, nu 0.3, below y0 = 5 m; Mohr-Coulomb
#     clay, rho 1600, E 50 MPa, nu 0.25, above; H = 10 m), both with
#     cohesion enough to stay elastic. Exact, with y0 the initial height:
#         sigma_yy(y0) = -g int_y0^H rho dY (the weight above)
#         sigma_xx = nu_i/(1 - nu_i) sigma_yy in layer i
#         settlement: int_0^y0 (exp(sigma_yy/M_i) - 1) dY (the rate model's
#         stretch, as checkColumn.py), in closed form layer by layer
#     Prints
#         <mean |stress error|> <settlement error (signed: + for too much
#         settlement)> <sand ratio error>
#         <clay ratio error> <largest plastic strain> <1 if every point
#         below y0 = 5 m has one material and every point above the other,
#         else 0>
#     the stress error relative to the weight of the column (the normalised
#     error of Coombs & Augarde 2020), the others relative.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case = sys.argv[1]
g, H, Hs = 9.81, 10.0, 5.0
rho = (2000.0, 1600.0)
E, nu = (2e8, 5e7), (0.3, 0.25)
M = [e * (1 - n) / ((1 + n) * (1 - 2 * n)) for e, n in zip(E, nu)]
t = foamio.latest_time(case)
x0 = foamio.read_cloud(case, '0', 'x')
x = foamio.read_cloud(case, t, 'x')
s = foamio.read_cloud(case, t, 'stress')
mat = np.rint(foamio.read_cloud(case, t, 'material')).astype(int)
ep = foamio.read_cloud(case, t, 'plasticStrain')
y0 = x0[:, 1]


def weight(y):
    """Weight above height y per unit area."""
    return g * (rho[1] * (H - np.maximum(y, Hs)) + rho[0] * np.maximum(Hs - y, 0))


def displacement(y):
    """Exact vertical displacement at height y: in each layer the weight
    falls linearly, w(Y) = w(a) - rho_i g (Y - a), so the stretch
    exp(-w/M_i) integrates in closed form."""
    u = 0.0
    for i, (a, b) in enumerate(((0.0, Hs), (Hs, H))):
        b = min(b, y)
        if b <= a:
            break
        k = rho[i] * g / M[i]
        u += np.exp(-weight(a) / M[i]) * np.expm1(k * (b - a)) / k - (b - a)
    return u


err = (s[:, 3] + weight(y0)) / weight(0.0)
top = y0 > y0.max() - 1e-9
settle = np.mean(x[top, 1] - y0[top])
exact = displacement(y0[top][0])
ratios = []
for i, lo, hi in ((0, 0, 0.75 * Hs), (1, Hs + 0.1 * Hs, Hs + 0.75 * Hs)):
    sel = (y0 > lo) & (y0 < hi)
    r = np.sum(s[sel, 0] * s[sel, 3]) / np.sum(s[sel, 3] ** 2)
    ratios.append(abs(r / (nu[i] / (1 - nu[i])) - 1))
below, above = mat[y0 < Hs], mat[y0 > Hs]
layered = (np.all(below == below[0]) and np.all(above == above[0])
           and below[0] != above[0])
print('%.6e %.6e %.6e %.6e %.6e %d' % (
      np.mean(np.abs(err)), settle / exact - 1, ratios[0], ratios[1],
      np.abs(ep).max(), int(layered)))
