#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     convergence.py CASE ... [--csv FILE] [--png FILE] [--times T ...]
#     convergence.py --from-csv FILE [--png FILE]
#
# Description
#     The flagship's run-out against the cell size and the soil's CFL
#     number, from finished runs of the case (each run a case directory,
#     reconstructed if it ran in parallel; Allconvergence makes them).
#
#     Per run: dx (system/blockMeshDict), soilCFL (system/controlDict), the
#     run-out R(t) = the front's advance from the points' initial face (the
#     largest x of the points) at every written time, the front speed over
#     the last written interval before each reported time, and the
#     solver's wall time (log.mpmLbmFoam).
#
#     Printed (Markdown): the table of run-outs and front speeds, and per
#     reported time, from each three successive cell sizes at the default
#     soilCFL (0.5), the observed order
#         p = ln((R3 - R2)/(R2 - R1))/ln(r)         (r the refinement ratio)
#     the Richardson-extrapolated value R1 + (R1 - R2)/(r^p - 1) and
#     Roache's grid convergence index GCI = 1.25 |R1 - R2|/(|R1| (r^p - 1))
#     (Roache 1994, J. Fluids Eng. 116; a safety factor of 1.25 for a three-
#     grid study). Orders that the differences do not allow (of different
#     signs) are said to be so, not computed. The cell sizes whose run-out
#     is within 5% of the best estimate are listed: the extrapolated value
#     of the finest three grids when their order is trustworthy (0.5 to
#     4), else the finest run.
#
#     Written: FILE.csv (one row per run and time: dx, soilCFL, time,
#     run-out, front speed, wall time) and a picture FILE.png: run-out
#     against time per dx; run-out at the reported times against dx (with
#     the extrapolated value and its GCI band); front speed against dx;
#     run-out against soilCFL per dx.
#------------------------------------------------------------------------------
import argparse
import csv
import math
import os
import re
import sys

import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt   # noqa: E402
from matplotlib.ticker import FixedLocator, FormatStrFormatter, NullLocator  # noqa: E402

sys.path.insert(0, os.path.join(os.environ.get('MPMLBM_PROJECT_DIR', '../../..'),
                                'tests', 'lib'))
import foamio   # noqa: E402  (the project's reader of OpenFOAM's files)

DEFAULT_CFL = 0.5


def entry(path, key):
    """A plain scalar entry of an OpenFOAM dictionary (first match)."""
    with open(path) as f:
        text = foamio._strip_comments(f.read())
    m = re.search(r'(?m)^\s*%s\s+([-+0-9.eE]+)\s*;' % re.escape(key), text)
    if not m:
        sys.exit('convergence.py: no "%s" in %s' % (key, path))
    return float(m.group(1))


def wall_time(case):
    log = os.path.join(case, 'log.mpmLbmFoam')
    if not os.path.isfile(log):
        return float('nan')
    with open(log) as f:
        m = re.findall(r'^\s*wall time\s+([0-9.eE+-]+) s', f.read(), re.M)
    return float(m[-1]) if m else float('nan')


def read_run(case):
    dx = entry(os.path.join(case, 'system', 'blockMeshDict'), 'dx')
    cfl = entry(os.path.join(case, 'system', 'controlDict'), 'soilCFL')
    times = foamio.times(case)
    if not times or float(times[0]) != 0:
        sys.exit('convergence.py: %s has no written time 0' % case)
    x0 = foamio.read_cloud(case, times[0], 'x')[:, 0].max()
    rows, last = [], None
    for t in times:
        front = foamio.read_cloud(case, t, 'x')[:, 0].max()
        speed = ((front - last[1])/(float(t) - last[0])
                 if last else float('nan'))
        last = (float(t), front)
        rows.append(dict(case=os.path.basename(os.path.normpath(case)), dx=dx, CFL=cfl, time=float(t),
                         runout=front - x0, speed=speed,
                         wall=wall_time(case)))
    return rows


def at(rows, dx, cfl, t):
    for r in rows:
        if (abs(r['dx'] - dx) < 1e-12 and abs(r['CFL'] - cfl) < 1e-12
                and abs(r['time'] - t) < 1e-9):
            return r
    return None


def richardson(fine, mid, coarse, ratio):
    """(order, extrapolated, GCI) of three values on grids refined by
    ratio, fine first; order None when the differences change sign or
    vanish."""
    e21, e32 = fine - mid, mid - coarse
    if e21 == 0 or e32 == 0 or (e21 > 0) != (e32 > 0):
        return None, None, None
    p = math.log(e32/e21)/math.log(ratio)
    if p <= 0:
        return p, None, None
    ext = fine + e21/(ratio**p - 1)
    gci = 1.25*abs(e21)/(abs(fine)*(ratio**p - 1))
    return p, ext, gci


def report(rows, times):
    dxs = sorted({r['dx'] for r in rows}, reverse=True)
    cfls = sorted({r['CFL'] for r in rows}, reverse=True)
    print('| dx | soilCFL | ' + ' | '.join('run-out %g s | front speed %g s'
                                          % (t, t) for t in times)
          + ' | solver wall time |')
    print('|---|---|' + '---|---|'*len(times) + '---|')
    for dx in dxs:
        for c in cfls:
            got = [at(rows, dx, c, t) for t in times]
            if not any(got):
                continue
            cells = []
            for g in got:
                cells += (['-', '-'] if g is None else
                          ['%.2f m' % g['runout'], '%.2f m/s' % g['speed']])
            wall = next(g['wall'] for g in got if g)
            print('| %g m | %g | %s | %s |' % (
                dx, c, ' | '.join(cells),
                '-' if wall != wall else '%.0f s' % wall))
    print()
    estimates = {}
    base = [dx for dx in dxs if any(at(rows, dx, DEFAULT_CFL, t)
                                    for t in times)]
    for t in times:
        series = [(dx, at(rows, dx, DEFAULT_CFL, t)) for dx in base]
        series = [(dx, r['runout']) for dx, r in series if r]
        print('Run-out at %g s, soilCFL %g:' % (t, DEFAULT_CFL))
        best = None
        for i in range(len(series) - 2):
            (d3, r3), (d2, r2), (d1, r1) = series[i:i + 3]
            ratio = d2/d1
            if abs(d3/d2 - ratio) > 1e-9:
                print('- dx %g, %g, %g: not a constant refinement ratio'
                      % (d3, d2, d1))
                continue
            p, ext, gci = richardson(r1, r2, r3, ratio)
            if p is None:
                print('- dx %g, %g, %g: differences %+.3f, %+.3f m change '
                      'sign: no order' % (d3, d2, d1, r2 - r3, r1 - r2))
                best = None
                continue
            if ext is None:
                print('- dx %g, %g, %g: differences %+.3f, %+.3f m do not '
                      'shrink (order %.2f)' % (d3, d2, d1, r2 - r3, r1 - r2, p))
                best = None
                continue
            trusted = 0.5 <= p <= 4
            print('- dx %g, %g, %g: differences %+.3f, %+.3f m, observed '
                  'order %.2f, Richardson value %.2f m, GCI %.1f%%%s'
                  % (d3, d2, d1, r2 - r3, r1 - r2, p, ext, 100*gci,
                     '' if trusted else ' (order outside 0.5-4: not used)'))
            # (the finest three grids decide: an untrusted order there
            # leaves the finest run as the estimate)
            best = ((ext, 'Richardson value from dx %g-%g-%g' % (d3, d2, d1))
                    if trusted else None)
        if best is None and series:
            best = (series[-1][1], 'the finest run, dx %g m' % series[-1][0])
        if best:
            within = [dx for dx, r in series if abs(r/best[0] - 1) <= 0.05]
            print('- within 5%% of %.2f m (%s): dx %s'
                  % (best[0], best[1],
                     ', '.join('%g' % d for d in within) or 'none'))
            estimates[t] = best[0]
        for dx in dxs:
            pts = [(c, at(rows, dx, c, t)) for c in cfls]
            pts = [(c, r['runout']) for c, r in pts if r]
            if len(pts) > 1:
                print('- dx %g m against soilCFL: %s' % (dx, ', '.join(
                    '%g: %.2f m' % p for p in pts)))
        print()
    return estimates


def log2_axis(a, values, label):
    """A log2 x axis from coarse to fine, ticked at the values themselves."""
    a.set_xscale('log', base=2)
    a.xaxis.set_major_locator(FixedLocator(sorted(values)))
    a.xaxis.set_major_formatter(FormatStrFormatter('%g'))
    a.xaxis.set_minor_locator(NullLocator())
    a.set_xlim(max(values)*1.3, min(values)/1.3)
    a.set_xlabel(label)


def picture(rows, times, estimates, png):
    dxs = sorted({r['dx'] for r in rows}, reverse=True)
    cfls = sorted({r['CFL'] for r in rows}, reverse=True)
    fig, ax = plt.subplots(2, 2, figsize=(11, 8))
    a = ax[0][0]
    for dx in dxs:
        rs = sorted((r for r in rows if r['dx'] == dx
                     and r['CFL'] == DEFAULT_CFL), key=lambda r: r['time'])
        if rs:
            a.plot([r['time'] for r in rs], [r['runout'] for r in rs],
                   marker='o', ms=3, lw=1, label='dx %g m' % dx)
    a.set_xlabel('time [s]')
    a.set_ylabel('run-out [m]')
    a.set_title('run-out in time (soilCFL %g)' % DEFAULT_CFL, fontsize=10)
    a.legend(fontsize=8)
    a.grid(alpha=0.3)

    def against_dx(a, key, t):
        """The line of rows[key] at time t against dx (default soilCFL),
        or None without points."""
        pts = [(dx, at(rows, dx, DEFAULT_CFL, t)) for dx in dxs]
        pts = [(dx, r[key]) for dx, r in pts if r]
        if not pts:
            return None
        line, = a.plot([p[0] for p in pts], [p[1] for p in pts], marker='o',
                       label='%g s' % t)
        return line

    a = ax[0][1]
    for t in times:
        line = against_dx(a, 'runout', t)
        if line is not None and t in estimates:
            a.axhline(estimates[t], color=line.get_color(), ls='--', lw=0.8)
            a.axhspan(0.95*estimates[t], 1.05*estimates[t],
                      color=line.get_color(), alpha=0.12)
    log2_axis(a, dxs, 'dx [m]')
    a.set_ylabel('run-out [m]')
    a.set_title('run-out against dx: best estimate (dashed), +-5% (band)',
                fontsize=10)
    a.legend(fontsize=8)
    a.grid(alpha=0.3)

    a = ax[1][0]
    for t in times:
        against_dx(a, 'speed', t)
    log2_axis(a, dxs, 'dx [m]')
    a.set_ylabel('front speed [m/s]')
    a.set_title('front speed over the last written interval', fontsize=10)
    a.legend(fontsize=8)
    a.grid(alpha=0.3)

    a = ax[1][1]
    for dx in dxs:
        for t in times:
            pts = [(c, at(rows, dx, c, t)) for c in cfls]
            pts = [(c, r['runout']) for c, r in pts if r]
            if len(pts) > 1:
                a.plot([p[0] for p in pts], [p[1] for p in pts], marker='o',
                       label='dx %g m, %g s' % (dx, t))
    log2_axis(a, cfls, 'soilCFL')
    a.set_ylabel('run-out [m]')
    a.set_title('run-out against the soil\'s CFL number', fontsize=10)
    if a.lines:
        a.legend(fontsize=8)
    a.grid(alpha=0.3)
    fig.suptitle('Soil column collapse (pseudo-2D, drag oneWay, pure FLIP): '
                 'convergence', fontsize=11)
    fig.tight_layout()
    fig.savefig(png, dpi=100)
    print('Picture: %s' % png)


def main():
    p = argparse.ArgumentParser(prog='convergence.py')
    p.add_argument('cases', nargs='*')
    p.add_argument('--from-csv', help='the runs from an earlier --csv')
    p.add_argument('--csv', help='write the runs to this file')
    p.add_argument('--png', help='write the picture to this file')
    p.add_argument('--times', type=float, nargs='+', default=[3, 6])
    args = p.parse_args()
    rows = []
    if args.from_csv:
        with open(args.from_csv) as f:
            for r in csv.DictReader(f):
                rows.append({k: (v if k == 'case' else float(v))
                             for k, v in r.items()})
    for case in args.cases:
        rows += read_run(case)
    if not rows:
        p.error('no runs: give case directories or --from-csv')
    if args.csv:
        keys = ['case', 'dx', 'CFL', 'time', 'runout', 'speed', 'wall']
        with open(args.csv, 'w', newline='') as f:
            w = csv.DictWriter(f, fieldnames=keys)
            w.writeheader()
            for r in rows:
                w.writerow({k: r[k] for k in keys})
    estimates = report(rows, args.times)
    if args.png:
        picture(rows, args.times, estimates, args.png)


if __name__ == '__main__':
    main()
