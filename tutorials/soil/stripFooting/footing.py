#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     footing.py CASE [--png FILE]
#
# Description
#     The strip footing's pressure against its settlement (the loaded
#     points' mean displacement, postProcessing/surfaceLoad) with
#     Prandtl's bearing capacity q_u = (2 + pi) c_u (c_u from the clay's
#     cohesion in constant/soilProperties). Prints the pressure at
#     settlements of 1%, 5% and 10% of B (B = 1 m; the last a common
#     failure criterion) against q_u; with --png, the curve and the clay's
#     points at the last written time coloured by their plastic strain.
#------------------------------------------------------------------------------
import os
import re
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(
    os.environ.get('MPMLBM_PROJECT_DIR', os.path.join(here, '..', '..', '..')),
    'tests', 'lib'))
import foamio   # noqa: E402  (the project's reader of OpenFOAM's files)

B = 1.0


def main():
    case = sys.argv[1] if len(sys.argv) > 1 else '.'
    png = sys.argv[sys.argv.index('--png') + 1] if '--png' in sys.argv else None
    soil = re.sub(r'//.*', '', open(os.path.join(case, 'constant', 'soilProperties')).read())
    cu = float(re.search(r'cohesion\s+([-+0-9.eE]+)', soil).group(1))
    qu = (2 + np.pi) * cu
    d = np.loadtxt(os.path.join(case, 'postProcessing', 'surfaceLoad', '0', 'surfaceLoad.dat'),
                   ndmin=2)
    x0 = foamio.read_cloud(case, '0', 'x')
    box = re.sub(r'//.*', '', open(os.path.join(case, 'constant',
                                                'surfaceLoadProperties')).read())
    ymin = float(re.search(r'min\s+\(\s*\S+\s+(\S+)', box).group(1))
    xmax = float(re.search(r'max\s+\(\s*(\S+)', box).group(1))
    loaded = (x0[:, 0] < xmax) & (x0[:, 1] > ymin)
    q = d[:, 1]
    s = d[:, 3] + x0[loaded, 1].mean()
    print("c_u %.4g Pa: Prandtl's q_u = (2 + pi) c_u = %.4g Pa" % (cu, qu))
    for frac in (0.01, 0.05, 0.1):
        if s.max() >= frac * B:
            qf = np.interp(frac * B, s, q)
            print('pressure at a settlement of %4.0f%% of B: %.4g Pa = %.3f q_u'
                  % (100 * frac, qf, qf / qu))
        else:
            print('settlement of %.0f%% of B not reached (largest %.3g m at %.3f q_u)'
                  % (100 * frac, s.max(), q[-1] / qu))
    if not png:
        return
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(12, 4.6))
    a1.plot(1e3 * s, q / cu, '-', label='mpmLbmFoam')
    a1.axhline(2 + np.pi, color='k', ls='--', label='Prandtl: 2 + pi')
    a1.set_xlabel('settlement [mm]')
    a1.set_ylabel('pressure / c_u')
    a1.set_title('strip footing on Tresca clay (B = 1 m, half section)')
    a1.legend(loc='lower right')
    last = foamio.times(case)[-1]
    x = foamio.read_cloud(case, last, 'x')
    ep = foamio.read_cloud(case, last, 'plasticStrain')
    sc = a2.scatter(x[:, 0], x[:, 1], c=np.minimum(ep, 0.2), s=2, cmap='viridis')
    a2.set_aspect('equal')
    a2.set_xlim(0, 4)
    a2.set_ylim(0, 3.5)
    a2.set_title('plastic strain at t = %s s (pressure %.2f q_u)' % (last, q[-1] / qu))
    fig.colorbar(sc, ax=a2, label='equivalent plastic strain (cut at 0.2)')
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print('wrote', png)


if __name__ == '__main__':
    main()
