#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     tests/validation/holeErosionTest/quarterPipe.py
#
# Description
#     Cuts a copy of tutorials/coupled/holeErosionPipe to a quarter of its
#     section: the block y, z in [0, 24 mm] with the pipe's axis on the edge
#     y = z = 0, whose faces bottom (y = 0) and back (z = 0) are symmetry
#     planes (slip walls for the water and the soil); top and front stay
#     noSlip walls. A quarter of the nodes and points, the same flow.
#
# Usage
#     quarterPipe.py CASE
#------------------------------------------------------------------------------
import re
import sys


def edit(path, pairs):
    text = open(path).read()
    for old, new in pairs:
        if not re.search(old, text):
            sys.exit('quarterPipe.py: %s has no %s' % (path, old))
        text = re.sub(old, new, text)
    open(path, 'w').write(text)


case = sys.argv[1]
edit(case + '/system/blockMeshDict', [
    (r'0\.048', '0.024'),
    (r'\(32 24 24\)', '(32 12 12)'),
    (r'frontAndBack \{ type wall; faces \(\(0 3 2 1\) \(4 5 6 7\)\); \}[^\n]*',
     'back  { type wall; faces ((0 3 2 1)); }\n'
     '    front { type wall; faces ((4 5 6 7)); }'),
])
edit(case + '/system/setMaterialPointsDict', [
    (r'point1(\s+)\(-1 0\.024 0\.024\)', r'point1\1(-1 0 0)'),
    (r'point2(\s+)\(1 0\.024 0\.024\)', r'point2\1(1 0 0)'),
])
edit(case + '/system/controlDict', [
    (r'(\(0\.0\d+) 0\.024 0\.024\)', r'\1 0.0005 0.0005)'),
])
for field, sym, wall in (('U', 'slip', 'noSlip'), ('p', 'zeroGradient', None),
                         ('fines', 'zeroGradient', None)):
    pairs = [(r'bottom(\s+)\{ type \w+; \}', r'bottom\1{ type %s; }' % sym),
             (r'frontAndBack \{ type (\w+); \}',
              'back         { type %s; }\n    front        { type %s; }'
              % (sym, wall or r'\1'))]
    edit(case + '/0/' + field, pairs)
edit(case + '/constant/soilProperties', [
    (r'bottom(\s+)\{ type noSlip; \}', r'bottom\1{ type slip; }'),
    (r'frontAndBack \{ type noSlip; \}',
     'back         { type slip; }\n    front        { type noSlip; }'),
])
