#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     advectionDiffusion.py set CASE SIGMA0 X0 Y0 Z0
#     advectionDiffusion.py gauss CASE TIME D UX SIGMA0 X0 Y0 Z0
#     advectionDiffusion.py ogata CASE TIME D U
#     advectionDiffusion.py balance CASE
#
# Description
#     set: 0/s = exp(-|x - x0|^2/(2 sigma0^2)) from the cell centres 0/C
#     (postProcess -func writeCellCentres).
#     gauss: the pulse at TIME against the exact solution of
#     ds/dt + u.grad(s) = D lap(s) on the periodic unit square (cube)
#     (erosion-free-surface-outputs.md section 4, images of the periodic
#     box summed):
#         s = (sigma0^2/sigma^2)^(d/2) exp(-|x - x0 - u t|^2/(2 sigma^2)),
#         sigma^2 = sigma0^2 + 2 D t
#     Prints: the relative L2 error, the relative error of the variance's
#     growth 2 D t along each axis (largest), the centroid's offset from
#     x0 + u t in cells, the content's relative change, the smallest s.
#     ogata: the scalar entering a uniform flow U along x from a patch held
#     at s = 1 (initially 0), against Ogata & Banks (1961):
#         s = 1/2 [erfc((x - U t)/(2 sqrt(D t)))
#                  + exp(U x/D) erfc((x + U t)/(2 sqrt(D t)))]
#     Prints the largest error along the channel (section means).
#     balance: the largest |defect| of postProcessing/scalarTransport/*/
#     balance.dat.
#------------------------------------------------------------------------------
import os
import sys
import math
import glob
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests',
                                'lib'))
import foamio


def centres(case):
    return foamio.read(case, '0', 'C')


def set_pulse(case, sigma0, x0):
    c = centres(case)
    d = 3 if np.ptp(c[:, 2]) > 1e-6 * np.ptp(c[:, 0]) else 2
    r2 = ((c[:, :d] - x0[:d]) ** 2).sum(axis=1)
    s = np.exp(-r2 / (2 * sigma0 ** 2))
    path = os.path.join(case, '0', 's')
    text = open(path).read()
    head, tail = text.split('internalField', 1)
    tail = tail.split(';', 1)[1]
    body = 'internalField   nonuniform List<scalar>\n%d\n(\n%s\n)\n;' % (
        len(s), '\n'.join('%.17g' % v for v in s))
    open(path, 'w').write(head + body + tail)


def exact_pulse(c, d, t, D, u, sigma0, x0):
    s2 = sigma0 ** 2 + 2 * D * t
    centre = x0[:d] + u[:d] * t
    out = np.zeros(len(c))
    shifts = np.array(np.meshgrid(*[[-1, 0, 1]] * d)).reshape(d, -1).T
    for sh in shifts:
        r2 = ((c[:, :d] - centre - sh) ** 2).sum(axis=1)
        out += np.exp(-r2 / (2 * s2))
    return (sigma0 ** 2 / s2) ** (d / 2) * out, s2, centre


def gauss(case, time, D, ux, sigma0, x0):
    c = centres(case)
    d = 3 if np.ptp(c[:, 2]) > 1e-6 * np.ptp(c[:, 0]) else 2
    t = float(time)
    u = np.array([ux, 0, 0])
    s = foamio.read(case, time, 's')
    s0 = foamio.read(case, '0', 's')
    exact, s2, centre = exact_pulse(c, d, t, D, u, sigma0, x0)
    err = math.sqrt(((s - exact) ** 2).sum() / (exact ** 2).sum())
    # Moments about the expected centre, the periodic offset wrapped into
    # [-1/2, 1/2)
    r = c[:, :d] - centre
    r -= np.round(r)
    mass = s.sum()
    cen = (s[:, None] * r).sum(axis=0) / mass
    var = (s[:, None] * (r - cen) ** 2).sum(axis=0) / mass
    r0 = c[:, :d] - x0[:d]
    r0 -= np.round(r0)
    var0 = (s0[:, None] * r0 ** 2).sum(axis=0) / s0.sum()
    growth = var - var0
    varErr = np.abs(growth / (2 * D * t) - 1).max()
    dx = foamio.Lattice(c).dx
    print('%.6e %.6e %.6e %.6e %.6e' % (
        err, varErr, np.abs(cen).max() / dx, abs(mass / s0.sum() - 1),
        s.min()))


def ogata(case, time, D, U):
    from math import erfc
    c = centres(case)
    lat = foamio.Lattice(c)
    s = lat.grid(foamio.read(case, time, 's'))
    x = lat.axis(0) - (lat.lo[0] - lat.dx / 2)
    t = float(time)
    prof = s[:, :, 0].mean(axis=1)
    exact = np.array([0.5 * (erfc((xi - U * t) / (2 * math.sqrt(D * t)))
                             + math.exp(U * xi / D)
                             * erfc((xi + U * t) / (2 * math.sqrt(D * t))))
                      for xi in x])
    spread = np.ptp(s[:, :, 0], axis=1).max()
    print('%.6e %.6e %.6e' % (np.abs(prof - exact).max(), spread, s.min()))


def balance(case):
    worst = 0.0
    n = 0
    for path in glob.glob(os.path.join(case, 'postProcessing',
                                       'scalarTransport', '*', 'balance.dat')):
        for line in open(path):
            if line.startswith('#') or not line.strip():
                continue
            worst = max(worst, abs(float(line.split()[-1])))
            n += 1
    print('%.6e %d' % (worst, n))


if __name__ == '__main__':
    cmd, case = sys.argv[1], sys.argv[2]
    if cmd == 'set':
        set_pulse(case, float(sys.argv[3]),
                  np.array([float(v) for v in sys.argv[4:7]]))
    elif cmd == 'gauss':
        gauss(case, sys.argv[3], float(sys.argv[4]), float(sys.argv[5]),
              float(sys.argv[6]), np.array([float(v) for v in sys.argv[7:10]]))
    elif cmd == 'ogata':
        ogata(case, sys.argv[3], float(sys.argv[4]), float(sys.argv[5]))
    elif cmd == 'balance':
        balance(case)
    else:
        sys.exit('unknown command ' + cmd)
