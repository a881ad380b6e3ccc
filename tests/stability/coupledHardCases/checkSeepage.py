#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkSeepage.py CASE LABEL RATIO W H HS MODE EXTRA
#
# Description
#     A soil column H_s = HS high (n = 0.4, rho_s = 2650 kg/m3, d = 1 mm,
#     elastic M = 134.6 MPa) on the inlet of a vertical channel W x H, the
#     inlet pressure raised at t = 0 from hydrostatic by RATIO i_c gamma_w H_s
#     (critical gradient i_c = gamma'/gamma_w = phi (rho_s - rho_w)/rho_w =
#     0.99). Checks:
#     - runs to End, no non-finite value in any written field or cloud file;
#     - soil mass exact, every point inside the channel at every written
#       time (the water flows in and out through the pressure patches: its
#       mass is not conserved and not checked);
#     - MODE stay: the column stays put, no point moves by more than 1 mm
#       at any written time (its elastic heave, i gamma_w H_s^2/(2 M), is
#       micrometres);
#       MODE lift: the column is lifted, every point at least 2 mm higher at the end and
#       the column moving up;
#       MODE probe: prints whether it is lifted, no check (onset bracket);
#     - EXTRA darcy: before any lift, the seepage flux through
#       the column equals Darcy's q = (k/mu) i gamma_w of the applied
#       gradient within 5% (k of Beetstra-van der Hoef at the measured
#       Reynolds number, as tests/validation/darcySeepage);
#       EXTRA plug: the lifted column rises as a rigid plug of
#       soil and water, the whole channel's water accelerated with it
#       (incompressible water, quasi-steady Darcy drag):
#         A = (i - i_c) gamma_w H_s / ((phi rho_s + n rho_w) H_s
#                                       + rho_w (H - H_s)),
#       mean displacement A t^2/2 at the end within 5% (the water above
#       moves aside only through the displacement source of the porous
#       flow: without it the column rose at twice the water's pace).
#------------------------------------------------------------------------------
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
from common import foamio  # noqa: E402

case, label = sys.argv[1], sys.argv[2]
ratio, W, H, Hs = (float(v) for v in sys.argv[3:7])
mode, extra = sys.argv[7], sys.argv[8]
n0, rhoS, rhoW, g, d, mu, M = 0.4, 2650.0, 1000.0, 9.81, 1e-3, 1e-3, 1e8 * 0.7 / (1.3 * 0.4)
phi0 = 1 - n0
ic = phi0 * (rhoS - rhoW) / rhoW
i = ratio * ic
gw = rhoW * g

ended, why = common.ran(case)
times = foamio.times(case)
ok = foamio.check(ended, '%s: runs to the end' % label,
                  'written up to t = %s s%s' % (times[-1], '; stopped: ' + why if why else ''))
nFiles, bad = common.nonFinite(case)
ok &= foamio.check(nFiles > 0 and not bad, '%s: no NaN or inf in any written field or cloud file'
                   % label, '%d files over %d times%s'
                   % (nFiles, len(times), ', bad: ' + ' '.join(bad[:4]) if bad else ''))
dm, same, inside, ext, nPoints = common.soilMass(case, (0, 0), (W, H))
ok &= foamio.check(dm == 0 and same and inside,
                   '%s: soil mass exact, no point lost, every point inside the channel' % label,
                   '%d points, mass change %.1e, x in [%.4f, %.4f], y in [%.4f, %.4f]'
                   % ((nPoints, dm) + tuple(ext)))

x0 = foamio.read_cloud(case, times[0], 'x')
m = foamio.read_cloud(case, times[0], 'mass')
moved = max(np.sqrt(((foamio.read_cloud(case, t, 'x') - x0) ** 2).sum(axis=1)).max()
            for t in times)
x1 = foamio.read_cloud(case, times[-1], 'x')
v1 = foamio.read_cloud(case, times[-1], 'U')
dy = x1[:, 1] - x0[:, 1]
vy = np.average(v1[:, 1], weights=m)
T = float(times[-1])
if mode == 'stay':
    heave = i * gw * Hs ** 2 / (2 * M)
    ok &= foamio.check(moved <= 1e-3, '%s: the column stays put (no point moves by more than '
                       '1 mm)' % label, 'largest displacement %.2e m at any time (elastic heave '
                       '%.1e m)' % (moved, heave))
elif mode == 'probe':
    print('  %s: onset probe, lowest rise %.2e m, mean %.2e m at t = %g s, mean velocity '
          '%+.3e m/s: %s' % (label, dy.min(), np.average(dy, weights=m), T, vy,
                             'lifted' if dy.min() >= 2e-3 and vy > 0 else 'not lifted'))
else:
    lifted = dy.min() >= 2e-3 and vy > 0
    ok &= foamio.check(
        lifted, '%s: the column is lifted (every point >= 2 mm higher at t = %g s, moving up)'
        % (label, T), 'lowest rise %.2e m, mean %.2e m, mean velocity %+.3e m/s'
        % (dy.min(), np.average(dy, weights=m), vy))

if extra == 'darcy':
    C = foamio.read(case, '0', 'C')
    U = foamio.read(case, times[-1], 'U')
    inner = (C[:, 1] > 0.2 * Hs) & (C[:, 1] < 0.8 * Hs)
    q = U[inner, 1].mean()
    Re = rhoW * d * abs(q) / mu
    F = 10 * phi0 / n0 ** 2 + n0 ** 2 * (1 + 1.5 * np.sqrt(phi0))
    F += (0.413 * Re / (24 * n0 ** 2) * (1 / n0 + 3 * phi0 * n0 + 8.4 * Re ** -0.343)
          / (1 + 10 ** (3 * phi0) * Re ** (-(1 + 4 * phi0) / 2)))
    k = n0 * d * d / (18 * phi0 * F)
    qD = k / mu * i * gw
    ok &= foamio.check(abs(q / qD - 1) <= 0.05, '%s: seepage flux = Darcy (k/mu) i gamma_w of '
                      'the applied gradient within 5%%' % label,
                      'q %.4e m/s against %.4e (k %.3e m2, Re %.2g): %+.1f%%'
                      % (q, qD, k, Re, 100 * (q / qD - 1)))
elif extra == 'plug':
    A = (i - ic) * gw * Hs / ((phi0 * rhoS + n0 * rhoW) * Hs + rhoW * (H - Hs))
    rise = np.average(dy, weights=m)
    ok &= foamio.check(abs(rise / (0.5 * A * T * T) - 1) <= 0.05,
                      '%s: the column rises as a rigid plug (A t^2/2 within 5%%)' % label,
                      'mean rise %.4f m at t = %g s against %.4f m (A = %.3f m/s2), '
                      'mean velocity %.3f m/s against A t = %.3f m/s'
                      % (rise, T, 0.5 * A * T * T, A, vy, A * T))
sys.exit(0 if ok else 1)
