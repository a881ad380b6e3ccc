#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     tutorials/coupled/holeErosionTest/holeErosion.py
#
# Description
#     The slot's half-width R(t) of a hole erosion test case against the
#     analytic solution of Bonelli & Brivois (2008) for a slot: the wall
#     shear stress of a slot of half-width R under the pressure gradient
#     dP/L is tau = R dP/L (the momentum balance of the water between the
#     walls), the walls recede at m_dot/rho_d = kEr (tau - tauC)/rho_d, so
#         R(t) = R_c + (R0 - R_c) exp(t/t_er),
#         t_er = L rho_d/(kEr dP),  R_c = tauC L/dP.
#     R is measured where the nodal solid fraction crosses
#     surfaceSolidFraction (half the soil's, 0.3), averaged over the columns
#     of the middle third.
#
#     A 3D case whose setMaterialPointsDict carves the hole as a
#     searchableCylinder of material none (tutorials/coupled/holeErosionPipe)
#     is the pipe: there
#     tau = R dP/(2 L) and
#         R(t) = R_c + (R0 - R_c) exp(t/t_er),
#         t_er = 2 L rho_d/(kEr dP),  R_c = 2 tauC L/dP,
#     R is the radius of the hole's area, A = pi R^2, the soil missing from
#     a cross-section, sum of (1 - phi/phi_s) dx^2 (phi_s the intact soil's
#     solid fraction), averaged over the cross-sections of the middle third,
#     and R0 that of the hole as seeded (its sub-cells: the cylinder's
#     staircase) at t = 0; the discharge against Poiseuille's
#     Q = pi R^4 (dP/L)/(8 mu), the wall shear stress (its magnitude,
#     averaged over the surface nodes of the middle third) against
#     R0 dP/(2 L).
#
#     Prints per written time: t, R/R0, the analytic R/R0, the relative
#     error; with --tau, the wall shear stress on both walls of the middle
#     third against R0 dP/L; with --flow, the flow meter's discharge per
#     unit depth (function object flowMeter) at the written times against
#     the slot's Poiseuille discharge q = (2/3) R^3 (dP/L)/mu with the
#     measured R, and the piezometers (function object piezometers) at the
#     last written time against the linear drop dP (1 - x/L); with
#     --level phi_s, the half-width Rs at the nodal solid fraction phi_s
#     (the erosion's surfaceSolidFraction) against Rs(t0) exp((t - t0)/t_er)
#     from the first written time t0 (the wall stress the surface sees is
#     (dP/L) Rs); with --png,
#     the plot: R(t), the discharge against time with Poiseuille's and
#     (R0 exp(t/t_er))^3's, the piezometers' pressures.
#
# Usage
#     holeErosion.py CASE [--tau] [--flow] [--level PHI] [--png FILE]
#------------------------------------------------------------------------------
import math
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(
    os.environ.get('MPMLBM_PROJECT_DIR', os.path.join(here, '..', '..', '..')),
    'tests', 'lib'))
import foamio


def entry(path, key):
    """The first number after key in a dictionary file"""
    text = open(path).read()
    text = re.sub(r'//.*', '', text)
    m = re.search(r'\b' + key + r'\s+(?:uniform\s+)?([-+0-9.eE]+)\s*;', text)
    if not m:
        sys.exit('%s: no entry %s' % (path, key))
    return float(m.group(1))


def series(case, name, file):
    """Time and values of postProcessing/<name>/<start>/<file> as lists (a
    restart's folder replacing the rows from its start:
    foamio.post_processing)"""
    return foamio.post_processing(case, name, file).tolist()




def flowAt(flow, t, scale):
    """The flow meter's reading at time t over scale (None: no reading)"""
    near = [r for r in flow if abs(r[0] - t) < 1e-9*max(1, t)]
    return abs(near[-1][1])/scale if near else None


def printPiezometers(piezo, dP):
    """The piezometers at the last sampled time against the linear drop"""
    if piezo:
        last = piezo[-1]
        for k, x in enumerate((0.25, 0.5, 0.75)):
            pa = dP*(1 - x)
            print('piezometer %g %.3f %.6g %.6g %.6f'
                  % (last[0], x, last[1 + k], pa, last[1 + k]/pa - 1))


def newFigure():
    """matplotlib without a display, and a row of three panels"""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.4))
    return fig, axes

def plotRadiusAndDischarge(axes, rows, R0, Rc, tEr, dx, radiusTitle, flow,
                           power, qLabel, qTitle):
    """The first two panels: R/R0 against Bonelli & Brivois's solution, and
    the flow meter's discharge (times and values over the reference)
    against Poiseuille's, which goes as (R/R0)^power"""
    ts = [r[0] for r in rows]
    tt = [i*ts[-1]/200 for i in range(201)]
    analytic = [(Rc + (R0 - Rc)*math.exp(x/tEr))/R0 for x in tt]
    ax = axes[0]
    ax.plot(tt, analytic, 'k-',
            label='Bonelli & Brivois (2008): exp(t/t_er), t_er = %.0f s' % tEr)
    ax.plot(ts, [r[1] for r in rows], 'o', color='tab:red',
            label='mpmLbmFoam, dx = R0/%d' % round(R0/dx))
    ax.set_xlabel('t [s]')
    ax.set_ylabel('R/R0')
    ax.set_title(radiusTitle)
    ax.grid(alpha=0.3)
    ax.legend(loc='upper left', fontsize=8)

    ax = axes[1]
    if flow:
        ax.plot([f[0] for f in flow], [f[1] for f in flow], '-',
                color='tab:blue', lw=1.5,
                label='flow meter (outlet), every 0.5 s')
    ax.plot(tt, [r**power for r in analytic], 'k-',
            label='Poiseuille with R0 exp(t/t_er): (R/R0)$^%d$' % power)
    ax.plot(ts, [r[1]**power for r in rows], 'o', color='tab:red', ms=4,
            label='Poiseuille with the measured R')
    ax.set_xlabel('t [s]')
    ax.set_ylabel(qLabel)
    ax.set_title(qTitle, fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(loc='upper left', fontsize=8)


def main():
    args = sys.argv[1:]
    case = args[0]
    png = args[args.index('--png') + 1] if '--png' in args else None

    bmd = open(os.path.join(case, 'system', 'blockMeshDict')).read()
    nx, ny, nz = map(int, re.search(
        r'hex\s*\([^)]*\)\s*\((\d+)\s+(\d+)\s+(\d+)\)', bmd).groups())
    zero = r'0(?:\.0*)?'
    length = float(re.search(
        r'\(\s*%s\s+%s\s+%s\s*\)\s*\(([-+0-9.eE]+)' % (zero, zero, zero),
        bmd).group(1))
    dx = length/nx
    depth = max(float(z) for z in re.findall(
        r'\(\s*[-+0-9.eE]+\s+[-+0-9.eE]+\s+([-+0-9.eE]+)\s*\)',
        bmd.split('blocks')[0]))
    fluid = os.path.join(case, 'constant', 'fluidProperties')
    mu = entry(fluid, 'rho')*entry(fluid, 'nu')
    ero = os.path.join(case, 'constant', 'erosionProperties')
    kEr = entry(ero, 'kEr')
    tauC = entry(ero, 'tauC')
    rhoD = entry(os.path.join(case, 'constant', 'soilProperties'), 'rho')
    dP = entry(os.path.join(case, '0', 'p'), 'value')
    smp = open(os.path.join(case, 'system', 'setMaterialPointsDict')).read()
    if 'searchableCylinder' in smp:
        return pipe(case, args, png, nx, ny, nz, dx, length, mu, kEr, tauC,
                    rhoD, dP, smp)
    lowTop = float(re.search(r'max\s*\(\s*\S+\s+([-+0-9.eE]+)', smp).group(1))
    topBottom = float(re.findall(
        r'min\s*\(\s*\S+\s+([-+0-9.eE]+)', smp)[1])
    R0 = 0.5*(topBottom - lowTop)
    yc = 0.5*(topBottom + lowTop)
    G = dP/length
    tEr = rhoD/(kEr*G) if kEr > 0 else float('inf')
    Rc = tauC/G
    # R: the half level of the soil's nodal solid fraction (0.6 inside)
    level = 0.3

    def halfWidth(phi):
        Rs = []
        for i in range(nx//3, 2*nx//3):
            col = [phi[j*nx + i] for j in range(ny)]
            jc = int(yc/dx)
            lo = max(j for j in range(jc) if col[j] >= level)
            hi = min(j for j in range(jc, ny) if col[j] >= level)
            ylo = (lo + 0.5 + (level - col[lo])/(col[lo + 1] - col[lo]))*dx
            yhi = (hi - 0.5 + (level - col[hi - 1])/(col[hi] - col[hi - 1]))*dx
            Rs.append(0.5*(yhi - ylo))
        return sum(Rs)/len(Rs)

    rows = []
    for t in foamio.times(case):
        phi = foamio.read(case, t, 'soilFraction') \
            if os.path.exists(os.path.join(case, t, 'soilFraction')) else None
        if phi is None:
            continue
        R = halfWidth(phi)
        Ra = Rc + (R0 - Rc)*math.exp(float(t)/tEr)
        rows.append((float(t), R/R0, Ra/R0, R/Ra - 1))
        print('R %s %.6f %.6f %.6f' % (t, R/R0, Ra/R0, R/Ra - 1))

    # --level phi_s: the half-width Rs of the surface the erosion sees
    # (surfaceSolidFraction phi_s), whose wall stress is G Rs: it grows as
    # Rs(t0) exp((t - t0)/t_er) from the first written time t0 (tauC 0)
    if '--level' in args:
        level = float(args[args.index('--level') + 1])
        first = None
        for t in foamio.times(case):
            if not os.path.exists(os.path.join(case, t, 'soilFraction')):
                continue
            Rs = halfWidth(foamio.read(case, t, 'soilFraction'))
            if first is None:
                first = (float(t), Rs)
            ratio = math.exp((float(t) - first[0])/tEr)
            print('S %s %.6f %.6f %.6f %.6f' % (t, Rs/R0, Rs/first[1], ratio,
                                                Rs/first[1]/ratio - 1))

    # The flow meter (m3/s through the depth) and the piezometers
    flow = series(case, 'flowMeter', 'surfaceFieldValue.dat')
    piezo = series(case, 'piezometers', 'p')
    q0 = 2.0/3.0*R0**3*G/mu

    if '--flow' in args:
        for t, RR0, _, _ in rows:
            q = flowAt(flow, t, depth)
            if q is None or t <= 0:
                continue
            qP = 2.0/3.0*(RR0*R0)**3*G/mu
            print('Q %g %.6g %.6g %.6f' % (t, q, qP, q/qP - 1))
        printPiezometers(piezo, dP)

    if '--tau' in args:
        t = foamio.latest_time(case)
        tau = foamio.read(case, t, 'wallShearStress')
        jc = int(yc/dx)
        for side, js in (('bottom', range(jc)), ('top', range(jc, ny))):
            vals = [max(abs(tau[j*nx + i][0]) for j in js)
                    for i in range(nx//3, 2*nx//3)]
            mean = sum(vals)/len(vals)
            print('tau %s %.6g %.6g %.6f' % (side, mean, R0*G, mean/(R0*G) - 1))

    if png:
        fig, axes = newFigure()
        plotRadiusAndDischarge(
            axes, rows, R0, Rc, tEr, dx, 'Half-width of the slot',
            [(r[0], abs(r[1])/depth/q0) for r in flow], 3, 'q/q0',
            'Discharge, q0 = (2/3) R0$^3$ (dP/L)/mu = %.3g m$^2$/s' % q0)

        ax = axes[2]
        if piezo:
            for k, (x, c) in enumerate(zip((0.25, 0.5, 0.75),
                                           ('tab:green', 'tab:orange',
                                            'tab:purple'))):
                ax.plot([r[0] for r in piezo], [r[1 + k] for r in piezo],
                        '-', color=c, lw=1.5, label='x = %.2f L' % x)
                ax.axhline(dP*(1 - x), color=c, ls='--', lw=0.8)
        ax.set_xlabel('t [s]')
        ax.set_ylabel('p [Pa]')
        ax.set_ylim(0, dP)
        ax.set_title('Piezometers on the axis (dashed: dP (1 - x/L))',
                     fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(loc='center right', fontsize=8)
        fig.suptitle('Hole erosion test (2D slot, Wan & Fell 2004): '
                     'kEr = %g s/m, dP = %g Pa over L = %g m' % (kEr, dP, length))
        fig.tight_layout()
        fig.savefig(png, dpi=100)


def pipe(case, args, png, nx, ny, nz, dx, length, mu, kEr, tauC, rhoD, dP,
         smp):
    """The 3D pipe: R(t) from the hole's area, the discharge, the wall
    shear stress (see the description)"""
    cyl = re.search(r'searchableCylinder;(.*?)}', smp, re.S).group(1)
    p1 = [float(v) for v in re.search(
        r'point1\s*\(([^)]*)\)', cyl).group(1).split()]
    Rseed = float(re.search(r'radius\s+([-+0-9.eE]+)', cyl).group(1))
    # The hole as seeded: the sub-cells (pointsPerCell per cell and
    # direction) whose centres lie in the cylinder are left empty
    n = int(re.search(r'pointsPerCell\s+(\d+)', smp).group(1))
    h = dx/n
    seeded = sum(1 for j in range(ny*n) for k in range(nz*n)
                 if ((j + 0.5)*h - p1[1])**2 + ((k + 0.5)*h - p1[2])**2
                 < Rseed**2)
    # The share of the pipe's section inside the mesh (1; 1/4 for a
    # quarter of the pipe between two symmetry planes through its axis)
    m = 400
    inside = sum(1 for a in range(m) for b in range(m)
                 if (-1 + (2*a + 1)/m)**2 + (-1 + (2*b + 1)/m)**2 < 1
                 and 0 < p1[1] + Rseed*(-1 + (2*a + 1)/m) < ny*dx
                 and 0 < p1[2] + Rseed*(-1 + (2*b + 1)/m) < nz*dx)
    share = inside/(math.pi/4*m*m)
    share = 0.25*round(4*share) if abs(4*share - round(4*share)) < 0.02 \
        else share
    R0 = math.sqrt(seeded*h*h/(share*math.pi))
    print('seeded %.6g %.6g' % (R0, Rseed))
    G = dP/length
    tEr = 2*rhoD/(kEr*G) if kEr > 0 else float('inf')
    Rc = 2*tauC/G
    cols = range(nx//3, 2*nx//3)

    def field(t, name):
        path = os.path.join(case, t, name)
        return foamio.read(case, t, name) if os.path.exists(path) else None

    phiS = None
    rows = []
    for t in foamio.times(case):
        phi = field(t, 'soilFraction')
        if phi is None:
            continue
        if phiS is None:
            # The intact soil's solid fraction: the densest node of the
            # first written time (the soil is not compacted: elastic, held
            # by its walls)
            phiS = max(phi)
        areas = []
        for i in cols:
            a = 0.0
            for k in range(nz):
                for j in range(ny):
                    a += min(max(1 - phi[(k*ny + j)*nx + i]/phiS, 0.0), 1.0)
            areas.append(a*dx*dx)
        R = math.sqrt(sum(areas)/len(areas)/(share*math.pi))
        Ra = Rc + (R0 - Rc)*math.exp(float(t)/tEr)
        rows.append((float(t), R/R0, Ra/R0, R/Ra - 1))
        print('R %s %.6f %.6f %.6f' % (t, R/R0, Ra/R0, R/Ra - 1))

    flow = series(case, 'flowMeter', 'surfaceFieldValue.dat')
    piezo = series(case, 'piezometers', 'p')
    Q0 = math.pi*R0**4*G/(8*mu) if R0 else 1

    if '--flow' in args:
        for t, RR0, _, _ in rows:
            q = flowAt(flow, t, share)
            if q is None or t <= 0:
                continue
            qP = Q0*RR0**4
            print('Q %g %.6g %.6g %.6f' % (t, q, qP, q/qP - 1))
        printPiezometers(piezo, dP)

    if '--tau' in args:
        t = foamio.latest_time(case)
        tau = field(t, 'wallShearStress')
        vals = []
        for i in cols:
            for k in range(nz):
                for j in range(ny):
                    v = tau[(k*ny + j)*nx + i]
                    m = math.sqrt(v[0]**2 + v[1]**2 + v[2]**2)
                    if m > 0:
                        vals.append(m)
        mean = sum(vals)/len(vals)
        spread = (max(vals) - min(vals))/mean
        ref = R0*G/2
        print('tau wall %.6g %.6g %.6f %d %.4f'
              % (mean, ref, mean/ref - 1, len(vals), spread))

    if png:
        fig, axes = newFigure()
        plotRadiusAndDischarge(
            axes, rows, R0, Rc, tEr, dx, 'Radius of the pipe (its area)',
            [(r[0], abs(r[1])/share/Q0) for r in flow], 4, 'Q/Q0',
            'Discharge, Q0 = pi R0$^4$ (dP/L)/(8 mu) = %.3g m$^3$/s' % Q0)

        ax = axes[2]
        phi = None
        for t in reversed(foamio.times(case)):
            phi = field(t, 'soilFraction')
            if phi is not None:
                break
        i = nx//2
        img = [[phi[(k*ny + j)*nx + i] for j in range(ny)] for k in range(nz)]
        im = ax.imshow(img, origin='lower', cmap='copper_r',
                       extent=(0, ny*dx*1e3, 0, nz*dx*1e3), vmin=0, vmax=phiS)
        th = [2*math.pi*x/200 for x in range(201)]
        for r, style in ((R0, 'w--'), (rows[-1][2]*R0, 'c-')):
            ax.plot([(p1[1] + r*math.cos(a))*1e3 for a in th],
                    [(p1[2] + r*math.sin(a))*1e3 for a in th], style, lw=1)
        fig.colorbar(im, ax=ax, label='soil fraction')
        ax.set_xlabel('y [mm]')
        ax.set_ylabel('z [mm]')
        ax.set_title('Cross-section at x = L/2, t = %g s (dashed: R0, '
                     'cyan: analytic R)' % rows[-1][0], fontsize=10)
        fig.suptitle('Hole erosion test (3D pipe, Wan & Fell 2004): '
                     'kEr = %g s/m, dP = %g Pa over L = %g m' % (kEr, dP, length))
        fig.tight_layout()
        fig.savefig(png, dpi=100)


main()
