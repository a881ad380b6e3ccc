#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Module
#     common (tests/stability/coupledHardCases)
#
# Description
#     What the coupled hard cases measure, from a case's log (progress
#     line at every step: progressInterval 0) and its written fields and
#     cloud files (read with tests/lib/foamio.py):
#     - ran():        the run reached End without a FATAL error, or the
#                     time and message where it stopped;
#     - nonFinite():  every value of every field and cloud file written, at
#                     every time, finite;
#     - progress():   per step: time, water mass defect, soil kinetic
#                     energy (the log's progress lines);
#     - soilMass():   the points' masses summed at every written time,
#                     their number, and their positions within a box;
#     - energies():   per written time the soil's kinetic energy, the work
#                     gravity has done on it, W_g(t) = g sum m_p (y_p(0) -
#                     y_p(t)), and the elastic energy the points started with;
#     - grainVolume(): the grains' volume sum (1 - n_p) V_p, the solid
#                     fraction the points give the nodes (incompressible
#                     grains: both fixed by the points' masses).
#------------------------------------------------------------------------------
import glob
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio  # noqa: E402


def log(case):
    path = os.path.join(case, 'log.mpmLbmFoam')
    return open(path).read() if os.path.exists(path) else ''


def ran(case):
    """(reached End, what stopped it)"""
    text = log(case)
    ok = re.search(r'^End\s*$', text, re.M) is not None and 'FATAL' not in text
    why = ''
    m = re.search(r'FOAM FATAL[^\n]*\n+([^\n]*)\n([^\n]*)\n([^\n]*)', text)
    if m:
        why = ' / '.join(s.strip() for s in m.groups())
    elif not ok:
        why = 'no End in the log'
    return ok, why


def nonFinite(case):
    """(files read, [files with a non-finite value])"""
    n, bad = 0, []
    for t in foamio.times(case):
        for path in sorted(glob.glob(os.path.join(case, t, '*'))):
            if os.path.isdir(path):
                continue
            try:
                v = foamio.read_internal_field(path)
            except ValueError:
                continue
            n += 1
            if not np.isfinite(v).all():
                bad.append(os.path.relpath(path, case))
        cloud = os.path.join(case, t, 'lagrangian', 'materialPoints')
        for path in sorted(glob.glob(os.path.join(cloud, '*'))):
            if os.path.basename(path) in ('positions', 'coordinates'):
                continue
            v = foamio.read_list(path)
            n += 1
            if not np.isfinite(v).all():
                bad.append(os.path.relpath(path, case))
    return n, bad


def progress(case):
    """Per step (from the progress lines): time, mass defect, soil kinetic
    energy [J] (nan where a line lacks it)."""
    t, d, k = [], [], []
    for line in log(case).splitlines():
        if not line.startswith('Time = ') or ' step ' not in line:
            continue
        t.append(float(line.split()[2]))
        m = re.search(r'mass defect (\S+)', line)
        d.append(float(m.group(1)) if m else np.nan)
        m = re.search(r'kinetic energy (\S+) J', line)
        k.append(float(m.group(1)) if m else np.nan)
    return np.array(t), np.array(d), np.array(k)


def waterMass(case):
    """Largest |mass defect| of the log's steps and largest relative change
    of the sum of rho over the written times (t > 0)."""
    _, d, _ = progress(case)
    times = foamio.times(case)[1:]
    s = np.array([foamio.read(case, t, 'rho').sum() for t in times])
    drift = np.abs(s / s[0] - 1).max() if s.size else np.nan
    return (np.abs(d).max() if d.size else np.nan), drift, d.size


def soilMass(case, lo, hi):
    """(largest relative change of the total mass, same number of points at
    every time, all points inside [lo, hi] (x, y) at every time, the
    extent (xmin, xmax, ymin, ymax) over all times)"""
    times = foamio.times(case)
    m0 = foamio.read_cloud(case, times[0], 'mass')
    dm, same, inside = 0.0, True, True
    ext = [np.inf, -np.inf, np.inf, -np.inf]
    for t in times:
        m = foamio.read_cloud(case, t, 'mass')
        x = foamio.read_cloud(case, t, 'x')
        same &= m.size == m0.size
        dm = max(dm, abs(m.sum() / m0.sum() - 1))
        inside &= bool(((x[:, 0] >= lo[0]) & (x[:, 0] <= hi[0])
                        & (x[:, 1] >= lo[1]) & (x[:, 1] <= hi[1])).all())
        ext = [min(ext[0], x[:, 0].min()), max(ext[1], x[:, 0].max()),
               min(ext[2], x[:, 1].min()), max(ext[3], x[:, 1].max())]
    return dm, same, inside, ext, m0.size


def elasticEnergy(case, time, E, nu):
    """Elastic energy of the points' stress [J] (isotropic, E and nu)."""
    s = foamio.read_cloud(case, time, 'stress')
    V = foamio.read_cloud(case, time, 'volume')
    xx, xy, xz, yy, yz, zz = s.T
    ss = xx**2 + yy**2 + zz**2 + 2 * (xy**2 + xz**2 + yz**2)
    tr = xx + yy + zz
    return np.sum(V * ((1 + nu) * ss - nu * tr**2) / (2 * E))


def energies(case, g, E, nu):
    """Per written time: (times, soil kinetic energy, W_g, E_el(0)); and
    g sum m_p y_p(0), the most gravity can give a soil above y = 0."""
    times = foamio.times(case)
    m0 = foamio.read_cloud(case, times[0], 'mass')
    x0 = foamio.read_cloud(case, times[0], 'x')
    ke, W = [], []
    for t in times:
        m = foamio.read_cloud(case, t, 'mass')
        x = foamio.read_cloud(case, t, 'x')
        v = foamio.read_cloud(case, t, 'U')
        ke.append(0.5 * np.sum(m * (v**2).sum(axis=1)))
        W.append(g * np.sum(m0 * x0[:, 1]) - g * np.sum(m * x[:, 1]))
    return (times, np.array(ke), np.array(W), elasticEnergy(case, times[0], E, nu),
            g * np.sum(m0 * x0[:, 1]))


def grainVolume(case):
    """Largest relative change over the written times of the grains' volume
    sum (1 - n_p) V_p, the largest point volume ratio V/V(0), the largest
    nodal solid fraction (t > 0) and the time of the largest change."""
    times = foamio.times(case)
    V0 = foamio.read_cloud(case, times[0], 'volume')
    n0 = foamio.read_cloud(case, times[0], 'porosity')
    g0 = ((1 - n0) * V0).sum()
    worst, tWorst, J, phi = 0.0, times[0], 1.0, 0.0
    for t in times:
        V = foamio.read_cloud(case, t, 'volume')
        n = foamio.read_cloud(case, t, 'porosity')
        change = abs(((1 - n) * V).sum() / g0 - 1)
        if change > worst:
            worst, tWorst = change, t
        J = max(J, (V / V0).max())
        if t != times[0] and os.path.exists(os.path.join(case, t, 'soilFraction')):
            phi = max(phi, foamio.read(case, t, 'soilFraction').max())
    return worst, tWorst, J, phi, (1 - n0).max()
