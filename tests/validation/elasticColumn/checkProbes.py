#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkProbes.py CASE RHO G H E NU
#     checkProbes.py --compare REFCASE CASE TOL
#
# Description
#     The tutorial's materialPointProbes (a settlement plate at y0 = 9.875 m,
#     a stress cell at y0 = 5.125 m, material positions at the start)
#     against the exact column (small strain, as checkColumn.py):
#         u(y0) = -(rho g/M)(H y0 - y0^2/2),  M = E(1 - nu)/((1 + nu)(1 - 2 nu))
#         sigma_yy(y0) = -rho g (H - y0),  sigma_xx = nu/(1 - nu) sigma_yy
#     the settlement of both within 1% (the column test's tolerance), the
#     stress cell's sigma_yy within 1% and its lateral ratio within 1%. Or
#     the last row of CASE's probes (a restart: postProcessing/column/<t>)
#     against REFCASE's.
#------------------------------------------------------------------------------
import os
import re
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio


def rows(case, field):
    root = os.path.join(case, 'postProcessing', 'column')
    start = sorted(os.listdir(root), key=float)[-1]
    out = []
    for line in open(os.path.join(root, start, field + '.dat')):
        if line.startswith('#'):
            continue
        out.append([float(v) for v in re.findall(r'[-+]?[0-9.]+(?:[eE][-+]?[0-9]+)?', line)])
    return np.array(out), start


if sys.argv[1] == '--compare':
    ref, case, tol = sys.argv[2], sys.argv[3], float(sys.argv[4])
    ok = True
    for field in ('displacement', 'stress'):
        a, _ = rows(ref, field)
        b, start = rows(case, field)
        err = np.max(np.abs(a[-1] - b[-1])) / np.max(np.abs(a[-1, 1:]))
        ok &= foamio.check(start != '0' and len(b) < len(a) and err <= tol,
                           'materialPointProbes continue after a restart (from '
                           '%s): %s equals the full run\'s within %.0e'
                           % (start, field, tol), 'relative difference %.1e' % err)
    sys.exit(0 if ok else 1)

case = sys.argv[1]
rho, g, H, E, nu = (float(v) for v in sys.argv[2:7])
M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
disp, _ = rows(case, 'displacement')
stress, _ = rows(case, 'stress')
ok = True
for k, y0 in enumerate((9.875, 5.125)):
    exact = -(rho * g / M) * (H * y0 - y0 * y0 / 2)
    err = abs(disp[-1, 1 + 3 * k + 1] / exact - 1)
    ok &= foamio.check(err <= 0.01, 'materialPointProbes: settlement of the '
                       'material at y0 = %g m within 1%% of the exact column' % y0,
                       '%.5e m vs %.5e (%.2e)' % (disp[-1, 1 + 3 * k + 1], exact, err))
syy = stress[-1, 1 + 6 + 3]
sxx = stress[-1, 1 + 6 + 0]
exact = -rho * g * (H - 5.125)
err = abs(syy / exact - 1)
ok &= foamio.check(err <= 0.01, 'materialPointProbes: sigma_yy at y0 = 5.125 m '
                   'within 1% of -rho g (H - y0)', '%.1f Pa vs %.1f (%.1e)'
                   % (syy, exact, err))
errR = abs((sxx / syy) / (nu / (1 - nu)) - 1)
ok &= foamio.check(errR <= 0.01, 'materialPointProbes: lateral stress ratio '
                   'nu/(1 - nu) within 1% at y0 = 5.125 m', '%.5f (%.1e)'
                   % (sxx / syy, errR))
sys.exit(0 if ok else 1)
