#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkChannel.py CASE DP L H NU RHO
#
# Description
#     Pressure-driven channel between walls y = 0 and H, pressure DP at the
#     inlet x = 0 and 0 at the outlet x = L: Poiseuille profile
#         u(y) = DP/(2 rho nu L) y (H - y).
#     Checks:
#     - the middle section is the Poiseuille profile of the local pressure
#       gradient, measured there (largest error <= 1% of the centreline
#       speed);
#     - the flow rate the pressure boundaries drive: mid-section profile
#       within 1% of the Poiseuille profile of DP/L (measured 0.38%), and
#       the pressure gradient at mid-length within 0.5% of DP/L (measured
#       0.000%). (Until 2026-12-06 a pressure link took the velocity and
#       non-equilibrium of its own node rather than of its wall node's row:
#       the pressure at the boundary's nodes stood 3% of DP above the
#       patch's and the channel ran 2.1% fast);
#     - the pressure at mid-length is DP/2 within 1%;
#     - the mass flux is the same through every section (relative spread
#       <= 1e-4: steady state).
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case = sys.argv[1]
dp, L, H, nu, rho = (float(v) for v in sys.argv[2:7])
t = foamio.latest_time(case)
lat = foamio.Lattice(foamio.read(case, t, 'C'))
U = lat.grid(foamio.read(case, t, 'U'))[:, :, 0, :]
p = lat.grid(foamio.read(case, t, 'p'))[:, :, 0]
r = lat.grid(foamio.read(case, t, 'rho'))[:, :, 0]
x, y = lat.axis(0), lat.axis(1)
nx = lat.n[0]

umax = dp * H * H / (8 * rho * nu * L)
exact = dp / (2 * rho * nu * L) * y * (H - y)
mid = 0.5 * (U[nx // 2 - 1, :, 0] + U[nx // 2, :, 0])
err = np.max(np.abs(mid - exact)) / umax
pmid = 0.5 * (p[nx // 2 - 1, :] + p[nx // 2, :]).mean()
flux = np.sum(r * U[:, :, 0], axis=1)
spread = (flux.max() - flux.min()) / flux.mean()

i0, i1 = nx // 2 - 2, nx // 2 + 1
dpdx = (p[i1, :].mean() - p[i0, :].mean()) / (x[i1] - x[i0])
local = -dpdx / (2 * rho * nu) * y * (H - y)
errLocal = np.max(np.abs(mid - local)) / umax
ok = foamio.check(errLocal <= 0.01, 'pressure-driven channel: mid-section is '
                  'the Poiseuille profile of the local pressure gradient '
                  'within 1%', 'max error %.3e of u_max, dp/dx %.4g Pa/m'
                  % (errLocal, dpdx))
ok &= foamio.check(err <= 0.01, 'pressure-driven channel: flow driven by the '
                   'pressure boundaries within 1% of Poiseuille (L/H = 8)',
                   'max error %.3e of u_max' % err)
ok &= foamio.check(abs(-dpdx * L / dp - 1) <= 0.005,
                   'pressure-driven channel: the pressure gradient at '
                   'mid-length DP/L within 0.5%',
                   '%.5g Pa/m vs %.5g' % (-dpdx, dp / L))
ok &= foamio.check(abs(pmid - dp / 2) <= 0.01 * dp,
                   'pressure-driven channel: p at mid-length = dp/2 within 1%',
                   '%.3f Pa vs %.3f' % (pmid, dp / 2))
ok &= foamio.check(spread <= 1e-4, 'pressure-driven channel: mass flux equal '
                   'through every section', 'relative spread %.2e' % spread)
sys.exit(0 if ok else 1)
