#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     probes.py CASE --png FILE
#
# Description
#     The flagship's function objects against time: the water's force on the
#     tank's far wall (latticeForces farWall) and, at the column's base
#     (materialPointProbes columnBase, moving with the soil), the vertical
#     stress, the pore pressure and the displacement.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(
    os.environ.get('MPMLBM_PROJECT_DIR', os.path.join(here, '..', '..', '..')),
    'tests', 'lib'))
import foamio   # noqa: E402  (the project's reader of OpenFOAM's files)

case = sys.argv[1]
png = sys.argv[sys.argv.index('--png') + 1]


def series(name, file):
    """Time and values of every postProcessing/<name>/<start>/<file> (a
    restart's folder replacing the rows from its start:
    foamio.post_processing)"""
    rows = foamio.post_processing(case, name, file)
    return rows if rows.size else np.zeros((0, 2))


force = series('farWall', 'force.dat')
stress = series('columnBase', 'stress.dat')
pore = series('columnBase', 'porePressure.dat')
disp = series('columnBase', 'displacement.dat')

fig, axes = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
if len(force):
    axes[0].plot(force[:, 0], force[:, 1] / 1e3, lw=1)
axes[0].set_ylabel('far wall: $F_x$ [kN]')
axes[0].set_title('The water on the tank\'s far wall (latticeForces)', fontsize=10)
if len(stress):
    axes[1].plot(stress[:, 0], -stress[:, 4] / 1e3, lw=1, label="$-\\sigma_{yy}$ (soil)")
if len(pore):
    axes[1].plot(pore[:, 0], pore[:, 1] / 1e3, lw=1, label='pore pressure')
axes[1].set_ylabel('[kPa]')
axes[1].legend(loc='best', fontsize=8)
axes[1].set_title('Column base, x = 10 m, y = 0.5 m at the start '
                  '(materialPointProbes)', fontsize=10)
if len(disp):
    axes[2].plot(disp[:, 0], disp[:, 1], lw=1, label='$u_x$')
    axes[2].plot(disp[:, 0], disp[:, 2], lw=1, label='$u_y$')
axes[2].set_ylabel('displacement [m]')
axes[2].set_xlabel('time [s]')
axes[2].legend(loc='best', fontsize=8)
fig.tight_layout()
fig.savefig(png, dpi=100)
print('Picture: %s' % png)
