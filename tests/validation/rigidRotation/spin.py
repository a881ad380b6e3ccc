#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     spin.py CASE OMEGA
#
# Description
#     Sets the material points of CASE/0 spinning rigidly about the block's
#     centre of mass at OMEGA rad/s (about z): U = omega e_z x (x - x_c),
#     and the APIC velocity gradient C the spin's, [[0, -omega], [omega, 0]],
#     written over setMaterialPoints' U and C (as ASCII lists, in the
#     cloud's order).
#------------------------------------------------------------------------------
import os
import re
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.environ['MPMLBM_PROJECT_DIR'], 'tests', 'lib'))
import foamio

case, omega = sys.argv[1], float(sys.argv[2])
cloud = os.path.join(case, '0', 'lagrangian', 'materialPoints')
x = foamio.read_cloud(case, '0', 'x', by_identity=False)
m = foamio.read_cloud(case, '0', 'mass', by_identity=False)
xc = (m[:, None] * x).sum(0) / m.sum()
r = x - xc
U = np.column_stack((-omega * r[:, 1], omega * r[:, 0], np.zeros(len(x))))
C = np.tile([0, -omega, 0, omega, 0, 0, 0, 0, 0], (len(x), 1))


def rewrite(name, rows):
    path = os.path.join(cloud, name)
    text = open(path, 'rb').read().decode('latin-1')
    head = re.search(r'\n(\d+)\s*\n\(', text)
    if head is None or int(head.group(1)) != len(rows):
        sys.exit('spin.py: %s is not a list of %d values' % (path, len(rows)))
    # (the header says how the list is written)
    text = re.sub(r'format\s+binary;', 'format      ascii;', text[:head.start()])
    body = '\n'.join('(' + ' '.join('%.17g' % v for v in row) + ')' for row in rows)
    with open(path, 'w') as f:
        f.write(text + '\n%d\n(\n%s\n)\n' % (len(rows), body))


rewrite('U', U)
rewrite('C', C)
