#!/usr/bin/python3
#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     damage.py FILE INDEX VALUE
#
# Description
#     Damages one value of an OpenFOAM list file in place, as a disk or a
#     crash might: the scalar component INDEX of its (first) list is set to
#     VALUE (nan, inf, -inf or a number). Binary files (written by the
#     solver: populations, cloud fields) get the 8 bytes of the double;
#     ASCII files get the text.
#------------------------------------------------------------------------------
import re
import struct
import sys

path, index, value = sys.argv[1], int(sys.argv[2]), sys.argv[3]
number = float(value)
raw = open(path, 'rb').read()
# The list: after the header (FoamFile { ... }), "N (" or
# "internalField nonuniform List<T> N ("
start = raw.find(b'}', raw.find(b'FoamFile')) + 1
m = re.compile(rb'(\d+)\s*\(').search(raw, start)
if not m:
    sys.exit('damage.py: no list in ' + path)
body = m.end()
if re.search(rb'format\s+binary', raw[:start]):
    offset = body + 8 * index
    raw = raw[:offset] + struct.pack('<d', number) + raw[offset + 8:]
else:
    text = raw.decode()
    # Values: numbers in the list's text, in order
    nums = list(re.finditer(r'[-+0-9.eE]+', text[body:]))
    n = nums[index]
    text = text[:body + n.start()] + value + text[body + n.end():]
    raw = text.encode()
open(path, 'wb').write(raw)
