#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkCoupled.py CASE LABEL W H E NU DROP
#
# Description
#     Soil moving under gravity through water in a closed tank [0, W] x
#     [0, H] (the falling block and the column collapse of the Alltest;
#     elastic constants E, NU of the soil for its initial elastic energy).
#     Checks (each a PASS/FAIL that sets the exit code):
#     - runs to End;
#     - no non-finite value in any field or cloud file written;
#     - water mass exact: the log's mass defect at every step and the sum
#       of rho over the written times within 1e-10;
#     - soil mass exact (sum of the points' masses at every written time
#       equal to the initial, same number of points), every point inside
#       the tank at every written time;
#     - energy bounded (the soil starts at rest, the water at rest; the
#       drag and the water's viscosity only dissipate; a sinking soil lifts
#       water): the soil's kinetic energy
#         at every step (log)         <= E_el(0) + g sum m_p y_p(0) (all
#                                        gravity can give: the soil down to
#                                        the floor)
#         at every written time       <= E_el(0) + W_g(t),
#                                        W_g(t) = g sum m_p (y_p(0) - y_p(t))
#                                        (the work gravity has done)
#       with E_el(0) the elastic energy of the points' initial stress;
#     - the soil moves: its centre of mass at least DROP metres lower at
#       the end (the energy check is not vacuous);
#     - incompressible grains: the grains' volume sum (1 - n_p) V_p
#       conserved within 1% (the points keep their grains' volume: the
#       porosity follows the volume det F; once an open item, met since
#       2026-12-01).
#------------------------------------------------------------------------------
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
from common import foamio  # noqa: E402

case, label = sys.argv[1], sys.argv[2]
W, H = float(sys.argv[3]), float(sys.argv[4])
E, nu, minDrop = (float(v) for v in sys.argv[5:8])
g = 9.81

ended, why = common.ran(case)
times = foamio.times(case)
ok = foamio.check(ended, '%s: runs to the end' % label,
                  'written up to t = %s s%s' % (times[-1], '; stopped: ' + why if why else ''))

nFiles, bad = common.nonFinite(case)
ok &= foamio.check(nFiles > 0 and not bad, '%s: no NaN or inf in any written field or cloud file'
                  % label, '%d files over %d times%s'
                  % (nFiles, len(times), ', bad: ' + ' '.join(bad[:4]) if bad else ''))

defect, drift, nSteps = common.waterMass(case)
ok &= foamio.check(nSteps > 0 and defect <= 1e-10 and drift <= 1e-10,
                   '%s: water mass exact (log at every step and sum of rho, 1e-10)' % label,
                   'largest defect %.1e over %d steps, sum of rho %.1e' % (defect, nSteps, drift))

dm, same, inside, ext, nPoints = common.soilMass(case, (0, 0), (W, H))
ok &= foamio.check(dm == 0 and same, '%s: soil mass exact, no point lost' % label,
                   '%d points, largest change %.1e' % (nPoints, dm))
ok &= foamio.check(inside, '%s: every point inside the tank' % label,
                   'x in [%.4f, %.4f], y in [%.4f, %.4f]' % tuple(ext))

steps, _, keLog = common.progress(case)
_, ke, Wg, Eel0, supply = common.energies(case, g, E, nu)
supply += Eel0
kmax = np.nanmax(keLog) if keLog.size else np.nan
ratio = (ke[1:] / np.maximum(Eel0 + Wg[1:], 1e-300)).max() if ke.size > 1 else np.nan
tWorst = steps[np.nanargmax(keLog)] if keLog.size else np.nan
ok &= foamio.check(bool(kmax <= supply and np.all(ke <= Eel0 + Wg + 1e-9 * supply)),
               '%s: energy bounded (soil kinetic energy <= E_el(0) + g sum m y(0) at every '
               'step, <= E_el(0) + work of gravity W_g(t) at every written time)' % label,
               'largest %.4g J (step at t = %g s) against %.4g J; at the written times '
               'kinetic/(E_el(0) + W_g) up to %.3f, E_el(0) %.3g J'
               % (kmax, tWorst, supply, ratio, Eel0))

x0 = foamio.read_cloud(case, times[0], 'x')
x1 = foamio.read_cloud(case, times[-1], 'x')
m = foamio.read_cloud(case, times[0], 'mass')
drop = np.average(x0[:, 1], weights=m) - np.average(x1[:, 1], weights=m)
ok &= foamio.check(drop >= minDrop, '%s: the soil moves (centre of mass >= %g m lower)'
                   % (label, minDrop), '%.3f m lower at t = %s s' % (drop, times[-1]))

change, tWorst, J, phi, phi0 = common.grainVolume(case)
ok &= foamio.check(change <= 0.01, '%s: grains\' volume sum (1 - n) V conserved within 1%%'
                   % label, 'largest change %+.1f%% (t = %s s), point volume up to %.2f x its '
                   'initial, nodal solid fraction up to %.3f (points %.2f)'
                   % (100 * change, tWorst, J, phi, phi0))
sys.exit(0 if ok else 1)
