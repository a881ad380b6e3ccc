#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkPoiseuille.py CASE
#
# Description
#     Prints the largest and the L2 error of the body-force Poiseuille
#     profile u(y) = g y (H - y)/(2 nu) (walls at y = 0 and H = 1, g and nu
#     from constant/fluidProperties), relative to the centreline speed,
#     and, where the case wrote viscousStress (writeViscousStress), the
#     largest error of its shear component against rho g (H/2 - y),
#     relative to the wall's rho g H/2, and of its normal components:
#         <max error> <L2 error> [<shear error> <normal stress>]
#------------------------------------------------------------------------------
import os
import re
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case = sys.argv[1]
t = foamio.latest_time(case)
U = foamio.read(case, t, 'U')
y = foamio.read(case, t, 'C')[:, 1]
props = open(os.path.join(case, 'constant', 'fluidProperties')).read()
nu = float(re.search(r'\nnu\s+([0-9.eE+-]+)', props).group(1))
gravity = open(os.path.join(case, 'constant', 'g')).read()
g = float(re.search(r'\nvalue\s+\(\s*([0-9.eE+-]+)', gravity).group(1))
H = 1.0
exact = g / (2 * nu) * y * (H - y)
umax = g * H * H / (8 * nu)
err = U[:, 0] - exact
out = '%.6e %.6e' % (np.max(np.abs(err)) / umax,
                     np.sqrt(np.mean(err ** 2)) / umax)
if os.path.exists(os.path.join(case, t, 'viscousStress')):
    rho = float(re.search(r'\nrho\s+([0-9.eE+-]+)', props).group(1))
    S = foamio.read(case, t, 'viscousStress')     # xx xy xz yy yz zz
    wall = rho * g * H / 2
    shear = np.max(np.abs(S[:, 1] - rho * g * (H / 2 - y))) / wall
    normal = np.max(np.abs(S[:, [0, 3, 5]])) / wall
    out += ' %.6e %.6e' % (shear, normal)
print(out)
