#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     tutorials/coupled/leveeSuffusion/picture.py
#
# Description
#     The levee's foundation losing its fines, from the written fields: per
#     time (a row) the material points coloured by their porosity, the
#     suspended fines (kg per m3 of pore water) and the water's superficial
#     speed |U|, each with one colour range for all times. The nearest
#     written time is taken for each requested time. Prints the times and
#     the largest porosity, fines and speed shown.
#
# Usage
#     picture.py CASE [--times 5 7 9 12] [--png leveeSuffusion.png]
#------------------------------------------------------------------------------
import argparse
import os
import re
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(
    os.environ.get('MPMLBM_PROJECT_DIR', os.path.join(here, '..', '..', '..')),
    'tests', 'lib'))
import foamio


def main():
    p = argparse.ArgumentParser(prog='picture.py')
    p.add_argument('case')
    p.add_argument('--times', type=float, nargs='+', default=[5, 7, 9, 12])
    p.add_argument('--png', default='leveeSuffusion.png')
    args = p.parse_args()
    case = args.case

    bmd = open(os.path.join(case, 'system', 'blockMeshDict')).read()
    nx, ny, _ = map(int, re.search(
        r'hex\s*\([^)]*\)\s*\((\d+)\s+(\d+)\s+(\d+)\)', bmd).groups())
    verts = re.findall(r'\(\s*([-+0-9.eE]+)\s+([-+0-9.eE]+)\s+([-+0-9.eE]+)\s*\)',
                       re.search(r'vertices\s*\((.*?)\n\);', bmd, re.S).group(1))
    xs = [float(v[0]) for v in verts]
    ys = [float(v[1]) for v in verts]
    zs = [float(v[2]) for v in verts]
    extent = [min(xs), max(xs), min(ys), max(ys)]
    depth = max(zs) - min(zs)

    written = [t for t in foamio.times(case) if float(t) > 0]
    if not written:
        sys.exit('picture.py: no written times in %s' % case)
    chosen = []
    for t in args.times:
        near = min(written, key=lambda s: abs(float(s) - t))
        if near not in chosen:
            chosen.append(near)

    data = []
    for t in chosen:
        U = np.asarray(foamio.read(case, t, 'U')).reshape(ny, nx, 3)
        fines = np.asarray(foamio.read(case, t, 'fines')).reshape(ny, nx)
        x = np.asarray(foamio.read_cloud(case, t, 'x')).reshape(-1, 3)
        n = np.asarray(foamio.read_cloud(case, t, 'porosity'))
        # Each point drawn as a square of its own area (volume over the
        # case's depth): the soil a continuous body, not dots
        side = np.sqrt(np.asarray(foamio.read_cloud(case, t, 'volume'))/depth)
        data.append((t, np.sqrt((U**2).sum(axis=2)), fines, x, n, side))
    # The foundation's porosity from its initial value on (the levee's
    # denser points below it are grey)
    nMax = max(d[4].max() for d in data)
    nMin = 0.5*(min(d[4].min() for d in data)
                + min(np.percentile(d[4], 50) for d in data))
    cMax = max(d[2].max() for d in data) or 1.0
    uMax = max(d[1].max() for d in data) or 1.0
    print('picture.py: times %s; porosity %.4g to %.4g, fines up to %.4g '
          'kg/m3, |U| up to %.4g m/s' % (' '.join(chosen), nMin, nMax, cMax,
                                          uMax))

    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    rows = len(data)
    fig, axes = plt.subplots(rows, 3, figsize=(15, 1.55*rows + 0.9),
                             squeeze=False)
    from matplotlib.collections import PolyCollection
    for r, (t, speed, fines, x, n, side) in enumerate(data):
        a = axes[r][0]
        cmap = matplotlib.cm.get_cmap('viridis').copy()
        cmap.set_under('0.6')
        h = 0.5*side[:, None]
        corners = np.stack([
            np.column_stack([x[:, 0] - h[:, 0], x[:, 1] - h[:, 0]]),
            np.column_stack([x[:, 0] + h[:, 0], x[:, 1] - h[:, 0]]),
            np.column_stack([x[:, 0] + h[:, 0], x[:, 1] + h[:, 0]]),
            np.column_stack([x[:, 0] - h[:, 0], x[:, 1] + h[:, 0]])], axis=1)
        sc = PolyCollection(corners, array=n, cmap=cmap, linewidths=0,
                            edgecolors='face')
        sc.set_clim(nMin, max(nMax, nMin*1.001))
        a.add_collection(sc)
        a.set_xlim(extent[0], extent[1])
        a.set_ylim(extent[2], extent[3])
        a.set_facecolor('#dbe9f6')
        im1 = axes[r][1].imshow(fines, origin='lower', extent=extent,
                                cmap='YlOrBr', vmin=0, vmax=cMax)
        im2 = axes[r][2].imshow(speed, origin='lower', extent=extent,
                                cmap='turbo', vmin=0, vmax=uMax)
        for c, a in enumerate(axes[r]):
            a.set_aspect('equal')
            a.tick_params(labelsize=7)
            if r < rows - 1:
                a.set_xticklabels([])
        axes[r][0].set_ylabel('t = %s s\ny [m]' % t, fontsize=9)
    for c, (mappable, title) in enumerate((
            (sc, 'soil: porosity of its points [-] (grey: the levee, denser)'),
            (im1, 'suspended fines [kg/m3 of pore water]'),
            (im2, 'water: |U| (superficial) [m/s]'))):
        axes[0][c].set_title(title, fontsize=10)
        fig.colorbar(mappable, ax=[axes[r][c] for r in range(rows)],
                     shrink=0.9, pad=0.01)
    for a in axes[-1]:
        a.set_xlabel('x [m]', fontsize=9)
    fig.suptitle('A levee on a foundation losing its fines (suffusion): '
                 'seepage from left to right', fontsize=11)
    fig.savefig(args.png, dpi=100)
    print('picture.py: %s' % args.png)


main()
