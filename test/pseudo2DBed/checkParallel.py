#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks of the 2-rank pseudo2DBed PW run against the serial one.

    checkParallel.py PARALLELCASE SERIALCASE

- the parallel run reached 0.2 s and reconstructPar wrote it;
- the reconstructed cloud holds as many parcels as the serial one, each
  with a temperature between the walls' 293.15 K and the charge's
  363.15 K (no parcel lost or duplicated at the processor boundary, none
  heated or cooled past the temperatures the bed meets);
- the bed cools over 0.12-0.2 s by the serial run's amount within 10 %:
  the ranks sum in another order, so the two runs part ways (chaotic
  dynamics), but the cooling is a bulk quantity of the whole bed.
"""
import re
import struct
import sys
from pathlib import Path

sys.dont_write_bytecode = True   # no __pycache__ beside the test
sys.path.insert(0, str(Path(__file__).resolve().parent))
from check import mean_T, at  # noqa: E402


def parcels(case, time):
    """The count and the values of the cloud's T at `time` (ascii or
    binary)."""
    raw = (case / time / 'lagrangian/cloud/T').read_bytes()
    header_end = raw.index(b'}', raw.index(b'FoamFile')) + 1
    binary = re.search(rb'format\s+binary', raw[:header_end]) is not None
    m = re.compile(rb'(\d+)\s*\(').search(raw, header_end)
    n = int(m.group(1))
    start = m.end()
    if binary:
        values = list(struct.unpack(f'<{n}d', raw[start:start + 8 * n]))
    else:
        values = [float(v) for v in
                  raw[start:raw.index(b')', start)].split()]
    return n, values


def main():
    par, ser = Path(sys.argv[1]), Path(sys.argv[2])
    ok = True
    t0, t1 = 0.12, 0.2
    if not (par / '0.2/lagrangian/cloud/T').exists():
        print('FAIL: reconstructPar wrote no 0.2/lagrangian/cloud/T')
        return 1
    nPar, TPar = parcels(par, '0.2')
    nSer, _ = parcels(ser, '0.2')
    print(f'parcels at 0.2 s: parallel {nPar}, serial {nSer}')
    ok = ok and nPar == nSer and len(TPar) == nPar
    lo, hi = min(TPar), max(TPar)
    print(f'parcel temperatures in [{lo:.4f}, {hi:.4f}] K'
          ' (within [293.15, 363.15])')
    ok = ok and lo >= 293.15 and hi <= 363.15

    sPar, sSer = mean_T(par), mean_T(ser)
    if abs(sPar[-1][0] - t1) > 1e-9:
        print(f'FAIL: the parallel run ended at {sPar[-1][0]} s')
        return 1
    dPar = at(sPar, t0) - at(sPar, t1)
    dSer = at(sSer, t0) - at(sSer, t1)
    rel = abs(dPar - dSer) / dSer
    print(f'cooled over {t0}-{t1} s: parallel {dPar:.4f} K, serial'
          f' {dSer:.4f} K ({100 * rel:.2f} % apart, at most 10 %)')
    ok = ok and dSer > 0 and rel < 0.1
    print('passed' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
