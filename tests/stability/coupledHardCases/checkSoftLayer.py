#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkSoftLayer.py CASE LABEL
#
# Description
#     Soft layers of fine sand along the walls of a slot with water flowing
#     through it (softFineLayer/ of the Alltest: nothing loads the soil but
#     the water's drag and pressure and round-off). Checks (each a
#     PASS/FAIL that sets the exit code):
#     - runs to End; no non-finite value in any field or cloud file;
#     - soil mass exact, no point lost, every point inside the slot;
#     - nothing grows: the soil's kinetic energy (the log's, every step)
#       over the last 0.1 s at most its largest over 0.1 to 0.2 s (the
#       start-up's load has passed by then). An exchange that feeds the
#       layers' elastic modes grows them from round-off by orders of
#       magnitude per 0.1 s (measured before the drag was integrated in
#       the soil's sub-steps: x 3000 in kinetic energy per 0.1 s with
#       porous flow and buoyancy, the plain drag unstable at 0.15 s).
#------------------------------------------------------------------------------
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
from common import foamio  # noqa: E402

case, label = sys.argv[1], sys.argv[2]

ended, why = common.ran(case)
times = foamio.times(case)
ok = foamio.check(ended, '%s: runs to the end' % label,
                  'written up to t = %s s%s' % (times[-1], '; stopped: ' + why if why else ''))

nFiles, bad = common.nonFinite(case)
ok &= foamio.check(nFiles > 0 and not bad, '%s: no NaN or inf in any written field or cloud file'
                  % label, '%d files over %d times%s'
                  % (nFiles, len(times), ', bad: ' + ' '.join(bad[:4]) if bad else ''))

dm, same, inside, ext, nPoints = common.soilMass(case, (0, 0), (0.064, 0.056))
ok &= foamio.check(dm == 0 and same and inside,
                   '%s: soil mass exact, no point lost, every point inside the slot' % label,
                   '%d points, largest change %.1e, x in [%.4f, %.4f], y in [%.4f, %.4f]'
                   % ((nPoints, dm) + tuple(ext)))

t, _, ke = common.progress(case)
tEnd = t.max() if t.size else 0
early = (t > 0.1) & (t <= 0.2)
late = t > tEnd - 0.1
kEarly = np.nanmax(ke[early]) if early.any() else np.nan
kLate = np.nanmax(ke[late]) if late.any() else np.nan
ok &= foamio.check(bool(tEnd >= 0.3 and kLate <= kEarly),
                   '%s: the soil\'s kinetic energy does not grow (largest over the last 0.1 s '
                   '<= largest over 0.1 to 0.2 s)' % label,
                   '%.3g J against %.3g J (ratio %.3g) up to t = %g s'
                   % (kLate, kEarly, kLate / kEarly if kEarly > 0 else np.nan, tEnd))
sys.exit(0 if ok else 1)
