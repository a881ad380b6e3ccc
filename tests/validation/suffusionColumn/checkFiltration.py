#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkFiltration.py CASE T0 LAMBDA CIN FMAX clean|clogging
#
# Description
#     Deep-bed filtration in the suffusion column (filtrationLaw deepBed:
#     m_dot = lambda |q| C (1 - f/f_max), Iwasaki 1937, Herzig et al.
#     1970) fed with water carrying C_in [kg/m3] from T0 on.
#     clean: a clean bed (no fines, nothing erodes) and a dilute inflow,
#     so the blocking stays below 1e-3 and lambda is the clean bed's.
#     The steady concentration in the pores solves
#         q C' = n D C'' - lambda q C,  C(0) = C_in, C'(L) = 0
#     (the inlet's value at its face, no gradient at the outlet's), so
#         C = A exp(-r1 z) + B exp(-r2 z),  n D r^2 + q r - lambda q = 0,
#     with the Darcy flux q the run's own. Checks, at the last write time:
#     - C at every node within 2% of C_in of that solution;
#     - the rate the points catch (the balance's filtered over the last
#       second) within 2% of lambda q A times C's integral;
#     - the points' fines mass and the rise of their grains' volume
#       (1 - n) V (times rho_s) both equal to the filtered mass within
#       1e-9;
#     - the balance (suspended + out + filtered = suspended at T0) to
#       1e-12 at every step.
#     clogging: a concentrated inflow fills the pores near the inlet:
#     - no point's fines content above f_max (1e-12);
#     - the inlet's points within 10% of f_max (the blocking approaches
#       it as 1 - exp(-t/1.7 s): 5 s);
#     - the Darcy flux falling as the pores clog (by more than 3%);
#     - the balance to 1e-12 at every step.
#     Prints PASS:/FAIL: lines.
#------------------------------------------------------------------------------
import os
import sys
import glob
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests',
                                'lib'))
import foamio

case, t0, lam, cIn, fMax, mode = (sys.argv[1], float(sys.argv[2]),
                                  float(sys.argv[3]), float(sys.argv[4]),
                                  float(sys.argv[5]), sys.argv[6])

# The case's parameters (constant/*Properties, setMaterialPointsDict, mesh)
L, A = 0.64, 0.04 * 0.01
rhoS, D, n0 = 2650.0, 0.01, 0.4

rows = []
for path in sorted(glob.glob(os.path.join(case, 'postProcessing', 'erosion',
                                          '*', 'erosion*.dat'))):
    for line in open(path):
        if line.startswith('#') or not line.strip():
            continue
        rows.append([float(v) for v in line.split()])
t, er, filt, sus, out, defect = np.array(rows).T
ok = True
tag = 'filtration (%s bed)' % mode

lat = foamio.Lattice(foamio.read(case, '0', 'C'))
x = lat.axis(0)
mid = (x > 0.1 * L) & (x < 0.9 * L)
writeTimes = [tt for tt in foamio.times(case) if float(tt) > t0 + 1e-9]


def darcy(tt):
    U = np.atleast_2d(lat.grid(foamio.read(case, tt, 'U')))[:, :, 0]
    return U[mid, :, 0].mean()


last = writeTimes[-1]
if mode == 'clean':
    q = darcy(last)
    a = n0 * D
    r1 = (-q + np.sqrt(q * q + 4 * a * lam * q)) / (2 * a)
    r2 = (-q - np.sqrt(q * q + 4 * a * lam * q)) / (2 * a)
    # A + B = cIn; r1 A exp(-r1 L) + r2 B exp(-r2 L) = 0
    e1, e2 = np.exp(-r1 * L), np.exp(-r2 * L)
    B = -cIn * r1 * e1 / (r2 * e2 - r1 * e1)
    Acoef = cIn - B

    def exact(z):
        return Acoef * np.exp(-r1 * z) + B * np.exp(-r2 * z)

    C = np.atleast_2d(lat.grid(foamio.read(case, last, 'fines')))[:, :, 0]
    err = np.abs(C - exact(x)[:, None]).max() / cIn
    print('  q %.5g m/s, r1 %.4f 1/m (lambda %g), C at the outlet %.4g'
          ' (exact %.4g) kg/m3' % (q, r1, lam, C[-1].mean(), exact(L)))
    ok &= foamio.check(err < 0.02, '%s: C along the column within 2%% of'
                       ' C_in of the steady solution with diffusion' % tag,
                       '%.4f' % err)
    # The catching rate over the last second against lambda q A int C
    zf = np.linspace(0, L, 20001)
    Ce = exact(zf)
    integral = np.sum(0.5 * (Ce[1:] + Ce[:-1]) * np.diff(zf))
    t1 = float(last)
    rate = (filt[-1] - np.interp(t1 - 1, t, filt)) / (t[-1] - (t1 - 1))
    rateRef = lam * q * A * integral
    ok &= foamio.check(abs(rate / rateRef - 1) < 0.02, '%s: the points'
                       ' catch lambda q A int(C) within 2%%' % tag,
                       '%.5g against %.5g kg/s (%.4f)'
                       % (rate, rateRef, rate / rateRef - 1))
    # The points: fines mass and porosity against the filtered mass
    m = foamio.read_cloud(case, last, 'mass')
    f = foamio.read_cloud(case, last, 'fines')
    first = '%.12g' % t0

    def solid(tt):
        # The grains' volume (1 - n) V: kept as a point deforms (the
        # grains are incompressible), raised only by what it catches
        return ((1 - foamio.read_cloud(case, tt, 'porosity'))
                * foamio.read_cloud(case, tt, 'volume')).sum()

    caught = filt[-1]
    dFines = abs((f * m).sum() / caught - 1)
    dPores = abs((solid(last) - solid(first)) * rhoS / caught - 1)
    ok &= foamio.check(max(dFines, dPores) < 1e-9, '%s: the points\' fines'
                       ' and their pores\' loss x rho_s equal the filtered'
                       ' mass' % tag, '%.2e, %.2e of %.5g kg'
                       % (dFines, dPores, caught))
else:
    f = foamio.read_cloud(case, last, 'fines')
    ok &= foamio.check(f.max() <= fMax * (1 + 1e-12), '%s: no point\'s'
                       ' fines content above maxFinesContent %g' % (tag, fMax),
                       'max %.15g' % f.max())
    # The points of the first cell column (the cloud's origId follows
    # setMaterialPoints' order: x fastest? use the largest instead)
    top = np.sort(f)[-4:]
    ok &= foamio.check(top.min() > 0.9 * fMax, '%s: the most filled points'
                       ' (the inlet\'s 4) within 10%% of maxFinesContent'
                       ' (approached as 1 - exp(-t/1.7 s))' % tag,
                       '%.4f of %g' % (top.min(), fMax))
    q0, q1 = darcy(writeTimes[0]), darcy(last)
    ok &= foamio.check(q1 < 0.97 * q0, '%s: the Darcy flux falls as the'
                       ' pores clog' % tag, '%.5g to %.5g m/s (%.1f%%)'
                       % (q0, q1, 100 * (q1 / q0 - 1)))

ok &= foamio.check(np.abs(defect).max() < 1e-12, '%s: balance (suspended'
                   ' + out + filtered = suspended at the start) to 1e-12 at'
                   ' every step' % tag, '%.2e over %d steps, filtered %.5g kg'
                   % (np.abs(defect).max(), len(t), filt[-1]))
sys.exit(0 if ok else 1)
