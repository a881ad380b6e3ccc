#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkDarcy.py CASE MODEL D MU N DP L
#     checkDarcy.py CASE fixed K MU N DP L
#
# Description
#     Steady seepage through a soil column held in place (porosity N, grain
#     diameter D, water viscosity MU), pressure DP at the inlet x = 0 and 0
#     at the outlet x = L. Darcy's law (coupling-formulas.md 2.2, 4.1):
#         q = n (v_f - v_s) = -(k/mu) dp/dx = (k/mu) DP/L
#     q from the fields: U (the superficial velocity) - n Usoil (the
#     soil's nodal velocity; n = N: the soil hardly strains). The intrinsic
#     permeability k of the drag model:
#         KozenyCarman        k = d^2 n^3/(180 (1 - n)^2)
#         BeetstraVanDerHoef  k = (1 - phi) d^2/(18 phi Fhat(phi, Re)),
#                             Re = rho_f d q/mu (the superficial slip),
#                             Fhat of coupling-formulas.md 2.1
#     (k = n^2 mu/beta(phi, slip): Stokes limit of each law); for a rigid
#     medium (porousFlow medium fixed, no soil) k = K and mu = rho nu of
#     the water.
#     Checks:
#     - the soil is held: its nodal speed <= 1% of q;
#     - steady: the flux through every section of the middle 80% equal
#       within 1e-3, and uniform across each section of the middle half
#       (slip side walls: plug flow) within 1e-3;
#     - local Darcy law in the middle 80% of the column: q against
#       (k/mu)(-dp/dx) of the pore pressure's slope there, within 1e-4
#       (the issue asks 2%; measured a few 1e-6 since the corners where a
#       slip side meets a pressure patch take the patch's extrapolation,
#       1.2% before);
#     - global: q against (k/mu) DP/L within 1e-4 (the pore pressure is
#       continuous where the water enters and leaves the soil: no loss at
#       the ends);
#     - the discharge that OpenFOAM's surfaceFieldValue reads on a plane
#       sampled through the soil at mid-length (the seepage discharge an
#       engineer asks for): (k/mu)(DP/L) A within 1e-3.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case, model = sys.argv[1], sys.argv[2]
d, mu, n0, dp, L = (float(v) for v in sys.argv[3:8])
rhoF = 1000.0
phi0 = 1 - n0


def Fhat(phi, Re):
    """Beetstra-van der Hoef drag coefficient (coupling-formulas.md 2.1)."""
    F = 10 * phi / (1 - phi) ** 2 + (1 - phi) ** 2 * (1 + 1.5 * np.sqrt(phi))
    if Re > 0:
        F += (0.413 * Re / (24 * (1 - phi) ** 2)
              * (1 / (1 - phi) + 3 * phi * (1 - phi) + 8.4 * Re ** -0.343)
              / (1 + 10 ** (3 * phi) * Re ** (-(1 + 4 * phi) / 2)))
    return F


t = foamio.latest_time(case)
lat = foamio.Lattice(foamio.read(case, t, 'C'))


def field(name):
    return np.atleast_2d(lat.grid(foamio.read(case, t, name)))[:, :, 0]


U = field('U')
Us = field('Usoil') if model != 'fixed' else 0 * U
p = field('p')
x = lat.axis(0)
q = U[:, :, 0] - n0 * Us[:, :, 0]
mid = (x > 0.1 * L) & (x < 0.9 * L)
qs = q[mid].mean(axis=1)            # flux through each middle section
qm = qs.mean()
slope = np.polyfit(x[mid], p[mid].mean(axis=1), 1)[0]
Re = rhoF * d * abs(qm) / mu
if model == 'fixed':
    k = d
elif model == 'KozenyCarman':
    k = d * d * n0 ** 3 / (180 * phi0 ** 2)
else:
    k = n0 * d * d / (18 * phi0 * Fhat(phi0, Re))
qLocal = -k / mu * slope
qGlobal = k / mu * dp / L

ok = True
if model != 'fixed':
    vs = np.abs(Us).max()
    ok &= foamio.check(vs <= 0.01 * abs(qm), '%s seepage: the soil is held (speed <= 1%% of q)'
                       % model, 'largest %.2e m/s, q %.4e m/s' % (vs, qm))
spread = (qs.max() - qs.min()) / abs(qm)
half = (x > 0.25 * L) & (x < 0.75 * L)
across = np.ptp(q[half], axis=1).max() / abs(qm)
ok &= foamio.check(spread <= 1e-3 and across <= 1e-3,
                   '%s seepage: steady plug flow, the same flux through every section'
                   % model, 'relative spread along %.1e, across %.1e' % (spread, across))
e = qm / qLocal - 1
ok &= foamio.check(abs(e) <= 1e-4, '%s seepage: Darcy q = (k/mu)(-dp/dx) within 1e-4 inside '
                   'the column (k = %.4e m2, Re = %.1e)' % (model, k, Re),
                   'q %.6e m/s, -dp/dx %.3f Pa/m, deviation %+.1e' % (qm, -slope, e))
e = qm / qGlobal - 1
ok &= foamio.check(abs(e) <= 1e-4, '%s seepage: q = (k/mu) dp/L within 1e-4' % model,
                   'q %.6e m/s vs %.6e, deviation %+.1e' % (qm, qGlobal, e))

# The seepage discharge OpenFOAM's surfaceFieldValue reads on a plane
# through the soil at mid-length: q A, A the section 0.04 m x 0.01 m
root = os.path.join(case, 'postProcessing', 'seepage', '0')
rows = np.loadtxt(os.path.join(root, os.listdir(root)[0]), comments='#', ndmin=2)
Q = rows[-1, 1]
A = 0.04 * 0.01
e = Q / (qGlobal * A) - 1
ok &= foamio.check(abs(e) <= 1e-3, '%s seepage: the discharge through the soil\'s '
                   'mid-section (surfaceFieldValue on a sampled plane) = (k/mu)(dp/L) A '
                   'within 1e-3' % model, '%.6e m3/s vs %.6e, deviation %+.1e'
                   % (Q, qGlobal * A, e))
sys.exit(0 if ok else 1)
