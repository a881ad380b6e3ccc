#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     runout.py [CASE ...] [--times T ...]
#
# Description
#     What the flagship's README tables report, read from the written times
#     of each case (reconstructed, if run in parallel): the soil's front
#     (the largest x of its points) and top (the largest y), the front's
#     speed since the time before, the fastest soil point and the fastest
#     water (cell) speed. One Markdown table per case, on the terminal:
#
#         ./runout.py . --times 3 6
#         ./runout.py run2d run3d        # two cases side by side in time
#------------------------------------------------------------------------------
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get('MPMLBM_PROJECT_DIR', '../../..'),
                                'tests', 'lib'))
import foamio   # noqa: E402  (the project's reader of OpenFOAM's files)


def summary(case, wanted):
    times = foamio.times(case)
    rows, last = [], None
    for t in times:
        x = foamio.read_cloud(case, t, 'x')
        front = x[:, 0].max()
        speed = (front - last[1])/(float(t) - last[0]) if last else float('nan')
        last = (float(t), front)
        if wanted and not any(abs(float(t) - w) < 1e-9 for w in wanted):
            continue
        Us = np.atleast_2d(foamio.read_cloud(case, t, 'U'))
        # (a uniform field, e.g. U at 0, is one vector)
        Uw = np.atleast_2d(foamio.read(case, t, 'U'))
        rows.append((t, front, speed, x[:, 1].max(),
                     np.sqrt((Us**2).sum(axis=1)).max(),
                     np.sqrt((Uw**2).sum(axis=1)).max()))
    return rows


def main():
    p = argparse.ArgumentParser(prog='runout.py')
    p.add_argument('cases', nargs='*', default=['.'])
    p.add_argument('--times', type=float, nargs='+', default=[])
    args = p.parse_args()
    for case in args.cases:
        print('%s\n' % case)
        print('| t | soil front | front speed | soil top | fastest soil point'
              ' | fastest water |')
        print('|---|---|---|---|---|---|')
        for t, front, speed, top, us, uw in summary(case, args.times):
            print('| %s s | %.1f m | %s | %.1f m | %.1f m/s | %.1f m/s |'
                  % (t, front, '-' if speed != speed else '%.1f m/s' % speed,
                     top, us, uw))
        print()


if __name__ == '__main__':
    main()
