#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkTotals.py FULL RESTART T0 T1 LABEL
#
# Description
#     A restart's erosion balance goes on where the written run stood:
#     FULL is the uninterrupted run's erosion.dat, RESTART the one a run
#     started at T0 from FULL's written time writes (its own start folder).
#     At T1 the restart's eroded, suspended and out (totals since erosion
#     started, carried over through uniform/erosionState and
#     uniform/<field>Balance) equal the uninterrupted run's within 1e-12 of
#     the eroded mass, the part eroded before T0 is not negligible (else
#     the check proves nothing), and the restart's defect stays below
#     1e-12 at every step.
#------------------------------------------------------------------------------
import sys


def rows(path):
    """{time: {column: value}} of an erosion.dat"""
    cols, out = None, {}
    for line in open(path):
        if line.startswith('#'):
            cols = line[1:].split()
        elif line.strip():
            v = [float(x) for x in line.split()]
            out[v[0]] = dict(zip(cols, v))
    return out


full, restart = rows(sys.argv[1]), rows(sys.argv[2])
t0, t1, label = float(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
if t1 not in full or t1 not in restart or t0 not in full:
    sys.exit('FAIL: %s: no row at %g s in %s or %s'
             % (label, t1, sys.argv[1], sys.argv[2]))
a, b = full[t1], restart[t1]
scale = max(abs(a['eroded']), 1e-300)
worst = max(abs(a[k] - b[k]) for k in ('eroded', 'suspended', 'out')) / scale
before = full[t0]['eroded'] / scale
defect = max(abs(r['defect']) for r in restart.values())
ok = worst < 1e-12 and before > 1e-3 and defect < 1e-12
print('%s: %s: erosion.dat at %g s carries the totals since erosion started'
      ' (eroded %.6g kg, %.3g of it before %g s): eroded, suspended, out as'
      ' the uninterrupted run\'s within 1e-12 (%.2g), defect below 1e-12 at'
      ' every step (%.2g)'
      % ('PASS' if ok else 'FAIL', label, t1, b['eroded'], before, t0, worst,
         defect))
sys.exit(0 if ok else 1)
