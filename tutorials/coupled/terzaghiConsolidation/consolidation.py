#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     consolidation.py CASE [--png FILE]
#
# Description
#     The consolidation of the tutorial's sand layer against Terzaghi's
#     series (Terzaghi 1943, Theoretical Soil Mechanics, ch. XIII) for an
#     initial excess pore pressure u0 = gamma' z (the layer's buoyant
#     weight, z the depth below its drained surface, impermeable bottom):
#         u(z, t) = sum_m 2 gamma' H_s (-1)^m/M_m^2 sin(M_m z/H_s)
#                   exp(-M_m^2 T_v),  M_m = (2m + 1) pi/2,
#         T_v = c_v t/H_s^2,  c_v = K/(mu (n/K_f + 1/M)),
#     K from the drag law (Kozeny-Carman), M the constrained modulus and K_f
#     = rho_w c_s^2 the lattice water's bulk modulus (what the solver's log
#     states as the factor the consolidation runs slower than with water);
#     the surface's settlement w(t) = (1/M) int (gamma' z - u) dz.
#     Reads the case's dictionaries: E and nu of the sand, d and muFluid,
#     deltaT and the mesh; the layer's H_s = 1 m, n = 0.4 and rho_s =
#     2650 kg/m3 are the tutorial's (set below). Prints per written time
#     T_v, the excess pore pressure at the bottom and the settlement, each
#     against the series, and the largest pore-pressure error; with --png,
#     the isochrones u/(gamma' H_s) against z/H_s and the settlement
#     against T_v.
#------------------------------------------------------------------------------
import os
import re
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(
    os.environ.get('MPMLBM_PROJECT_DIR', os.path.join(here, '..', '..', '..')),
    'tests', 'lib'))
import foamio   # noqa: E402  (the project's reader of OpenFOAM's files)

Hs, n, rhoW, rhoS, g = 1.0, 0.4, 1000.0, 2650.0, 9.81


def entry(path, key):
    """The first number of a dictionary entry (as the case sets it)."""
    text = re.sub(r'//.*', '', open(path).read())
    m = re.search(r'\b%s\s+([-+0-9.eE]+)\s*;' % key, text)
    if not m:
        raise SystemExit('consolidation.py: no %s in %s' % (key, path))
    return float(m.group(1))


def series(z, Tv, gammaP, terms=400):
    """Terzaghi's excess pore pressure for u0 = gamma' z."""
    u = np.zeros_like(z, dtype=float)
    for m in range(terms):
        Mm = np.pi * (2 * m + 1) / 2
        u += (2 * gammaP * Hs * (-1) ** m / Mm ** 2 * np.sin(Mm * z / Hs)
              * np.exp(-Mm ** 2 * Tv))
    return u


def main():
    case = sys.argv[1] if len(sys.argv) > 1 else '.'
    png = sys.argv[sys.argv.index('--png') + 1] if '--png' in sys.argv else None
    sand = re.search(r'sand\s*\{([^}]*)\}',
                     open(os.path.join(case, 'constant', 'soilProperties')).read()).group(1)
    E = float(re.search(r'\bE\s+([-+0-9.eE]+)', sand).group(1))
    nu = float(re.search(r'\bnu\s+([-+0-9.eE]+)', sand).group(1))
    d = entry(os.path.join(case, 'constant', 'dragProperties'), 'd')
    mu = entry(os.path.join(case, 'constant', 'dragProperties'), 'muFluid')
    dt = entry(os.path.join(case, 'system', 'controlDict'), 'deltaT')

    C = foamio.read(case, '0', 'C')
    lat = foamio.Lattice(C)
    dx = lat.dx
    y = lat.axis(1)
    H = y.max() + 0.5 * dx
    gammaP = (1 - n) * (rhoS - rhoW) * g
    M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    Kf = rhoW * (dx / dt) ** 2 / 3
    K = d ** 2 * n ** 3 / (180 * (1 - n) ** 2)
    cv = K / (mu * (n / Kf + 1 / M))
    print('c_v = K/(mu (n/K_f + 1/M)) = %.4g m2/s (K %.3g m2, M %.4g Pa, K_f %.3g Pa);'
          ' T_v = 1 at %.3g s' % (cv, K, M, Kf, Hs ** 2 / cv))

    soil = y < Hs
    z = Hs - y[soil]
    x0 = foamio.read_cloud(case, '0', 'x')
    top = x0[:, 1] > Hs - dx / 2
    z0 = Hs - x0[top, 1].mean()
    zz = np.linspace(z0, Hs, 4001)

    rows = []
    print('%8s %7s %14s %14s %14s %14s' % ('t [s]', 'T_v', 'u bottom [Pa]', 'series',
                                            'settlement [m]', 'series'))
    for t in foamio.times(case):
        Tv = cv * float(t) / Hs ** 2
        p = lat.grid(foamio.read(case, t, 'p'))[:, :, 0].mean(axis=0)
        u = (p - rhoW * g * (H - y))[soil]
        x = np.atleast_2d(foamio.read_cloud(case, t, 'x'))
        w = -(x[top, 1] - x0[top, 1]).mean()
        wS = np.trapz(gammaP * zz - series(zz, Tv, gammaP), zz) / M
        rows.append((float(t), Tv, u, w, wS))
        print('%8s %7.3f %14.1f %14.1f %14.4e %14.4e'
              % (t, Tv, u[0], series(z[:1], Tv, gammaP)[0], w, wS))
    late = [r for r in rows if r[1] >= 0.04]
    if late:
        err = max(np.abs(r[2] - series(z, r[1], gammaP)).max() for r in late) / (gammaP * Hs)
        print('largest error of the excess pore pressure (T_v >= 0.04): %.4f of gamma\' H_s'
              % err)

    if not png:
        return
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.8))
    zs = np.linspace(0, Hs, 200)
    wanted = [0.02, 0.05, 0.1, 0.2, 0.4, 0.7, 1.0]
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(wanted)))
    for Tw, col in zip(wanted, colours):
        r = min(rows, key=lambda r: abs(r[1] - Tw))
        if abs(r[1] - Tw) > 0.3 * Tw:
            continue
        a1.plot(r[2] / (gammaP * Hs), z / Hs, 'o', ms=3, color=col)
        a1.plot(series(zs, r[1], gammaP) / (gammaP * Hs), zs / Hs, '-', color=col,
                label='T_v = %.2f' % r[1])
    a1.plot(zs / Hs, zs / Hs, 'k:', lw=0.8, label='start: gamma\' z')
    a1.set_xlabel("excess pore pressure u / (gamma' H_s)")
    a1.set_ylabel('depth z / H_s')
    a1.invert_yaxis()
    a1.set_title('isochrones: mpmLbmFoam (dots), Terzaghi (lines)')
    a1.legend(fontsize=8)
    Tv = np.array([r[1] for r in rows])
    Ts = np.linspace(0, max(Tv.max(), 1e-3), 200)
    a2.plot(Ts, [1e3 * np.trapz(gammaP * zz - series(zz, T, gammaP), zz) / M for T in Ts],
            'k-', label='Terzaghi')
    a2.plot(Tv, [1e3 * r[3] for r in rows], 'o', ms=4, label='mpmLbmFoam')
    a2.set_xlabel('T_v = c_v t / H_s^2')
    a2.set_ylabel('settlement of the surface [mm]')
    a2.set_title('c_v = %.3g m2/s (lattice water: K_f = %.3g Pa)' % (cv, Kf))
    a2.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print('wrote', png)


if __name__ == '__main__':
    main()
