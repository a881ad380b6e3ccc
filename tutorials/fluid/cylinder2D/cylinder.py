#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     cylinder.py CASE [--png FILE] [--window T]
#
# Description
#     The Schaefer & Turek 1996 benchmark 2D-1 read off a run of this case:
#     - C_D, C_L: latticeForces' coefficient.dat (C = 2 F/(rho U_mean^2 D)),
#       averaged over the last T seconds (default 1 s);
#     - Delta p = p(0.15, 0.2) - p(0.25, 0.2), the pressure at the front and
#       the back of the cylinder: the mean of the two cell rows beside
#       y = 0.2, extrapolated linearly from the two nearest water cells to
#       x = 0.15 and 0.25 (latest time; needs the cell centres C:
#       postProcess -func writeCellCentres -latestTime);
#     against the reference of Nabh 1998 as quoted by FeatFlow (C_D
#     5.57953523384, C_L 0.010618948146, Delta p 0.11752016697). Prints one
#     line "cylinder2D: Cd ... Cl ... dp ..." for scripts; --png plots C_D
#     and C_L against time with the reference values.
#     Benchmark 2D-2 (Re 100, Allrun -Re 100: the case has the probes
#     pressureProbes), over the last T seconds (default 2 s) cut to whole
#     periods of the lift:
#     - the Strouhal number St = f D/U_mean from the lift's upward zero
#       crossings, and the largest C_D and C_L;
#     - Delta p half a period after the lift's last maximum (Schaefer &
#       Turek's t0 + 1/(2f)), from the probes' p extrapolated to the
#       points as above, interpolated in time;
#     against the intervals Schaefer & Turek 1996 (their table 4) give
#     (C_D,max 3.22-3.24, C_L,max 0.99-1.01, St 0.295-0.305, Delta p
#     2.46-2.50). Prints "cylinder2D-2: St ... Cdmax ... Clmax ... dp ...".
#------------------------------------------------------------------------------
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

CD, CL, DP = 5.57953523384, 0.010618948146, 0.11752016697

case = sys.argv[1]
png = sys.argv[sys.argv.index('--png') + 1] if '--png' in sys.argv else None
window = float(sys.argv[sys.argv.index('--window') + 1]) if '--window' in sys.argv else None

root = os.path.join(case, 'postProcessing', 'cylinderForces')
start = sorted(os.listdir(root), key=float)[0]
coeff = np.loadtxt(os.path.join(root, start, 'coefficient.dat'), comments='#', ndmin=2)
t, cd, cl = coeff[:, 0], coeff[:, 1], coeff[:, 2]

# Schaefer & Turek 1996, table 4: the intervals of benchmark 2D-2
RANGES = {'St': (0.295, 0.305), 'Cdmax': (3.22, 3.24), 'Clmax': (0.99, 1.01),
          'dp': (2.46, 2.50)}


def peak(tt, y):
    """The largest sample of y refined by the parabola through it and its
    neighbours: (time, value)"""
    i = int(np.clip(np.argmax(y), 1, len(y) - 2))
    y0, y1, y2 = y[i - 1], y[i], y[i + 1]
    den = y0 - 2 * y1 + y2
    d = 0.5 * (y0 - y2) / den if den < 0 else 0.0
    h = tt[i + 1] - tt[i]
    return tt[i] + d * h, y1 - 0.25 * (y0 - y2) * d


def probes_p(case):
    """The probes' times, locations and p (postProcessing/pressureProbes)"""
    root = os.path.join(case, 'postProcessing', 'pressureProbes')
    start = sorted(os.listdir(root), key=float)[0]
    path = os.path.join(root, start, 'p')
    loc = []
    for line in open(path):
        if line.startswith('# Probe'):
            xyz = line[line.index('(') + 1:line.index(')')].split()
            loc.append([float(v) for v in xyz])
        elif not line.startswith('#'):
            break
    data = np.loadtxt(path, comments='#', ndmin=2)
    return data[:, 0], np.array(loc), data[:, 1:]


def at_point(loc, p, xw, yw):
    """p at (xw, yw) from the probes of one side: linear extrapolation in x
    along each of the two rows, then linear in y between them"""
    rows = np.unique(np.round(loc[:, 1], 10))
    vals = []
    for y in rows:
        r = np.nonzero(np.abs(loc[:, 1] - y) < 1e-9)[0]
        r = r[np.argsort(np.abs(loc[r, 0] - xw))]
        (x1, x2), (p1, p2) = loc[r[:2], 0], p[:, r[:2]].T
        vals.append(p1 + (p1 - p2) * (xw - x1) / (x1 - x2))
    (ya, yb), (va, vb) = rows, vals
    return va + (vb - va) * (yw - ya) / (yb - ya)


if os.path.isdir(os.path.join(case, 'postProcessing', 'pressureProbes')):
    window = window or 2.0
    last = t >= t[-1] - window
    up = np.nonzero((cl[:-1] < 0) & (cl[1:] >= 0) & last[:-1])[0]
    if len(up) < 3:
        raise SystemExit('cylinder.py: fewer than two periods of the lift in '
                         'the last %g s of %s: no vortex street to measure' % (window, case))
    tc = t[up] - cl[up] * (t[up + 1] - t[up]) / (cl[up + 1] - cl[up])
    period = (tc[-1] - tc[0]) / (len(tc) - 1)
    St = 0.1 / period / 1.0
    whole = (t >= tc[0]) & (t <= tc[-1])
    Cdmax = max(peak(t[whole & (t >= a) & (t < b)], cd[whole & (t >= a) & (t < b)])[1]
                for a, b in zip(tc[:-1], tc[1:]))
    # each period's lift maximum; t0 the last one half a period from the end
    tops = [peak(t[(t >= a) & (t < b)], cl[(t >= a) & (t < b)])
            for a, b in zip(tc[:-1], tc[1:])]
    Clmax = max(v for _, v in tops)
    tp, loc, pp = probes_p(case)
    t0 = max(tt for tt, _ in tops if tt + 0.5 * period <= tp[-1])
    front = loc[:, 0] < 0.2
    pf = at_point(loc[front], pp[:, front], 0.15, 0.2)
    pb = at_point(loc[~front], pp[:, ~front], 0.25, 0.2)
    dp = float(np.interp(t0 + 0.5 * period, tp, pf - pb))
    vals = {'St': St, 'Cdmax': Cdmax, 'Clmax': Clmax, 'dp': dp}

    def off(k):
        lo, hi = RANGES[k]
        v = vals[k]
        return 0.0 if lo <= v <= hi else 100 * ((v - hi) / hi if v > hi else (v - lo) / lo)
    dx = 0.1 / round(0.1 / np.diff(np.sort(np.unique(np.round(loc[:, 1], 10))))[0])
    print('cylinder2D-2: St %.5f Cdmax %.5f Clmax %.5f dp %.5f (%d periods in the '
          'last %g s; C_D %.4f to %.4f, mean %.4f; outside the 1996 intervals by '
          '%.2f%%, %.2f%%, %.2f%%, %.2f%%)'
          % (St, Cdmax, Clmax, dp, len(tc) - 1, window, cd[whole].min(),
             Cdmax, cd[whole].mean(), off('St'), off('Cdmax'), off('Clmax'), off('dp')))
    if png:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        fig, (a1, a2, a3) = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
        a1.plot(t, cd, lw=1, label='mpmLbmFoam')
        a1.axhspan(*RANGES['Cdmax'], color='k', alpha=0.2,
                   label='Schaefer & Turek 2D-2: $C_{D,max}$ 3.22-3.24')
        a1.set_ylabel('$C_D$')
        a1.set_ylim(3.0, 3.5)
        a1.legend(loc='lower right', fontsize=8)
        a2.plot(t, cl, lw=1)
        a2.axhspan(*RANGES['Clmax'], color='k', alpha=0.2, label='$C_{L,max}$ 0.99-1.01')
        a2.set_ylabel('$C_L$')
        a2.set_ylim(-1.3, 1.3)
        a2.legend(loc='lower right', fontsize=8)
        a3.plot(tp, pf - pb, lw=1)
        a3.axhspan(*RANGES['dp'], color='k', alpha=0.2,
                   label='$\\Delta p(t_0 + 1/(2f))$ 2.46-2.50')
        a3.axvline(t0 + 0.5 * period, color='k', lw=0.8, ls=':')
        a3.set_ylabel('$\\Delta p$ [Pa]')
        a3.set_ylim(1.5, 3.0)
        a3.set_xlabel('time [s]')
        a3.legend(loc='lower right', fontsize=8)
        fig.suptitle('Cylinder in a channel, Re = 100 (dx = %.4g m): St %.4f, $C_{D,max}$ %.4f, '
                     '$C_{L,max}$ %.4f, $\\Delta p$ %.3f Pa' % (dx, St, Cdmax, Clmax, dp), fontsize=9)
        fig.tight_layout()
        fig.savefig(png, dpi=110)
        print('Picture: %s' % png)
    sys.exit(0)

window = window or 1.0
last = t >= t[-1] - window
Cd, Cl = cd[last].mean(), cl[last].mean()
spread = cd[last].max() - cd[last].min()

time = foamio.latest_time(case)
C = foamio.read(case, time, 'C')
p = foamio.read(case, time, 'p')
U = foamio.read(case, time, 'U')
dx = np.min(np.diff(np.unique(np.round(C[:, 0], 12))))
row = np.abs(C[:, 1] - 0.2) < 0.6 * dx
water = np.sum(U ** 2, axis=1) > 0          # (cells inside a body: U = 0)
xs = np.unique(np.round(C[row, 0], 12))
prow = np.array([p[row & water & (np.abs(C[:, 0] - x) < 1e-9)].mean()
                 if np.any(row & water & (np.abs(C[:, 0] - x) < 1e-9)) else np.nan
                 for x in xs])


def extrapolate(xw, side):
    """p at x = xw from the two water cells beyond it on the given side"""
    ok = np.isfinite(prow) & ((xs < xw) if side < 0 else (xs > xw))
    idx = np.nonzero(ok)[0]
    i1, i2 = (idx[-1], idx[-2]) if side < 0 else (idx[0], idx[1])
    x1, x2 = xs[i1], xs[i2]
    return prow[i1] + (prow[i1] - prow[i2]) * (xw - x1) / (x1 - x2)


dp = extrapolate(0.15, -1) - extrapolate(0.25, +1)
print('cylinder2D: Cd %.6f Cl %.6f dp %.6f (last %g s: Cd spread %.2e; '
      'reference Cd %.5f Cl %.6f dp %.5f; errors %.2f%%, %.1f%%, %.2f%%)'
      % (Cd, Cl, dp, window, spread, CD, CL, DP, 100 * (Cd / CD - 1),
         100 * (Cl / CL - 1), 100 * (dp / DP - 1)))

if png:
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    a1.plot(t, cd, lw=1, label='mpmLbmFoam')
    a1.axhline(CD, color='k', ls='--', lw=1, label='Schaefer & Turek 2D-1: %.4f' % CD)
    a1.set_ylabel('$C_D$')
    a1.set_ylim(CD * 0.95, CD * 1.05)
    a1.legend(loc='upper right')
    a2.plot(t, cl, lw=1)
    a2.axhline(CL, color='k', ls='--', lw=1, label='%.5f' % CL)
    a2.set_ylabel('$C_L$')
    a2.set_ylim(-0.01, 0.04)
    a2.set_xlabel('time [s]')
    a2.legend(loc='upper right')
    fig.suptitle('Cylinder in a channel, Re = 20 (dx = %.4g m): C_D %.4f, C_L %.5f, '
                 '$\\Delta p$ %.4f Pa' % (dx, Cd, Cl, dp), fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print('Picture: %s' % png)
