#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     tests/lib/setHydrostatic.py CASE RHO G H
#
# Description
#     Writes the hydrostatic pore pressure p = RHO G (H - y) (relative to
#     the lattice's reference pressure at the top) as the internalField of
#     CASE/0/p, from the cell centres 0/C (postProcess -func
#     writeCellCentres -time 0).
#------------------------------------------------------------------------------
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case = sys.argv[1]
rho, g, H = (float(v) for v in sys.argv[2:5])
y = foamio.read(case, '0', 'C')[:, 1]
p = rho * g * (H - y)
path = os.path.join(case, '0', 'p')
text = open(path).read()
field = 'internalField   nonuniform List<scalar>\n%d\n(\n%s\n)\n;' % (
    len(p), '\n'.join('%.17g' % v for v in p))
text = re.sub(r'internalField\s+uniform\s+0;', lambda m: field, text)
open(path, 'w').write(text)
