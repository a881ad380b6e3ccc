#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     setRe100.py N
#
# Description
#     Turns this case (benchmark 2D-1, Re 20) into Schaefer & Turek's 2D-2
#     (Re 100) at N cells over the diameter (Allrun -Re 100 calls it on the
#     case's copy of 0.orig, constant and system):
#     - the inflow's parabola five times faster (U_m 1.5 m/s, mean 1 m/s) in
#       0.orig/U and system/setExprFieldsDict; Uref 1.5 (the Mach check);
#     - latticeForces' magUInf 1 (C = 2 F/(rho U_mean^2 D));
#     - endTime 8 s (periodic from about 4 s), written at 4 and 8 s;
#     - OpenFOAM's probes of p at the two nodes in front of (0.15, 0.2) and
#       the two behind (0.25, 0.2), on the rows of nodes either side of
#       y = 0.2 (cylinder.py extrapolates them to the points: Delta p(t));
#     deltaT is Allrun's (dx/(40 m/s)).
#------------------------------------------------------------------------------
import math
import re
import sys

n = int(sys.argv[1])
dx = 0.1 / n


def edit(path, *subs):
    s = open(path).read()
    for old, new in subs:
        if old not in s:
            raise SystemExit('setRe100.py: "%s" not found in %s' % (old, path))
        s = s.replace(old, new)
    open(path, 'w').write(s)


edit('0.orig/U', ('(2.926829268292683 0 0)', '(14.634146341463415 0 0)'),
     ('(-7.138607971445568 0 0)', '(-35.69303985722784 0 0)'),
     ('U_m = 0.3 m/s', 'U_m = 1.5 m/s'), ('(mean 0.2 m/s)', '(mean 1 m/s)'))
edit('system/setExprFieldsDict', ('vector(1.2*pos()', 'vector(6.0*pos()'))
edit('constant/fluidProperties', ('Uref            0.3;', 'Uref            1.5;'),
     ('Re = U_mean D/nu = 20', 'Re = U_mean D/nu = 100'))

# The nodes (x = (i + 1/2) dx) nearest the two points on the water's side
front = [(math.floor(0.15 / dx - 0.5 + 1e-9) - k + 0.5) * dx for k in (0, 1)]
back = [(math.ceil(0.25 / dx - 0.5 - 1e-9) + k + 0.5) * dx for k in (0, 1)]
j = math.floor(0.2 / dx - 0.5 + 1e-9)
rows = [(j + 0.5) * dx, (j + 1.5) * dx]
points = '\n'.join('            (%.10g %.10g 0.5)' % (x, y)
                   for x in front + back for y in rows)
probes = '''
    // p in front of and behind the cylinder: Delta p(t) (setRe100.py)
    pressureProbes
    {
        type            probes;
        libs            (sampling);
        fields          (p);
        probeLocations
        (
%s
        );
        writeControl    timeStep;
        writeInterval   10;
    }
''' % points

edit('system/controlDict', ('        magUInf     0.2;', '        magUInf     1.0;'))
s = open('system/controlDict').read()
# (the probes as the last entry of functions)
end = s.rindex('}', 0, s.rindex('// ****'))
s = s[:end] + probes.lstrip('\n') + s[end:]
s = re.sub(r'\nendTime\s+[^;]+;[^\n]*',
           '\nendTime         8;              // periodic from about 4 s', s)
s = re.sub(r'\nwriteInterval\s+[^;]+;', '\nwriteInterval   4;', s)
open('system/controlDict', 'w').write(s)
