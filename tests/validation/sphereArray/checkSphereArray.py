#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkSphereArray.py CASE LABEL
#
# Description
#     Stokes flow through a simple cubic array of spheres (one sphere of
#     radius a in a periodic cube of side L, lattice units, rho = 1), driven
#     by the body force g on the water. Prints the dimensionless drag
#         K = F/(6 pi mu a U),   F = F_water + rho g V_s,
#     F_water the momentum exchange on the sphere (latticeForces), V_s its
#     volume, U the superficial velocity (the mean over the cube, the
#     sphere's nodes at rest), mu = rho nu. F is the force of the mean
#     pressure gradient on the whole cell, rho g L^3 at a steady state (the
#     body force stands for the pressure gradient, which acts on the sphere
#     too). Against the series of Sangani & Acrivos (1982, Int. J.
#     Multiphase Flow 8, 343-360; Hasimoto's 1959 leading terms) in the
#     solid fraction c = 4 pi a^3/(3 L^3):
#         1/K = 1 - 1.7601 c^(1/3) + c - 1.5593 c^2 + 3.9799 c^(8/3)
#               - 3.0734 c^(10/3)
#     (K = 2.842 at c = pi/48). Writes K to CASE/K for the comparisons of
#     Alltest.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case, label = sys.argv[1], sys.argv[2]
a, L, nu, g = 8.0, 32.0, 1.0 / 6.0, 2.3323770750484947e-05

c = 4 * np.pi * a**3 / (3 * L**3)
K_ref = 1 / (1 - 1.7601 * c**(1 / 3) + c - 1.5593 * c**2
             + 3.9799 * c**(8 / 3) - 3.0734 * c**(10 / 3))

t = foamio.latest_time(case)
U = foamio.read(case, t, 'U')
U_sup = U[:, 0].sum() / L**3
force = np.loadtxt(os.path.join(case, 'postProcessing', 'sphere', '0', 'force.dat'),
                   ndmin=2)
F = force[-1, 1] + g * 4 * np.pi * a**3 / 3
K = F / (6 * np.pi * nu * a * U_sup)
with open(os.path.join(case, 'K'), 'w') as f:
    f.write('%.12g\n' % K)

ok = True
# Steady: the cell's force balance F = rho g L^3 (momentum in = out)
balance = F / (g * L**3) - 1
ok &= foamio.check(abs(balance) < 2e-3,
                   '%s: steady, the drag F balances the driving rho g L^3 within 0.2%%'
                   % label, '%+.3f%%' % (100 * balance))
err = K / K_ref - 1
ok &= foamio.check(abs(err) < 0.01,
                   '%s: drag K = F/(6 pi mu a U) within 1%% of Sangani & Acrivos '
                   '(c = %.4f, K = %.4f)' % (label, c, K_ref),
                   'K %.4f, %+.2f%%' % (K, 100 * err))
sys.exit(0 if ok else 1)
