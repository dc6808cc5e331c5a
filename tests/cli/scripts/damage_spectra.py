#!/usr/bin/env python3
"""Issue 39, class 3: sets one ordinate of a spectra.bin (record 0, damping 0,
period index I) to VALUE and writes its trailing FNV-1a 64 content hash again,
as a damaged file whose hash still matches (record_spectra.cpp's layout).

  damage_spectra.py SPECTRA.BIN I VALUE
"""
import struct
import sys

path, index, value = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
b = bytearray(open(path, "rb").read())
n_periods, n_dampings, n_records = struct.unpack_from("<3I", b, 32)
first = len(b) - 8 - 8 * n_periods * n_dampings * n_records
struct.pack_into("<d", b, first + 8 * index, value)
h = 14695981039346656037
for c in bytes(b[:-8]):
    h = ((h ^ c) * 1099511628211) % 2**64
struct.pack_into("<Q", b, len(b) - 8, h)
open(path, "wb").write(b)
