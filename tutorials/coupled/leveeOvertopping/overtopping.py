#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     overtopping.py CASE [--png FILE]
#
# Description
#     What the overtopped levee tells at every written time:
#     - the eroded mass per metre of levee (postProcessing/erosion), the part
#       still suspended and the part carried out through the tailwater's
#       floor;
#     - the crest's height: the highest point of the sand between the
#       crest's ends (x = 0.7 to 0.9 m); the downstream slope's retreat: the
#       sand's outermost x at half the levee's height (0.2 m) against the
#       initial slope's (1.2 m);
#     - the overflow per metre: the reservoir meter's inflow through its
#       floor (the level held at 0.45 m) and the tailwater meter's outflow
#       (function objects of system/controlDict);
#     --png: the water, the suspended sand's concentration and the levee's
#     points at three times, and the numbers above against time.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

# The levee (system/setMaterialPointsDict) and the flume's thickness
TOE_UP, CREST_UP, CREST_DOWN, TOE_DOWN, HEIGHT, DZ = 0.3, 0.7, 0.9, 1.5, 0.4, 0.01


def meter(case, name):
    """Time and flux [m2/s per metre] of a surfaceFieldValue meter."""
    rows = foamio.post_processing(case, name, 'surfaceFieldValue.dat')
    if rows.shape[0] == 0 or rows.shape[1] < 2:
        return np.zeros(0), np.zeros(0)
    return rows[:, 0], rows[:, 1] / DZ


def levee(case, t):
    """The crest's height and the downstream slope's x at mid-height."""
    x = foamio.read_cloud(case, t, 'x', by_identity=False)
    if len(x) == 0:
        return 0.0, TOE_UP
    crest = x[(x[:, 0] > CREST_UP) & (x[:, 0] < CREST_DOWN), 1]
    mid = x[np.abs(x[:, 1] - 0.5 * HEIGHT) < 0.01, 0]
    return (crest.max() if len(crest) else 0.0), (mid.max() if len(mid) else TOE_UP)


def main():
    case, png = foamio.case_and_png(sys.argv[1:])

    times = foamio.times(case)
    # (the totals since erosion started: a restart carries them on)
    rows = foamio.post_processing(case, 'erosion', 'erosion.dat')
    if rows.shape[0] == 0:
        sys.exit('%s: no postProcessing/erosion/<start>/erosion.dat' % case)
    # (written times past the balance's last row are an earlier run's,
    # left behind by a restart from before them: not this run's state)
    stale = [t for t in times if float(t) > rows[-1, 0] + 1e-9]
    if stale:
        print('Written times after the erosion balance ends (%g s), from an'
              ' earlier run, skipped: %s' % (rows[-1, 0], ' '.join(stale)))
        times = [t for t in times if t not in stale]
    tIn, qIn = meter(case, 'reservoirMeter')
    tOut, qOut = meter(case, 'tailwaterMeter')

    print('%6s %12s %12s %12s %10s %12s %12s %12s'
          % ('t [s]', 'eroded', 'suspended', 'out', 'crest',
             'slope x(0.2)', 'q in', 'q out'))
    print('%6s %12s %12s %12s %10s %12s %12s %12s'
          % ('', '[kg/m]', '[kg/m]', '[kg/m]', '[m]', '[m]', '[m2/s]', '[m2/s]'))
    summary = []
    for t in times:
        tt = float(t)
        r = rows[np.argmin(np.abs(rows[:, 0] - tt))] if tt > 0 else np.zeros(5)
        crest, slope = levee(case, t)
        qi = -qIn[np.argmin(np.abs(tIn - tt))] if len(tIn) and tt > 0 else 0.0
        qo = qOut[np.argmin(np.abs(tOut - tt))] if len(tOut) and tt > 0 else 0.0
        summary.append((tt, r[1] / DZ, r[2] / DZ, r[3] / DZ, crest, slope, qi, qo))
        print('%6.2f %12.4f %12.4f %12.4f %10.4f %12.4f %12.5f %12.5f'
              % summary[-1])
    summary = np.array(summary)

    if png is None:
        return
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt

    lat = foamio.Lattice(foamio.read(case, times[-1], 'C'))
    xs, ys = lat.axis(0), lat.axis(1)
    extent = (xs[0] - 0.5 * lat.dx, xs[-1] + 0.5 * lat.dx,
              ys[0] - 0.5 * lat.dx, ys[-1] + 0.5 * lat.dx)
    shown = [times[0], times[len(times) // 2], times[-1]]
    fig = plt.figure(figsize=(11, 11))
    cmax = 1.0
    for t in shown[1:]:
        c = np.asarray(foamio.read(case, t, 'fines'))
        cmax = max(cmax, np.percentile(c[c > 0], 99) if (c > 0).any() else 0)
    outline = np.array([(TOE_UP, 0), (CREST_UP, HEIGHT), (CREST_DOWN, HEIGHT),
                        (TOE_DOWN, 0)])
    for k, t in enumerate(shown):
        ax = fig.add_subplot(4, 1, k + 1)
        alpha = lat.grid(foamio.read(case, t, 'alpha.water'))[:, :, 0].T
        fines = lat.grid(foamio.read(case, t, 'fines'))[:, :, 0].T
        ax.imshow(np.where(alpha > 0.5, 1.0, np.nan), origin='lower', extent=extent,
                  cmap='Blues', vmin=0, vmax=2.5, interpolation='nearest')
        im = ax.imshow(np.where((alpha > 0.5) & (fines > 1e-2 * cmax), fines, np.nan),
                       origin='lower', extent=extent, cmap='YlOrBr', vmin=0,
                       vmax=cmax, interpolation='nearest', alpha=0.9)
        x = foamio.read_cloud(case, t, 'x', by_identity=False)
        if len(x):
            ax.plot(x[:, 0], x[:, 1], ',', color='saddlebrown')
        ax.plot(outline[:, 0], outline[:, 1], 'k--', lw=0.8)
        ax.set_xlim(extent[0], extent[1])
        ax.set_ylim(extent[2], 0.5)
        ax.set_aspect('equal')
        ax.set_ylabel('y [m]')
        ax.set_title('t = %s s: water (blue), suspended sand [kg/m3] (colour), '
                     'the levee\'s points; dashed: the levee at the start' % t,
                     fontsize=9)
        fig.colorbar(im, ax=ax, fraction=0.02, pad=0.01)
    ax.set_xlabel('x [m]')

    ax = fig.add_subplot(4, 2, 7)
    ax.plot(rows[:, 0], rows[:, 1] / DZ, label='eroded')
    ax.plot(rows[:, 0], rows[:, 2] / DZ, label='suspended')
    ax.plot(rows[:, 0], rows[:, 3] / DZ, label='out through the tailwater')
    ax.set_xlabel('t [s]')
    ax.set_ylabel('sand [kg per m of levee]')
    ax.legend(fontsize=8)
    ax = fig.add_subplot(4, 2, 8)
    ax.plot(summary[:, 0], summary[:, 4], 'o-', label='crest height [m]')
    ax.plot(summary[:, 0], summary[:, 5] - summary[0, 5], 's-',
            label='slope\'s advance at y = 0.2 m [m] (negative: retreat)')
    if len(tIn):
        ax2 = ax.twinx()
        ax2.plot(tIn, -qIn, 'g', lw=0.8, label='overflow q in [m2/s]')
        ax2.set_ylabel('q [m2/s]', color='g')
    ax.set_xlabel('t [s]')
    ax.legend(fontsize=8, loc='center left')
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == '__main__':
    main()
