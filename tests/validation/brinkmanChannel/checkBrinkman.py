#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkBrinkman.py CASE
#
# Description
#     Prints the largest and the L2 error of the Brinkman channel profile
#     (Guo & Zhao 2002, Phys. Rev. E 66, 036304; coupling-formulas.md 3.5)
#         u(y) = (G K/nu) [1 - cosh(r (y - H/2))/cosh(r H/2)],
#         r = sqrt(eps nu/(nu_e K)) = sqrt(eps/K)   (nu_e = nu),
#     walls at y = 0 and H = 1, relative to the exact centreline speed
#     u_c = (G K/nu)(1 - 1/cosh(r H/2)):
#         <max error> <L2 error> <u_c>
#     u is the superficial (Darcy) velocity the solver writes as U; G is the
#     water's body acceleration (constant/g), applied as the force density rho eps G of
#     the Guo-Zhao momentum equation; eps and K from
#     constant/porousFlowProperties, nu and G from constant/fluidProperties.
#------------------------------------------------------------------------------
import os
import re
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case = sys.argv[1]
num = r'([0-9.eE+-]+)'
fluid = open(os.path.join(case, 'constant', 'fluidProperties')).read()
porous = open(os.path.join(case, 'constant', 'porousFlowProperties')).read()
nu = float(re.search(r'\nnu\s+' + num, fluid).group(1))
gravity = open(os.path.join(case, 'constant', 'g')).read()
G = float(re.search(r'\nvalue\s+\(\s*' + num, gravity).group(1))
eps = float(re.search(r'\n\s*porosity\s+' + num, porous).group(1))
K = float(re.search(r'\n\s*permeability\s+' + num, porous).group(1))
H = 1.0
r = np.sqrt(eps / K)

t = foamio.latest_time(case)
U = foamio.read(case, t, 'U')
y = foamio.read(case, t, 'C')[:, 1]
exact = G * K / nu * (1 - np.cosh(r * (y - H / 2)) / np.cosh(r * H / 2))
uc = G * K / nu * (1 - 1 / np.cosh(r * H / 2))
err = U[:, 0] - exact
print('%.6e %.6e %.6e' % (np.max(np.abs(err)) / uc,
                          np.sqrt(np.mean(err ** 2)) / uc, uc))
