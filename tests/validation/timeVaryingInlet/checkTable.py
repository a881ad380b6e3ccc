#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkTable.py FILE FACTOR WHAT T0 V0 T1 V1 ...
#
# Description
#     The series of a surfaceFieldValue file (postProcessing/<name>/0/
#     surfaceFieldValue.dat: time, value) against FACTOR times the table
#     (T0 V0) (T1 V1) ... of a patch's uniformFixedValue, interpolated
#     linearly as OpenFOAM's table: every step within 1e-12 of the table's
#     largest value, and a row per step.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

path, factor, what = sys.argv[1], float(sys.argv[2]), sys.argv[3]
points = np.array([float(v) for v in sys.argv[4:]]).reshape(-1, 2)
data = np.loadtxt(path, comments='#', ndmin=2)
table = factor * np.interp(data[:, 0], points[:, 0], points[:, 1])
scale = np.max(np.abs(factor * points[:, 1]))
err = np.max(np.abs(data[:, 1] - table)) / scale
ok = foamio.check(err <= 1e-12 and len(data) > 100, '%s reproduces the table '
                  'at the patch at every step' % what,
                  '%d steps, largest difference %.1e of the largest value'
                  % (len(data), err))
sys.exit(0 if ok else 1)
