#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkSettling.py CASE C0 WS D PHI_EXPONENT
#
# Description
#     The settling column against an independent 1D solution of the same
#     equations: grains at C0 [kg/m3] in still water between a lid and a
#     floor, H high, settling at w(c) = WS (1 - c/rho_s)^n (n = 0: not
#     hindered) and diffusing at D:
#         dc/dt + d(w(c) c)/dy = D d2c/dy2   (y down from the lid)
#     no flux through the lid (w c - D dc/dy = 0), and at the floor the
#     settling flux w c leaves the water (deposited), the diffusive one
#     none: the lattice's wall rule. Finite volumes, 1024 cells, upwind
#     settling flux (the grid's numerical diffusion, w dy/2, is 3% of D),
#     explicit steps of 0.4 dy^2/D.
#     Prints, per written time of the case, the deposited mass of the case
#     (postProcessing/scalarTransport/0/balance.dat) and of the reference,
#     their relative difference, the settling law's w(C0) C0 A t, and the
#     profile's largest difference from the reference over C0; then the
#     balance's largest defect over all steps.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case = sys.argv[1]
c0, ws, D, n = (float(a) for a in sys.argv[2:6])
rhoS = 2650.0
H, W, T = 0.064, 0.004, 0.001        # the column: height, width, thickness
A = W * T                            # the floor's area


def w(c):
    return ws * (1 - np.clip(c / rhoS, 0, 1)) ** n


# The case's balance: time, deposited, defect
with open(os.path.join(case, 'postProcessing', 'scalarTransport', '0',
                       'balance.dat')) as f:
    lines = [l for l in f if not l.startswith('#')]
titles = open(os.path.join(case, 'postProcessing', 'scalarTransport', '0',
                           'balance.dat')).readlines()[1].lstrip('#').split()
data = np.array([[float(x) for x in l.split()] for l in lines])
col = {t: i for i, t in enumerate(titles)}
times = [t for t in foamio.times(case) if float(t) > 0]

# The reference
N = 1024
dy = H / N
dt = 0.4 * dy * dy / max(D, 1e-30)
c = np.full(N, c0)
deposited = 0.0
t = 0.0
out = {}
for target in sorted(float(x) for x in times):
    while t < target - 1e-12:
        h = min(dt, target - t)
        F = np.zeros(N + 1)              # flux down through face i (top of cell i)
        F[1:N] = w(c[:-1]) * c[:-1] - D * (c[1:] - c[:-1]) / dy
        F[N] = w(c[-1]) * c[-1]          # the floor: settling out
        c = c - h * (F[1:] - F[:-1]) / dy
        deposited += h * F[N] * A
        t += h
    out[target] = (deposited, c.copy())

yRef = (np.arange(N) + 0.5) * dy     # down from the lid
for tName in times:
    tv = float(tName)
    depRef, cRef = out[tv]
    row = np.argmin(abs(data[:, 0] - tv))
    dep = data[row, col['deposited']]
    s = foamio.read(case, tName, 's').reshape(-1, 4).mean(axis=1)   # rows up
    ny = s.size
    yLat = H - (np.arange(ny) + 0.5) * H / ny                         # down
    ref = np.interp(yLat, yRef, cRef)
    print('t %g deposited %.9e reference %.9e difference %.3e law %.9e '
          'profile %.3e' % (tv, dep, depRef, dep / depRef - 1,
                            w(c0) * c0 * A * tv, abs(s - ref).max() / c0))
print('defect %.3e' % abs(data[:, col['defect']]).max())
