#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     checkSuffusion.py CASE T0 LAMBDA
#
# Description
#     The suffusion column against an independent 1D solution of the same
#     equations, written here and resolved finely (256 cells, a quarter of
#     the lattice's step), per unit volume of the mixture:
#         solid M, fines F, porosity n, suspended Phi = n C:
#         m_dot = rho_s lambda (1 - n) max(C/rho_s, c_seed) q
#                 where F/M > f_lim and i = q mu/(k rho_w g) > i_c
#                 (at most what takes F/M to f_lim in a step),
#         dM/dt = dF/dt = -m_dot,  dn/dt = m_dot/rho_s,
#         dPhi/dt + d(C q)/dz = D d2Phi/dz2 + m_dot,
#         dq/dt integral(dz/n) = dp/rho_w - q integral(mu/(rho_w k) dz)
#         (Darcy through the column in series with the water's inertia,
#         Guo & Zhao's momentum integrated along it; Kozeny-Carman
#         k = d^2 n^3/(180 (1 - n)^2)),
#     C = 0 at the inlet (at the face), no diffusive flux at the outlet.
#     Central differences (cell Peclet 0.03), explicit steps.
#     The erosion starts at T0, the seepage established (the lattice's
#     water takes about 0.1 s to reach Darcy's flux from rest: the drag's
#     relaxation rho k/(n mu) = 80 ms and the lattice's sound crossing the
#     column), and runs 10 s.
#     Compares with postProcessing/erosion/*/erosion.dat and U:
#     - the eroded mass at T0 + 1 to 10 s within 3% of the 1D solution's
#       (where it exceeds 1% of the erodible fines);
#     - the mass out through the patches (the outlet, and back through
#       the clear-water inlet by diffusion) within 3% (where it exceeds
#       1%);
#     - the Darcy flux at the write times within 3%, and rising as the
#       permeability does (the last above 1.5 times the first);
#     - the balance: defect below 1e-12 at every step.
#     Prints PASS:/FAIL: lines.
#------------------------------------------------------------------------------
import os
import sys
import glob
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests',
                                'lib'))
import foamio

case = sys.argv[1]
t0, lam = float(sys.argv[2]), float(sys.argv[3])

# The case's parameters (constant/*Properties, 0/p, the mesh)
L, A = 0.64, 0.04 * 0.01
dp, mu, rhoW, g = 1000.0, 1e-3, 1000.0, 9.81
d = 5.7e-3
rhoS, iC, cSeed, D = 2650.0, 0.1, 1e-3, 0.01
n0, rhoDry, f0, fLim = 0.4, 1590.0, 0.2, 0.05


def k_of(n):
    return d * d * n ** 3 / (180 * (1 - n) ** 2)


def reference(times, N=256, dt=2.5e-4):
    """Eroded, out and q at the given times after the start of erosion."""
    dz = L / N
    n = np.full(N, n0)
    M = np.full(N, rhoDry)
    F = f0 * M
    Phi = np.zeros(N)
    eroded, out = 0.0, 0.0
    res = {}
    t = 0.0
    targets = sorted(times)
    k = 0
    q = dp / np.sum(mu / k_of(n) * dz)
    while k < len(targets):
        # The pore water's inertia (Guo & Zhao's momentum integrated over
        # the column): (1/n) dq/dt = -dp/dz/rho - (mu/(rho k)) q
        R = np.sum(mu / (rhoW * k_of(n)) * dz)
        q += dt * (dp / rhoW - q * R) / np.sum(dz / n)
        i = q * mu / (k_of(n) * rhoW * g)
        C = Phi / n
        excess = F / M - fLim
        rate = np.where((excess > 0) & (i > iC),
                        rhoS * lam * (1 - n) * np.maximum(C / rhoS, cSeed)
                        * q, 0.0)
        dm = np.minimum(rate * dt, np.maximum(M * excess / (1 - fLim), 0))
        M -= dm
        F -= dm
        n += dm / rhoS
        Phi += dm
        eroded += dm.sum() * dz * A
        # Transport of Phi (fluxes positive along z)
        C = Phi / n
        flux = np.empty(N + 1)
        flux[0] = -D * Phi[0] / (dz / 2)                      # C = 0 at inlet
        flux[1:N] = q * 0.5 * (C[:-1] + C[1:]) - D * np.diff(Phi) / dz
        flux[N] = q * C[-1]
        Phi -= dt / dz * np.diff(flux)
        out += (flux[N] - flux[0]) * dt * A     # out through both ends
        t += dt
        while k < len(targets) and t >= targets[k] - 0.5 * dt:
            res[targets[k]] = (eroded, out, q)
            k += 1
    return res


# The solver's balance, every step
rows = []
for path in sorted(glob.glob(os.path.join(case, 'postProcessing', 'erosion',
                                          '*', 'erosion*.dat'))):
    for line in open(path):
        if line.startswith('#') or not line.strip():
            continue
        rows.append([float(v) for v in line.split()])
rows = np.array(rows)
t, er, sus, out, defect = rows.T

checkTimes = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 10.0]
writeTimes = [tt for tt in foamio.times(case) if float(tt) > t0 + 1e-9]
ref = reference(checkTimes + [float(tt) - t0 for tt in writeTimes])
erodible = (f0 - fLim) / (1 - fLim) * rhoDry * L * A
ok = True


def at(tt, col):
    return np.interp(t0 + tt, t, col)


worstE, worstO = 0.0, 0.0
for tt in checkTimes:
    e, o, _ = ref[tt]
    if e > 0.01 * erodible:
        worstE = max(worstE, abs(at(tt, er) / e - 1))
    if o > 0.01 * erodible:
        worstO = max(worstO, abs(at(tt, out) / o - 1))
    print('  erosion + %4.1f s: eroded %.5g kg (1D %.5g), out %.5g kg'
          ' (1D %.5g)' % (tt, at(tt, er), e, at(tt, out), o))
ok &= foamio.check(worstE < 0.03, 'suffusion column: eroded mass within 3%'
                   ' of the 1D solution over 10 s', '%.4f' % worstE)
ok &= foamio.check(worstO < 0.03, 'suffusion column: mass out within 3% of'
                   ' the 1D solution over 10 s', '%.4f' % worstO)

lat = foamio.Lattice(foamio.read(case, '0', 'C'))
qs, worstQ = [], 0.0
for tt in writeTimes:
    U = np.atleast_2d(lat.grid(foamio.read(case, tt, 'U')))[:, :, 0]
    x = lat.axis(0)
    mid = (x > 0.1 * L) & (x < 0.9 * L)
    q = U[mid, :, 0].mean()
    qs.append(q)
    qRef = ref[float(tt) - t0][2]
    worstQ = max(worstQ, abs(q / qRef - 1))
    print('  t = %s s: Darcy flux %.5g m/s (1D %.5g)' % (tt, q, qRef))
ok &= foamio.check(worstQ < 0.03, 'suffusion column: Darcy flux within 3%'
                   ' of the 1D solution at every write time', '%.4f' % worstQ)
ok &= foamio.check(qs[-1] > 1.5 * qs[0], 'suffusion column: the flux rises'
                   ' as the permeability does', '%.4g to %.4g m/s'
                   % (qs[0], qs[-1]))
ok &= foamio.check(np.abs(defect).max() < 1e-12, 'suffusion column: balance'
                   ' (eroded = suspended + out) to 1e-12 at every step',
                   '%.2e over %d steps' % (np.abs(defect).max(), len(t)))
sys.exit(0 if ok else 1)
