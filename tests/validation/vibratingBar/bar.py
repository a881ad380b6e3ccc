#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     bar.py set CASE V0 L        initial velocity v0 sin(pi x/(2 L))
#     bar.py check CASE V0 L C    period and energy over the run
#
# Description
#     Vibrating bar, fixed at x = 0 and free at x = L (mpm-references.md
#     3.2): v(x, t) = v0 cos(w t) sin(b x), b = pi/(2L), w = b c; centre-of-
#     mass velocity (2 v0/pi) cos(w t), period 4L/c; total energy constant,
#     rho A L v0^2/4. 'check' prints <period error> <energy drift> <energy
#     error at t = 0> measured from the written clouds.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

mode, case = sys.argv[1], sys.argv[2]
v0, L = float(sys.argv[3]), float(sys.argv[4])
cloud = os.path.join(case, '0', 'lagrangian', 'materialPoints')

if mode == 'set':
    # (in the file's order: U is written back in it)
    x = foamio.read_cloud(case, '0', 'x', by_identity=False)
    v = np.zeros_like(x)
    v[:, 0] = v0 * np.sin(np.pi * x[:, 0] / (2 * L))
    with open(os.path.join(cloud, 'U'), 'w') as f:
        f.write('FoamFile\n{\n    version 2.0;\n    format ascii;\n'
                '    class vectorField;\n    location "0/lagrangian/'
                'materialPoints";\n    object U;\n}\n\n%d\n(\n' % len(v))
        for a in v:
            f.write('(%.17g %.17g %.17g)\n' % tuple(a))
        f.write(')\n')
    sys.exit(0)

c = float(sys.argv[5])
E = c * c  # rho = 1
times = [t for t in foamio.times(case)
         if os.path.isdir(os.path.join(case, t, 'lagrangian'))]
tt, vcm, energy = [], [], []
for t in times:
    m = foamio.read_cloud(case, t, 'mass')
    v = foamio.read_cloud(case, t, 'U')
    s = foamio.read_cloud(case, t, 'stress')
    V = foamio.read_cloud(case, t, 'volume')
    tt.append(float(t))
    vcm.append(np.sum(m * v[:, 0]) / np.sum(m))
    energy.append(np.sum(0.5 * m * v[:, 0] ** 2) + np.sum(V * s[:, 0] ** 2 / (2 * E)))
tt, vcm, energy = np.array(tt), np.array(vcm), np.array(energy)
# Zero crossings of the centre-of-mass velocity, linearly interpolated
cross = []
for i in range(len(tt) - 1):
    if vcm[i] == 0 or vcm[i] * vcm[i + 1] < 0:
        cross.append(tt[i] - vcm[i] * (tt[i + 1] - tt[i]) / (vcm[i + 1] - vcm[i]))
cross = np.array(cross)
period = 2 * np.mean(np.diff(cross)) if len(cross) > 2 else np.nan
exactPeriod = 4 * L / c
A = 0.5 * 0.5   # cross-section: dx x thickness
exactEnergy = A * L * v0 ** 2 / 4
print('%.6e %.6e %.6e' % (abs(period / exactPeriod - 1),
                          abs(energy[-1] / energy[0] - 1),
                          abs(energy[0] / exactEnergy - 1)))
