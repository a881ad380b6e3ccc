#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     pointsMoved.py CASE TIME0 TIME1 LABEL
#
# Description
#     Material points that changed processor between two times of a
#     decomposed case (from processor*/<time>/lagrangian/materialPoints/
#     origId): PASS: when some did and every point is on one processor
#     only at both times.
#------------------------------------------------------------------------------
import glob
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests',
                                'lib'))
import foamio

case, t0, t1, label = sys.argv[1:5]


def owners(time):
    owner = {}
    counts = []
    for p in sorted(glob.glob(os.path.join(case, 'processor*')),
                    key=lambda d: int(d.rsplit('processor', 1)[1])):
        f = os.path.join(p, time, 'lagrangian', 'materialPoints', 'origId')
        ids = foamio.read_list(f).astype(np.int64) if os.path.isfile(f) \
            else np.zeros(0, dtype=np.int64)
        counts.append(ids.size)
        for i in ids:
            owner.setdefault(int(i), []).append(p)
    return owner, counts


o0, c0 = owners(t0)
o1, c1 = owners(t1)
once = all(len(v) == 1 for v in o0.values()) and \
    all(len(v) == 1 for v in o1.values()) and set(o0) == set(o1)
moved = sum(1 for i in o0 if once and o0[i] != o1[i])
ok = foamio.check(once and moved > 0,
                  '%s material points migrate between processors '
                  '(each on one processor)' % label,
                  '%d of %d moved from %s s to %s s; per processor %s -> %s'
                  % (moved, len(o0), t0, t1, c0, c1))
sys.exit(0 if ok else 1)
