#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkGravity.py CASE PHASES
#
# Description
#     In a fully periodic box with drag twoWay only gravity acts on the two
#     phases from outside: the total momentum gained between steps is
#     M g t exactly, M the mass of PHASES (water, soil or water+soil: the water's
#     sum rho V at the end, conserved, and the soil's sum m_p). Reads
#     constant/g, postProcessing/momentumBalance/0/momentum.dat (time, water,
#     soil, total), the cloud at 0, rho at the end and V at 0. Checks every
#     row against the first step's (the row of t = 0 is written when the
#     drag is built, which may be before the gravity effect gives the water
#     its g: the water's momentum then lacks its half-step share m g dt/2)
#     plus M g (t - t_1), within 1e-12 |M g t_end|, and that the gain differs
#     from that of any other choice of phases by more than 1e3 times that.
#------------------------------------------------------------------------------
import os
import re
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case, phases = sys.argv[1], sys.argv[2]
text = open(os.path.join(case, 'constant', 'g')).read()
g = np.array([float(a) for a in re.search(r'\nvalue\s+\(([^)]*)\)', text).group(1).split()])

mSoil = foamio.read_cloud(case, '0', 'mass').sum()
t = foamio.latest_time(case)
mWater = (foamio.read(case, t, 'rho') * foamio.read(case, '0', 'V')).sum()
masses = {'water': mWater, 'soil': mSoil, 'water+soil': mWater + mSoil}

d = np.atleast_2d(np.loadtxt(os.path.join(case, 'postProcessing', 'momentumBalance',
                                          '0', 'momentum.dat'), comments='#'))
time, total = d[1:, 0], d[1:, 7:10]
gained = total - total[0]
scale = np.linalg.norm(masses[phases] * g * time[-1])
err = {k: np.abs(gained - m * np.outer(time - time[0], g)).max() / scale
       for k, m in masses.items()}
ok = foamio.check(d.shape[0] > 40 and err[phases] <= 1e-12,
                  'gravity effect on %s: total momentum gained = M g t at every step '
                  '(M = %.6g kg, %d steps)' % (phases, masses[phases], d.shape[0] - 1),
                  'max deviation %.1e of |M g t_end|' % err[phases])
others = min(e for k, e in err.items() if k != phases)
ok &= foamio.check(others > 1e3 * max(err[phases], 1e-15),
                   'gravity effect on %s: not the gain of any other choice of phases'
                   % phases, 'nearest other deviation %.2g' % others)
sys.exit(0 if ok else 1)
