#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     embankment.py CASE [--png FILE]
#
# Description
#     The numbers of the embankment seepage read off every written time:
#     - q/k [m], the discharge per unit width over the hydraulic conductivity
#       k = K g/nu: the water's mass flux through vertical sections of the
#       embankment (x = 0.8, 1.0, 1.2 m) over rho k; steady when the
#       sections agree and stop changing. The phreatic line does not depend
#       on k, q is proportional to it: q = (q/k) k for any sand;
#     - the reservoir's level h1 (as it settles under the floor's pressure)
#       and Casagrande's estimate of q/k for it (the flow net's classic
#       approximation, Casagrande 1937, "Seepage through dams"; Das,
#       Advanced Soil Mechanics, sec. 8): the phreatic line is a parabola
#       entering 0.3 D upstream of where the level meets the upstream slope
#       (D that wetted slope's horizontal length), d the horizontal
#       distance from there to the downstream toe, beta the downstream
#       slope's angle:
#           a = sqrt(d^2 + H^2) - sqrt(d^2 - H^2 cot^2 beta),
#           q/k = a sin^2 beta,  the exit point a sin(beta) above the toe;
#     - the exit point: the highest wet node of the downstream slope;
#     - the function objects of system/controlDict: the flow meters of the
#       reservoir's and the tailwater's floors (q/k in and out), and the
#       piezometers 1 cm above the floor: their head p/(rho g) + y against
#       the phreatic line's height above them (Dupuit's assumption:
#       vertical equipotentials, the head is the height of the water).
#     - with material points (Allrun -soil): the embankment's largest
#       displacement and plastic strain, and its vertical effective stress.
#     --png: the water (alpha.water) with the phreatic line, the Darcy
#     velocity in the embankment, q/k against time (sections and meters),
#     the piezometric heads against time; with material points the sand's
#     vertical effective stress too.
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

# The case's geometry (system/topoSetDict, blockMeshDict) and materials
TOE_UP, CREST_UP, CREST_DOWN, TOE_DOWN, HEIGHT = 0.3, 0.7, 0.9, 1.5, 0.4
K, NU, G, RHO = 1e-5, 5e-3, 9.81, 1000.0
SECTIONS = (0.8, 1.0, 1.2)


def inside(x, y):
    """Whether a point is in the embankment."""
    return ((y < HEIGHT) & (x > TOE_UP) & (x < TOE_DOWN)
            & (y < x - TOE_UP)
            & (y < HEIGHT * (TOE_DOWN - x) / (TOE_DOWN - CREST_DOWN)))


def casagrande(H):
    """q/k and the exit height for a reservoir level H (Casagrande 1937)."""
    D = H * (CREST_UP - TOE_UP) / HEIGHT
    xA = TOE_UP + D - 0.3 * D
    d = TOE_DOWN - xA
    beta = np.arctan(HEIGHT / (TOE_DOWN - CREST_DOWN))
    a = np.sqrt(d ** 2 + H ** 2) - np.sqrt(d ** 2 - (H / np.tan(beta)) ** 2)
    return a * np.sin(beta) ** 2, a * np.sin(beta)


def read(case):
    ts = foamio.times(case)
    if len(ts) < 2:
        raise SystemExit('embankment.py: no time written after the start in %s '
                         '(writeInterval in system/controlDict beyond endTime?)' % case)
    C = None
    for t in reversed(ts):
        if os.path.exists(os.path.join(case, t, 'C')):
            C = foamio.read(case, t, 'C')
            break
    if C is None:
        raise SystemExit('embankment.py: no cell centres C in %s: run '
                         'postProcess -func writeCellCentres -latestTime' % case)
    lat = foamio.Lattice(C)
    k = K * G / NU
    x, y = lat.axis(0), lat.axis(1)
    cols = [int(np.argmin(abs(x - s))) for s in SECTIONS]
    up = x < 0.2
    rows = []
    for t in ts[1:]:
        a = lat.grid(foamio.read(case, t, 'alpha.water'))[:, :, 0]
        U = lat.grid(np.asarray(foamio.read(case, t, 'U'))[:, 0])[:, :, 0]
        rho = lat.grid(foamio.read(case, t, 'rho'))[:, :, 0]
        if os.path.exists(os.path.join(case, t, 'soilFraction')):
            # (Allrun -soil: rho is the water's mass per mixture volume,
            # n times the pore water's density)
            n = 1 - lat.grid(foamio.read(case, t, 'soilFraction'))[:, :, 0]
            rho = rho / np.where(n > 0, n, 1)
        q = (rho * U * a).sum(axis=1) * lat.dx / (RHO * k)
        h1 = a[up, :].sum(axis=1).mean() * lat.dx
        rows.append((float(t), q[cols], h1))
    return lat, ts, rows


def series(case, name, file):
    """Time and values of postProcessing/<name>/<start>/<file> (a restart's
    folder replacing the rows from its start: foamio.post_processing)"""
    rows = foamio.post_processing(case, name, file)
    return rows if rows.size else np.zeros((0, 4))


PIEZOMETER_Y = 0.01


def meters(case, lat):
    """The function objects' series: (t, q/k in, q/k out) of the floors'
    flow meters and (t, head at each piezometer)"""
    k = K * G / NU
    depth = lat.dx            # (one cell thick)
    inflow = series(case, 'reservoirMeter', 'surfaceFieldValue.dat')
    outflow = series(case, 'tailwaterMeter', 'surfaceFieldValue.dat')
    n = min(len(inflow), len(outflow))
    flow = np.zeros((n, 3))
    if n:
        # (U.n on a floor: negative where the water enters)
        flow[:, 0] = inflow[:n, 0]
        flow[:, 1] = -inflow[:n, 1] / depth / k
        flow[:, 2] = outflow[:n, 1] / depth / k
    piezo = series(case, 'piezometers', 'p')
    if len(piezo):
        piezo = piezo.copy()
        piezo[:, 1:] = piezo[:, 1:] / (RHO * G) + PIEZOMETER_Y
    return flow, piezo


def exit_height(lat, a):
    """The highest wet node of the embankment's downstream face."""
    x, y = lat.axis(0), lat.axis(1)
    X, Y = np.meshgrid(x, y, indexing='ij')
    emb = inside(X, Y)
    face = emb & ~np.roll(emb, -1, axis=0) & (X > CREST_DOWN)
    wet = face & (a > 0.5)
    return Y[wet].max() + 0.5 * lat.dx if wet.any() else 0.0


def main():
    case, png = foamio.case_and_png(sys.argv[1:])
    lat, ts, rows = read(case)
    t, q, h1 = rows[-1]
    qMean = q.mean()
    qC, exitC = casagrande(h1)
    a = lat.grid(foamio.read(case, ts[-1], 'alpha.water'))[:, :, 0]
    hExit = exit_height(lat, a)
    change = abs(qMean / rows[-2][1].mean() - 1) if len(rows) > 1 else np.nan
    print('embankment: t %g s, reservoir level h1 %.4f m' % (t, h1))
    print('embankment: q/k through x = %s m: %s m (spread %.2f%%, change since '
          'the last write %.2f%%)' % (', '.join('%g' % s for s in SECTIONS),
                                      ', '.join('%.5f' % v for v in q),
                                      100 * (q.max() - q.min()) / qMean, 100 * change))
    print('embankment: exit point %.3f m above the toe (Casagrande %.3f m)'
          % (hExit, exitC))
    print('embankment: q/k %.5f m, Casagrande %.5f m (%+.1f%%); q = %.4e m2/s '
          'for k = %.3g m/s' % (qMean, qC, 100 * (qMean / qC - 1),
                               qMean * K * G / NU, K * G / NU))
    flow, piezo = meters(case, lat)
    if len(flow):
        print('embankment: flow meters at t %g s: q/k in (reservoir floor) '
              '%.5f m, out (tailwater floor) %.5f m' % tuple(flow[-1]))
    if len(piezo):
        x = lat.axis(0)
        for i, xs in enumerate(SECTIONS):
            h = a[int(np.argmin(abs(x - xs))), :].sum() * lat.dx
            print('embankment: piezometer x = %g m at t %g s: head %.4f m, '
                  'the phreatic line %.4f m above the floor (%+.1f%%)'
                  % (xs, piezo[-1, 0], piezo[-1, 1 + i], h,
                     100 * (piezo[-1, 1 + i] / h - 1)))
    sand = soil(case, ts)
    if sand is not None:
        X0, X, s, ep = sand
        d = np.linalg.norm(X - X0, axis=1)
        i = int(np.argmax(d))
        print('embankment: the sand (%d points): largest displacement %.2e m at '
              '(%.2f, %.2f) m, plastic strain up to %.2e (%d points yielded)'
              % (len(d), d[i], X0[i, 0], X0[i, 1], ep.max(), int((ep > 1e-6).sum())))
    if png:
        plot(case, lat, ts, rows, a, qC, png, flow, piezo, sand)


def soil(case, ts):
    """The material points at the start and the last time (Allrun -soil):
    start positions, positions, stress, plastic strain; None without them"""
    if not os.path.isdir(os.path.join(case, ts[-1], 'lagrangian', 'materialPoints')):
        return None
    return (foamio.read_cloud(case, ts[0], 'x'), foamio.read_cloud(case, ts[-1], 'x'),
            foamio.read_cloud(case, ts[-1], 'stress'),
            foamio.read_cloud(case, ts[-1], 'plasticStrain'))


def plot(case, lat, ts, rows, a, qC, png, flow, piezo, sand=None):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    x, y = lat.axis(0), lat.axis(1)
    dx = lat.dx
    U = np.asarray(foamio.read(case, ts[-1], 'U'))
    Ux = lat.grid(U[:, 0])[:, :, 0]
    Uy = lat.grid(U[:, 1])[:, :, 0]
    if sand is None:
        fig, (ax, bx, cx) = plt.subplots(3, 1, figsize=(9, 10.2),
                                         gridspec_kw={'height_ratios': [1.25, 1, 1]})
    else:
        fig, (ax, sx, bx, cx) = plt.subplots(
            4, 1, figsize=(9, 13.6), gridspec_kw={'height_ratios': [1.25, 1.25, 1, 1]})
    edges_x = np.append(x - 0.5 * dx, x[-1] + 0.5 * dx)
    edges_y = np.append(y - 0.5 * dx, y[-1] + 0.5 * dx)
    from matplotlib.colors import LinearSegmentedColormap
    water = LinearSegmentedColormap.from_list('water', ['white', '#5b9bd5'])
    m = ax.pcolormesh(edges_x, edges_y, a.T, cmap=water, vmin=0, vmax=1,
                      shading='flat')
    ax.plot([TOE_UP, CREST_UP, CREST_DOWN, TOE_DOWN],
            [0, HEIGHT, HEIGHT, 0], color='saddlebrown', lw=2,
            label='embankment (K = %g m2, n = 0.35)' % K)
    ax.contour(x, y, a.T, levels=[0.5], colors='k', linewidths=1.2)
    ax.plot([], [], 'k', lw=1.2, label='water surface, phreatic line (alpha.water = 0.5)')
    X, Y = np.meshgrid(x, y, indexing='ij')
    sel = inside(X, Y) & (a >= 1)
    s = (slice(2, None, 5), slice(2, None, 5))
    k = K * G / NU
    ax.quiver(X[s][sel[s]], Y[s][sel[s]], Ux[s][sel[s]] / k, Uy[s][sel[s]] / k,
              color='darkred', scale=4, width=0.0025,
              label='Darcy velocity (u/k; scale: 1 = 0.25 m)')
    for xs in SECTIONS:
        ax.axvline(xs, color='0.5', lw=0.6, ls=':')
    ax.set_xlim(edges_x[0], edges_x[-1])
    ax.set_ylim(edges_y[0], edges_y[-1])
    ax.set_aspect('equal')
    ax.set_xlabel('x [m]')
    ax.set_ylabel('y [m]')
    ax.set_title('Seepage through a sand embankment at t = %g s' % float(ts[-1]))
    ax.legend(loc='upper right', fontsize=7)
    fig.colorbar(m, ax=ax, label='alpha.water', shrink=0.7, ticks=[0, 0.5, 1])
    if sand is not None:
        X0, Xs, st, ep = sand
        sc = sx.scatter(Xs[:, 0], Xs[:, 1], c=-st[:, 3] / 1e3, s=3, cmap='viridis',
                        vmin=0, linewidths=0)
        sx.contour(x, y, a.T, levels=[0.5], colors='k', linewidths=1.2)
        sx.plot([], [], 'k', lw=1.2, label='water surface, phreatic line')
        sx.set_xlim(edges_x[0], edges_x[-1])
        sx.set_ylim(edges_y[0], edges_y[-1])
        sx.set_aspect('equal')
        sx.set_xlabel('x [m]')
        sx.set_ylabel('y [m]')
        sx.set_title("The sand's material points: vertical effective stress at t = %g s"
                     % float(ts[-1]))
        sx.legend(loc='upper right', fontsize=7)
        fig.colorbar(sc, ax=sx, label="-sigma'_yy [kPa]", shrink=0.7)
    t = np.array([r[0] for r in rows])
    q = np.array([r[1] for r in rows])
    for i, xs in enumerate(SECTIONS):
        bx.plot(t, q[:, i], 'o-', ms=3, label='section x = %g m' % xs)
    if len(flow):
        bx.plot(flow[:, 0], flow[:, 1], '-', color='tab:blue', lw=1,
                label='flow meter: in through the reservoir\'s floor')
        bx.plot(flow[:, 0], flow[:, 2], '-', color='tab:red', lw=1,
                label='flow meter: out through the tailwater\'s floor')
    bx.axhline(qC, color='k', ls='--',
               label='Casagrande (1937) for the settled level: %.4f m' % qC)
    bx.set_xlabel('t [s]')
    bx.set_ylabel('q/k [m]')
    bx.set_ylim(0, 2.5 * qC)
    bx.set_title('Discharge per unit width over the conductivity')
    bx.legend(fontsize=7, ncol=2)
    bx.grid(alpha=0.3)
    colours = ('tab:blue', 'tab:orange', 'tab:green')
    for i, xs in enumerate(SECTIONS):
        if len(piezo):
            cx.plot(piezo[:, 0], piezo[:, 1 + i], '-', color=colours[i],
                    label='piezometer x = %g m, y = %g m' % (xs, PIEZOMETER_Y))
        h = a[int(np.argmin(abs(x - xs))), :].sum() * dx
        cx.axhline(h, color=colours[i], ls='--', lw=0.8)
    cx.plot([], [], 'k--', lw=0.8, label='the phreatic line\'s height there '
            'at t = %g s (Dupuit)' % float(ts[-1]))
    cx.set_xlabel('t [s]')
    cx.set_ylabel('head p/(rho g) + y [m]')
    cx.set_ylim(0, HEIGHT)
    cx.set_title('Piezometers 1 cm above the floor')
    cx.legend(fontsize=7, loc='upper right')
    cx.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == '__main__':
    main()
