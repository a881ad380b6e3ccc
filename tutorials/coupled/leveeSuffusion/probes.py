#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     tutorials/coupled/leveeSuffusion/probes.py CASE [--png FILE]
#
# Description
#     What an engineer watches on a levee during suffusion, from the
#     function objects of system/controlDict and the erosion balance:
#     - the seepage meter (seepageMeter: the discharge through the landside
#       patch) per metre of levee, rising as the foundation loses its fines
#       and its permeability grows;
#     - the fines leaving per second (the time derivative of the
#       balance's "out", postProcessing/erosion) and the turbidity of the
#       outflow: that rate over the discharge [kg of fines per m3 of water];
#     - the piezometers in the foundation under the levee's waterside toe,
#       centre and landside toe: the pressure redistributes as the eroded
#       zone opens.
#     Prints the first and last readings; --png plots them against time.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(
    os.environ.get('MPMLBM_PROJECT_DIR', os.path.join(here, '..', '..', '..')),
    'tests', 'lib'))
import foamio   # noqa: E402  (the project's reader of OpenFOAM's files)

DEPTH = 0.02                       # the case's thickness (blockMeshDict)
# The water starts from rest under the full head: pressure waves cross the
# lattice for the first seconds (the meters sample them every 0.25 s)
SETTLED = 4.0
PIEZOMETERS = ('waterside toe, x = 0.56 m', 'centre, x = 0.8 m',
               'landside toe, x = 1.04 m')


def series(case, name, file):
    """Time and values of postProcessing/<name>/<start>/<file> (a restart's
    folder replacing the rows from its start: foamio.post_processing)"""
    return foamio.post_processing(case, name, file)


def main():
    case, png = foamio.case_and_png(sys.argv[1:])
    flow = series(case, 'seepageMeter', 'surfaceFieldValue.dat')
    piezo = series(case, 'piezometers', 'p')
    balance = series(case, 'erosion', 'erosion.dat')
    if len(flow) < 2 or len(piezo) < 2:
        # (a run shorter than the meters' interval, as the smoke test's)
        print('probes.py: fewer than two readings of seepageMeter and '
              'piezometers in %s (they sample every 0.25 s): no picture'
              % os.path.join(case, 'postProcessing'))
        return
    t, q = flow[:, 0], flow[:, 1] / DEPTH          # m2/s per metre
    # The fines leaving per second per metre, at the meter's times
    if len(balance) > 1:
        out = np.interp(t, balance[:, 0], balance[:, 3]) / DEPTH
        rate = np.gradient(out, t) if len(t) > 1 else np.zeros_like(t)
    else:
        rate = np.zeros_like(t)
    # (turbidity only where the water flows out: not over the start's
    # near-zero discharge)
    flowing = q > 0.1 * np.median(q)
    turbidity = np.where(flowing, rate / np.where(flowing, q, 1.0), np.nan)
    i0 = int(np.searchsorted(t, SETTLED))
    i0 = min(i0, len(t) - 1)
    for i in (i0, len(t) - 1):
        print('levee: t %g s: discharge %.4g l/s per metre (%.2f of the '
              'reading at %g s), fines out %.4g g/s per metre, turbidity '
              '%.4g kg/m3' % (t[i], 1e3 * q[i], q[i] / q[i0] if q[i0] else np.nan,
                              t[i0], 1e3 * rate[i], turbidity[i]))
    j0 = min(int(np.searchsorted(piezo[:, 0], SETTLED)), len(piezo) - 1)
    for k, name in enumerate(PIEZOMETERS):
        print('levee: piezometer %s: %.1f Pa at %g s, %.1f Pa at %g s'
              % (name, piezo[j0, 1 + k], piezo[j0, 0], piezo[-1, 1 + k],
                 piezo[-1, 0]))
    if not png:
        return
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(3, 1, figsize=(8, 8.5), sharex=True)
    axes[0].plot(t, 1e3 * q, color='tab:blue')
    axes[0].set_ylabel('discharge [l/s per m]')
    axes[0].set_title('Seepage meter (the landside patch)', fontsize=10)
    axes[1].plot(t, 1e3 * rate, color='tab:brown', label='fines out [g/s per m]')
    axes[1].set_ylabel('fines out [g/s per m]')
    tx = axes[1].twinx()
    tx.plot(t, turbidity, color='tab:orange', ls='--',
            label='turbidity [kg/m$^3$]')
    tx.set_ylabel('turbidity of the outflow [kg/m$^3$]')
    axes[1].set_title('Fines leaving with the outflow (postProcessing/erosion '
                      'over the discharge)', fontsize=10)
    lines = axes[1].get_lines() + tx.get_lines()
    axes[1].legend(lines, [l.get_label() for l in lines], fontsize=8,
                   loc='upper left')
    for k, name in enumerate(PIEZOMETERS):
        axes[2].plot(piezo[:, 0], piezo[:, 1 + k], label=name)
    axes[2].set_ylabel('p [Pa]')
    axes[2].set_xlabel('t [s]')
    axes[2].set_title('Piezometers in the foundation, 8 cm deep', fontsize=10)
    axes[2].legend(fontsize=8)
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.axvspan(0, min(SETTLED, t[-1]), color='0.9', zorder=0)
    axes[0].text(0.02, 0.8, 'start from rest:\npressure waves', fontsize=8,
                 transform=axes[0].transAxes, color='0.4')
    fig.suptitle('A levee losing its foundation\'s fines: what the '
                 'instruments read')
    fig.tight_layout()
    fig.savefig(png, dpi=100)
    print('probes.py: %s' % png)


if __name__ == '__main__':
    main()
