#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     taylorGreen.py set CASE U0 RHO      write 0/U and 0/p
#     taylorGreen.py rate CASE T1 T2 NU   print the measured viscosity error
#
# Description
#     2D Taylor-Green vortex on the periodic unit square, k = 2 pi:
#         u = -U0 cos(kx) sin(ky),  v = U0 sin(kx) cos(ky)
#         p = -rho U0^2/4 (cos 2kx + cos 2ky)
#     decays as exp(-2 nu k^2 t), the kinetic energy as exp(-4 nu k^2 t).
#     'rate' measures nu from the energy at two times and prints
#     |nu_measured - nu|/nu.
#------------------------------------------------------------------------------
import os
import re
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

k = 2 * np.pi


def set_fields(case, U0, rho):
    C = foamio.read(case, 0, 'C')
    x, y = C[:, 0], C[:, 1]
    u = -U0 * np.cos(k * x) * np.sin(k * y)
    v = U0 * np.sin(k * x) * np.cos(k * y)
    p = -rho * U0 ** 2 / 4 * (np.cos(2 * k * x) + np.cos(2 * k * y))
    for name, body in (
        ('U', 'nonuniform List<vector>\n%d\n(\n%s\n)\n' % (len(x), '\n'.join(
            '(%.17g %.17g 0)' % (a, b) for a, b in zip(u, v)))),
        ('p', 'nonuniform List<scalar>\n%d\n(\n%s\n)\n' % (len(x), '\n'.join(
            '%.17g' % a for a in p)))):
        path = os.path.join(case, '0', name)
        text = open(path).read()
        text = re.sub(r'internalField\s+uniform[^;]*;[^\n]*',
                      'internalField   ' + body + ';', text)
        open(path, 'w').write(text)


def energy(case, t):
    U = foamio.read(case, t, 'U')
    return np.sum(U[:, 0] ** 2 + U[:, 1] ** 2)


if sys.argv[1] == 'set':
    set_fields(sys.argv[2], float(sys.argv[3]), float(sys.argv[4]))
else:
    case, t1, t2, nu = sys.argv[2], sys.argv[3], sys.argv[4], float(sys.argv[5])
    ratio = energy(case, t2) / energy(case, t1)
    nu_measured = -np.log(ratio) / (4 * k * k * (float(t2) - float(t1)))
    print('%.6e %.8e' % (abs(nu_measured - nu) / nu, nu_measured))
