#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkGhia.py CASE DATAFILE TOLERANCE
#
# Description
#     Compares the centreline velocities of a unit lid-driven cavity (lid
#     speed 1 m/s, written at the latest time) with Ghia, Ghia & Shin (1982)
#     Tables I and II at Re = 100: linear interpolation of the lattice
#     profile (with the wall values) at the published points. Passes when the
#     largest deviation is at most TOLERANCE (in units of the lid speed).
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case, datafile, tol = sys.argv[1], sys.argv[2], float(sys.argv[3])
t = foamio.latest_time(case)
U = foamio.read(case, t, 'U')
C = foamio.read(case, t, 'C')
lat = foamio.Lattice(C)
Ug = lat.grid(U)[:, :, 0, :]
nx, ny = lat.n[0], lat.n[1]
x, y = lat.axis(0), lat.axis(1)

blocks = {}
key = None
for line in open(datafile):
    line = line.strip()
    if line.startswith('# u_vertical') or line.startswith('# v_horizontal'):
        key = line[2:].split(':')[0]
        blocks[key] = []
    elif line and not line.startswith('#') and key:
        blocks[key].append([float(v) for v in line.split()])

# u on the vertical centreline x = 0.5 (between the two middle columns)
u_mid = 0.5 * (Ug[nx // 2 - 1, :, 0] + Ug[nx // 2, :, 0]) if nx % 2 == 0 \
    else Ug[nx // 2, :, 0]
v_mid = 0.5 * (Ug[:, ny // 2 - 1, 1] + Ug[:, ny // 2, 1]) if ny % 2 == 0 \
    else Ug[:, ny // 2, 1]
yy = np.concatenate(([0.0], y, [1.0]))
uu = np.concatenate(([0.0], u_mid, [1.0]))
xx = np.concatenate(([0.0], x, [1.0]))
vv = np.concatenate(([0.0], v_mid, [0.0]))

ref_u = np.array(blocks['u_vertical_centreline'])
ref_v = np.array(blocks['v_horizontal_centreline'])
du = np.abs(np.interp(ref_u[:, 0], yy, uu) - ref_u[:, 1])
dv = np.abs(np.interp(ref_v[:, 0], xx, vv) - ref_v[:, 1])

print('time %s, lattice %d x %d' % (t, nx, ny))
for (p, r), d in zip(ref_u, du):
    print('  y = %.4f  u Ghia %+.5f  lattice %+.5f' % (p, r, np.interp(p, yy, uu)))
ok1 = foamio.check(du.max() <= tol,
                   'u on x = 0.5 against Ghia et al. 1982 Table I, max |du| <= %g U' % tol,
                   'max %.5f at y = %.4f' % (du.max(), ref_u[du.argmax(), 0]))
ok2 = foamio.check(dv.max() <= tol,
                   'v on y = 0.5 against Ghia et al. 1982 Table II, max |dv| <= %g U' % tol,
                   'max %.5f at x = %.4f' % (dv.max(), ref_v[dv.argmax(), 0]))
sys.exit(0 if ok1 and ok2 else 1)
