#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     cylinder.py CASE [--png FILE] [--window T]
#
# Description
#     The Schaefer & Turek 1996 benchmark 2D-1 read off a run of this case:
#     - C_D, C_L: latticeForces' coefficient.dat (C = 2 F/(rho U_mean^2 D)),
#       averaged over the last T seconds (default 1 s);
#     - Delta p = p(0.15, 0.2) - p(0.25, 0.2), the pressure at the front and
#       the back of the cylinder: the mean of the two cell rows beside
#       y = 0.2, extrapolated linearly from the two nearest water cells to
#       x = 0.15 and 0.25 (latest time; needs the cell centres C:
#       postProcess -func writeCellCentres -latestTime);
#     against the reference of Nabh 1998 as quoted by FeatFlow (C_D
#     5.57953523384, C_L 0.010618948146, Delta p 0.11752016697). Prints one
#     line "cylinder2D: Cd ... Cl ... dp ..." for scripts; --png plots C_D
#     and C_L against time with the reference values.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

CD, CL, DP = 5.57953523384, 0.010618948146, 0.11752016697

case = sys.argv[1]
png = sys.argv[sys.argv.index('--png') + 1] if '--png' in sys.argv else None
window = float(sys.argv[sys.argv.index('--window') + 1]) if '--window' in sys.argv else 1.0

root = os.path.join(case, 'postProcessing', 'cylinderForces')
start = sorted(os.listdir(root), key=float)[0]
coeff = np.loadtxt(os.path.join(root, start, 'coefficient.dat'), comments='#', ndmin=2)
t, cd, cl = coeff[:, 0], coeff[:, 1], coeff[:, 2]
last = t >= t[-1] - window
Cd, Cl = cd[last].mean(), cl[last].mean()
spread = cd[last].max() - cd[last].min()

time = foamio.latest_time(case)
C = foamio.read(case, time, 'C')
p = foamio.read(case, time, 'p')
U = foamio.read(case, time, 'U')
dx = np.min(np.diff(np.unique(np.round(C[:, 0], 12))))
row = np.abs(C[:, 1] - 0.2) < 0.6 * dx
water = np.sum(U ** 2, axis=1) > 0          # (cells inside a body: U = 0)
xs = np.unique(np.round(C[row, 0], 12))
prow = np.array([p[row & water & (np.abs(C[:, 0] - x) < 1e-9)].mean()
                 if np.any(row & water & (np.abs(C[:, 0] - x) < 1e-9)) else np.nan
                 for x in xs])


def extrapolate(xw, side):
    """p at x = xw from the two water cells beyond it on the given side"""
    ok = np.isfinite(prow) & ((xs < xw) if side < 0 else (xs > xw))
    idx = np.nonzero(ok)[0]
    i1, i2 = (idx[-1], idx[-2]) if side < 0 else (idx[0], idx[1])
    x1, x2 = xs[i1], xs[i2]
    return prow[i1] + (prow[i1] - prow[i2]) * (xw - x1) / (x1 - x2)


dp = extrapolate(0.15, -1) - extrapolate(0.25, +1)
print('cylinder2D: Cd %.6f Cl %.6f dp %.6f (last %g s: Cd spread %.2e; '
      'reference Cd %.5f Cl %.6f dp %.5f; errors %.2f%%, %.1f%%, %.2f%%)'
      % (Cd, Cl, dp, window, spread, CD, CL, DP, 100 * (Cd / CD - 1),
         100 * (Cl / CL - 1), 100 * (dp / DP - 1)))

if png:
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    a1.plot(t, cd, lw=1, label='mpmLbmFoam')
    a1.axhline(CD, color='k', ls='--', lw=1, label='Schaefer & Turek 2D-1: %.4f' % CD)
    a1.set_ylabel('$C_D$')
    a1.set_ylim(CD * 0.95, CD * 1.05)
    a1.legend(loc='upper right')
    a2.plot(t, cl, lw=1)
    a2.axhline(CL, color='k', ls='--', lw=1, label='%.5f' % CL)
    a2.set_ylabel('$C_L$')
    a2.set_ylim(-0.01, 0.04)
    a2.set_xlabel('time [s]')
    a2.legend(loc='upper right')
    fig.suptitle('Cylinder in a channel, Re = 20 (dx = %.4g m): C_D %.4f, C_L %.5f, '
                 '$\\Delta p$ %.4f Pa' % (dx, Cd, Cl, dp), fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print('Picture: %s' % png)
