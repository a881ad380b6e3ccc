#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     damBreak.py CASE [--a A] [--png FILE] [--label TEXT]
#
# Description
#     The surge front of the Martin & Moyce 1952 dam break (column of width
#     a, default 0.05715 m, and height 2a: n^2 = 2) read off every written
#     alpha.water: Z = x_front/a, the front being the water's length along
#     the bottom cell row (the sum of alpha.water times dx, from the left
#     wall; in 3D its mean across the tank), against T = t sqrt(2 g/a)
#     (g = 9.81). Compared with their measurements (Phil. Trans. R. Soc. A
#     244, 312; as tabulated in Lethe's examples/multiphysics/dam-break,
#     a = 2.25 in): prints one line per write "T Z Z_measured" where T is
#     within the measured range, then "damBreak: front max relative error E
#     over T in [1.4, 2.96]" and the same over the whole range; --png plots
#     Z(T) with the measurements, and alpha.water at four writes.
#
#     Computations of this experiment commonly lead the early measurements:
#     the gate of their tank took time to open.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

# Martin & Moyce 1952, n^2 = 2, a = 2.25 in (Lethe, dam-break-2d.py)
T_MM = np.array([0, 0.41, 0.84, 1.19, 1.43, 1.63, 1.82, 1.97, 2.20, 2.32,
                 2.50, 2.64, 2.82, 2.96])
Z_MM = np.array([1, 1.11, 1.23, 1.44, 1.67, 1.89, 2.11, 2.33, 2.56, 2.78,
                 3.00, 3.22, 3.44, 3.67])


def front(case, a=0.05715, g=9.81):
    """(T, Z) at every written time of the case."""
    ts = [t for t in foamio.times(case)]
    lat = foamio.Lattice(foamio.read(case, ts[-1], 'C')) if os.path.exists(
        os.path.join(case, ts[-1], 'C')) else None
    T, Z = [], []
    for t in ts:
        alpha = foamio.read(case, t, 'alpha.water')
        if lat is None:
            raise SystemExit('damBreak.py: no cell centres C in %s/%s: run '
                             'postProcess -func writeCellCentres -latestTime'
                             % (case, ts[-1]))
        # (3D: the mean over the cells across the tank)
        bottom = lat.grid(alpha)[:, 0, :]
        T.append(float(t) * np.sqrt(2 * g / a))
        Z.append(np.nansum(bottom) / bottom.shape[1] * lat.dx / a)
    return np.array(T), np.array(Z)


def errors(T, Z, tmin=0.0):
    """Relative error of Z against the measurements, interpolated in T."""
    inside = (T >= max(tmin, T_MM[0])) & (T <= T_MM[-1])
    Zm = np.interp(T[inside], T_MM, Z_MM)
    return T[inside], Z[inside], Zm, np.abs(Z[inside] / Zm - 1)


if __name__ == '__main__':
    case = sys.argv[1]
    a = float(sys.argv[sys.argv.index('--a') + 1]) if '--a' in sys.argv else 0.05715
    png = sys.argv[sys.argv.index('--png') + 1] if '--png' in sys.argv else None
    label = (sys.argv[sys.argv.index('--label') + 1] if '--label' in sys.argv
             else 'mpmLbmFoam (free-surface LBM)')
    T, Z = front(case, a)
    Ti, Zi, Zm, e = errors(T, Z)
    for row in zip(Ti, Zi, Zm):
        print('%.3f %.4f %.4f' % row)
    late = Ti >= 1.4
    if late.any():
        print('damBreak: front max relative error %.4f over T in [1.4, %.2f],'
              ' %.4f over T in [0, %.2f]'
              % (e[late].max(), T_MM[-1], e.max(), T_MM[-1]))
    else:
        print('damBreak: the run ends at T = %.3f, before the measurements'
              ' from T = 1.4 on' % T[-1])
    if png:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        ts = foamio.times(case)
        snaps = [ts[int(round(k*(len(ts) - 1)/3))] for k in range(4)]
        fig = plt.figure(figsize=(10, 4.2))
        grid = fig.add_gridspec(4, 3, width_ratios=[1.25, 1.25, 0.04],
                                wspace=0.25, hspace=0.15)
        ax = fig.add_subplot(grid[:, 0])
        ax.plot(T, Z, '-', label=label)
        ax.plot(T_MM, Z_MM, 'o', label='Martin & Moyce 1952 ($n^2 = 2$)')
        ax.set_xlabel(r'$T = t\,\sqrt{2g/a}$')
        ax.set_ylabel(r'$Z = x_{front}/a$')
        ax.set_xlim(0, max(T.max(), T_MM[-1]))
        ax.grid(True, alpha=0.3)
        ax.legend()
        lat = foamio.Lattice(foamio.read(case, ts[-1], 'C'))
        for k, t in enumerate(snaps):
            sub = fig.add_subplot(grid[k, 1])
            alpha = lat.grid(foamio.read(case, t, 'alpha.water'))
            # (3D: the plane in the middle across the tank)
            alpha = alpha[:, :, alpha.shape[2] // 2]
            image = sub.imshow(alpha.T, origin='lower', cmap='Blues', vmin=0,
                               vmax=1, extent=(0, lat.n[0]*lat.dx/a, 0,
                                               lat.n[1]*lat.dx/a))
            sub.set_yticks([])
            sub.set_xticks([] if k < 3 else [0, 1, 2, 3, 4, 5, 6])
            sub.text(0.99, 0.9, 't = %s s' % t, transform=sub.transAxes,
                     ha='right', va='top', fontsize=8)
        sub.set_xlabel('x/a')
        bar = fig.colorbar(image, cax=fig.add_subplot(grid[:, 2]))
        bar.set_label('alpha.water (water fraction, -)')
        fig.savefig(png, dpi=110, bbox_inches='tight')
        print('Picture: %s' % png)
