#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkBed.py CASE LABEL
#
# Description
#     A submerged soil layer at rest (Terzaghi; coupling-formulas.md 4.1):
#     tank H = 2 m, layer H_s = 1 m, n = 0.4, rho_s = 2650 kg/m3 (the
#     material's rho = phi rho_s = 1590), rho_w = 1000 kg/m3, g = 9.81:
#         pore pressure   p = p_top + rho_w g (H - y)       (19620 Pa at
#                                                            the bottom)
#         effective       sigma'_yy = -gamma' (H_s - y0),
#                         gamma' = phi (rho_s - rho_w) g = 9711.9 N/m3
#                                                  (9711.9 Pa at the base)
#                         sigma'_xx = K0 sigma'_yy, K0 = nu/(1 - nu) = 3/7
#     (a soil without buoyancy would carry phi rho_s g = 15598 N/m3, 61%
#     more). Checks:
#     - stable, the water's mass conserved (1e-10);
#     - at rest: the largest water speed near the soil's surface
#       (|y - H_s| <= 3 dx) and anywhere <= 1e-3 sqrt(g H) = 4.43e-3 m/s;
#     - pore pressure hydrostatic at every node, in the water and in the
#       soil: p - p(top row) against rho_w g (y_top - y) within 1% of
#       rho_w g H (196 Pa);
#     - vertical effective stress of the points deeper than 0.1 H_s within
#       2% of gamma' x depth (each point), and over all points an RMS error
#       <= 2% of gamma' H_s;
#     - the lateral stress sigma'_xx/sigma'_yy = K0 within 2% (points
#       deeper than 0.1 H_s).
#------------------------------------------------------------------------------
import os
import re
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case, label = sys.argv[1], sys.argv[2]
check = foamio.check
H, Hs, n0, rhoS, rhoW, g, nu = 2.0, 1.0, 0.4, 2650.0, 1000.0, 9.81, 0.3
phi = 1 - n0
gammaP = phi * (rhoS - rhoW) * g
K0 = nu / (1 - nu)

log = open(os.path.join(case, 'log.mpmLbmFoam')).read()
t = foamio.latest_time(case)
C = foamio.read(case, t, 'C')
U = np.atleast_2d(foamio.read(case, t, 'U'))
p = foamio.read(case, t, 'p')
y = C[:, 1]
dx = foamio.Lattice(C).dx

defect = [abs(float(v)) for v in re.findall(r'mass defect ([-0-9.e+]+)', log)]
ok = check('End' in log and len(defect) > 0 and max(defect) <= 1e-10,
                  '%s: stable, water mass conserved' % label,
                  'largest mass defect %.1e' % (max(defect) if defect else float('nan')))

speed = np.sqrt((U ** 2).sum(axis=1))
limit = 1e-3 * np.sqrt(g * H)
surface = np.abs(y - Hs) <= 3 * dx
ok &= check(speed[surface].max() <= limit and speed.max() <= limit,
                   '%s: water at rest at the soil surface and everywhere (<= %.3g m/s)'
                   % (label, limit), 'largest %.2e m/s at the surface, %.2e anywhere'
                   % (speed[surface].max(), speed.max()))

top = y > y.max() - 1e-9
ptop = p[top].mean()
exact = rhoW * g * (y[top].mean() - y)
err = np.abs(p - ptop - exact).max() / (rhoW * g * H)
inSoil = y < Hs
errSoil = np.abs(p - ptop - exact)[inSoil].max() / (rhoW * g * H)
ok &= check(err <= 0.01, '%s: pore pressure hydrostatic in water and soil within 1%%'
                   % label, 'largest deviation %.2e of rho_w g H (in the soil %.2e), p(bottom) - '
                   'p(top) %.1f Pa vs %.1f' % (err, errSoil, p[y < dx].mean() - ptop,
                                                rhoW * g * (y.max() - y.min())))

y0 = foamio.read_cloud(case, '0', 'x')[:, 1]
s = foamio.read_cloud(case, t, 'stress')
depth = Hs - y0
syy, sxx = s[:, 3], s[:, 0]
deep = depth > 0.1 * Hs
local = np.abs(syy[deep] + gammaP * depth[deep]) / (gammaP * depth[deep])
rms = np.sqrt(np.mean((syy + gammaP * depth) ** 2)) / (gammaP * Hs)
ok &= check(local.max() <= 0.02 and rms <= 0.02,
                   "%s: effective stress sigma'_yy = gamma' depth (gamma' = %.1f N/m3) within 2%%"
                   % (label, gammaP), 'largest %.2e (depth > 0.1 H_s), rms %.2e of gamma\' H_s; '
                   'base %.1f Pa vs %.1f' % (local.max(), rms, -syy[depth > Hs - dx / 2].mean(),
                                             gammaP * (Hs - dx / 4)))
ratio = np.sum(sxx[deep] * syy[deep]) / np.sum(syy[deep] ** 2)
ok &= check(abs(ratio / K0 - 1) <= 0.02, "%s: lateral stress sigma'_xx = K0 sigma'_yy within 2%%"
                   % label, 'ratio %.5f vs %.5f' % (ratio, K0))
sys.exit(0 if ok else 1)
