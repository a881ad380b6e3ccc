#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkDenseSuspension.py SERIAL PARALLEL [CAPPED CMAX]
#
# Description
#     Fast suffusion into a dense suspension (the suffusion column of
#     tests/validation/suffusionColumn with lambda 1000 times its, the
#     suspension's weight on the water, deep-bed filtration, hindered
#     settling onto the walls and a suspension per material all on), serial and on 2 ranks cut across
#     the flow:
#     - every written field and cloud file finite;
#     - the suspension dense: above 300 kg/m3 of pore water at a write
#       time (grains over a tenth of the pore volume);
#     - the balance (eroded = filtered + suspended + out + deposited) to
#       1e-12 at every step, and the soil's solid with it: the points'
#       mass now plus eroded less filtered equal to their mass at the
#       start (1e-12 of it);
#     - 2 ranks = serial: eroded, filtered, suspended, out and deposited
#       at every step within 1e-12 of the eroded mass.
#     CAPPED: the serial case with maxConcentration CMAX (below what it
#     reaches without) and no settling: the suspension at that limit,
#     within 5% below and 15% above (the limit holds the erosion at a
#     node's content before the step, which then streams in the denser
#     water around it: measured up to 11% above), the balance and the
#     soil's solid to 1e-12.
#     Prints PASS:/FAIL: lines.
#------------------------------------------------------------------------------
import os
import sys
import glob
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests',
                                'lib'))
import foamio


def balance(case):
    path = glob.glob(os.path.join(case, 'postProcessing', 'erosion', '*',
                                  'erosion*.dat'))[0]
    names, rows = None, []
    for line in open(path):
        if line.startswith('#'):
            words = line[1:].split()
            if words and words[0] == 'Time':
                names = words
            continue
        if line.strip():
            rows.append([float(v) for v in line.split()])
    rows = np.array(rows)
    return {n: rows[:, i] for i, n in enumerate(names)}


ok = True
runs = {}
cases = sys.argv[1:3] + sys.argv[3:4]
for case in cases:
    times = foamio.times(case)
    finite = True
    cMax = 0.0
    for t in times:
        for f in ('U', 'p', 'fines.gravel'):
            v = foamio.read(case, t, f)
            finite &= bool(np.all(np.isfinite(v)))
            if f == 'fines.gravel':
                cMax = max(cMax, float(np.max(v)))
        if t != '0':
            for f in ('mass', 'porosity', 'fines'):
                finite &= bool(np.all(np.isfinite(
                    foamio.read_cloud(case, t, f))))
    ok &= foamio.check(finite, '%s: every written field and cloud file'
                       ' finite' % case, '%d times' % len(times))
    if case not in sys.argv[3:4]:
        ok &= foamio.check(cMax > 300, '%s: the suspension dense (above'
                           ' 300 kg/m3 of pore water)' % case,
                           '%.4g kg/m3' % cMax)
    B = balance(case)
    ok &= foamio.check(np.abs(B['defect']).max() < 1e-12, '%s: balance to'
                       ' 1e-12 at every step' % case, '%.2e over %d steps'
                       % (np.abs(B['defect']).max(), len(B['defect'])))
    m0 = foamio.read_cloud(case, '0', 'mass').sum()
    m1 = foamio.read_cloud(case, times[-1], 'mass').sum()
    solid = abs(m1 + B['eroded'][-1] - B['filtered'][-1] - m0) / m0
    ok &= foamio.check(solid < 1e-12, '%s: the soil\'s solid: points +'
                       ' eroded - filtered = its start' % case,
                       '%.2e (eroded %.4g, filtered %.4g kg)'
                       % (solid, B['eroded'][-1], B['filtered'][-1]))
    runs[case] = B
    if case in sys.argv[3:4]:
        cap = float(sys.argv[4])
        ok &= foamio.check(0.95 * cap <= cMax <= 1.15 * cap, '%s: the'
                           ' suspension at its upper limit maxConcentration'
                           ' %g kg/m3 (within 5%% below, 15%% above)'
                           % (case, cap), '%.5g kg/m3' % cMax)

A, B = runs[sys.argv[1]], runs[sys.argv[2]]
scale = np.abs(A['eroded']).max()
n = min(len(A['eroded']), len(B['eroded']))
same = len(A['eroded']) == len(B['eroded']) and max(
    np.abs(A[c][:n] - B[c][:n]).max()
    for c in ('eroded', 'filtered', 'suspended', 'out', 'deposited')) / scale
ok &= foamio.check(len(A['eroded']) == len(B['eroded']) and same < 1e-12,
                   '2 ranks = serial: eroded, filtered, suspended, out,'
                   ' deposited at every step within 1e-12', '%.2e' % same)
sys.exit(0 if ok else 1)
