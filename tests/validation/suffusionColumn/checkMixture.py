#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkMixture.py MIXTURE CLEAR C
#
# Description
#     The suspension's weight on the water (erosionProperties
#     mixtureDensity): the column stood upright (g along -x, a tenth of
#     Earth's, the inlet at the bottom), fines suspended at C [kg/m3 of pore water] throughout,
#     the inlet's pressure the weight of the mixture above it,
#         p_in = (rho_w + C (1 - rho_w/rho_s)) g L,
#     the outlet's 0. Nothing erodes (the critical gradient is above any
#     the column sees). With mixtureDensity (case MIXTURE) the pore water
#     is that mixture and stays at rest; with clear water (case CLEAR)
#     the excess C (1 - rho_w/rho_s) g L drives Darcy's flux
#     q = K C (1 - rho_w/rho_s)/rho_w (K = k rho_w g/mu, Kozeny-Carman).
#     Checks at the last write time:
#     - MIXTURE: the pore pressure's slope within 0.5% of the mixture's
#       weight (rho_w + C (1 - rho_w/rho_s)) g, and more than 5% above
#       clear water's; the Darcy flux below 1% of CLEAR's;
#     - CLEAR: the Darcy flux within 3% of Darcy's law for the excess.
#     Prints PASS:/FAIL: lines.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests',
                                'lib'))
import foamio

mixture, clear, C = sys.argv[1], sys.argv[2], float(sys.argv[3])

# The case's parameters (constant/*Properties, the mesh)
L = 0.64
mu, rhoW, g, rhoS = 1e-3, 1000.0, 0.981, 2650.0
d, n0 = 5.7e-3, 0.4
k = d * d * n0 ** 3 / (180 * (1 - n0) ** 2)
K = k * rhoW * g / mu
excess = C * (1 - rhoW / rhoS)
qRef = K * excess / rhoW

ok = True
lat = foamio.Lattice(foamio.read(mixture, '0', 'C'))
x = lat.axis(0)
mid = (x > 0.1 * L) & (x < 0.9 * L)


def last(case):
    return foamio.latest_time(case)


def field(case, name):
    return np.atleast_2d(lat.grid(foamio.read(case, last(case), name)))[:, :, 0]


qMix = field(mixture, 'U')[mid, :, 0].mean()
qClear = field(clear, 'U')[mid, :, 0].mean()
p = field(mixture, 'p')[mid, :].mean(axis=1)
slope = -np.polyfit(x[mid], p, 1)[0]
rhoMix = rhoW + excess
ok &= foamio.check(abs(slope / (rhoMix * g) - 1) < 0.005,
                   'mixture density: the pore pressure\'s slope within 0.5%'
                   ' of the mixture\'s weight (rho_w + C (1 - rho_w/rho_s)) g',
                   '%.3f against %.3f Pa/m (%.5f; clear water %.3f)'
                   % (slope, rhoMix * g, slope / (rhoMix * g) - 1, rhoW * g))
ok &= foamio.check(slope > 1.05 * rhoW * g, 'mixture density: the slope'
                   ' more than 5% above clear water\'s',
                   '%.4f' % (slope / (rhoW * g)))
ok &= foamio.check(abs(qMix) < 0.01 * abs(qClear), 'mixture density: the'
                   ' suspension at rest under the mixture\'s head (Darcy flux'
                   ' below 1% of the clear water\'s)',
                   '%.3e against %.4g m/s' % (qMix, qClear))
ok &= foamio.check(abs(qClear / qRef - 1) < 0.03, 'mixture density off:'
                   ' the excess head drives Darcy\'s K C (1 - rho_w/rho_s)'
                   '/rho_w within 3%', '%.5g against %.5g m/s (%.4f)'
                   % (qClear, qRef, qClear / qRef - 1))
sys.exit(0 if ok else 1)
