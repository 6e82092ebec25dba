#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks of the agglomerate statistics of the three columns (see ./run).

    check.py CASE [SERIALCASE]
    check.py --bridged CASE
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / 'lib'))
from foamFiles import lagrangian_list  # noqa: E402


def rows(case):
    dat = case / 'postProcessing/agglomerates/0/agglomerateStatistics.dat'
    return [[float(v) for v in line.split()]
            for line in dat.read_text().splitlines()
            if line.strip() and not line.startswith('#')]


def bridged(case):
    """The plain count against the bridged-only one (run bridgedOnly)"""
    n = 15
    plain = {round(r[0], 9): r for r in rows(case)}
    dat = case / 'postProcessing/bridged/0/agglomerateStatistics.dat'
    brid = {round(float(line.split()[0]), 9): [float(v) for v in line.split()]
            for line in dat.read_text().splitlines()
            if line.strip() and not line.startswith('#')}
    ok = True
    two = lambda r: (r[1] == 2 and abs(r[2] - 11 / n) < 1e-12
                     and abs(r[4] - 6 / n) < 1e-12 and abs(r[5] - 5.5) < 1e-12)
    before = [t for t in brid if 0.02 - 1e-9 <= t < 0.025 - 1e-9]
    bad = [t for t in before if not two(plain[t]) or brid[t][1] != 0]
    print(f'{len(before)} evaluations in [0.02, 0.025) s (contacts older than'
          f' 0.01 s, no bridge yet): plain count 2 (6 and 5), bridged count 0:'
          f' {"ok" if before and not bad else "FAIL"}')
    ok &= bool(before) and not bad
    first = min((t for t in brid if brid[t][1] > 0), default=None)
    print(f'first bridged agglomerate at t = {first} s (bridges from 0.025 s)')
    after = [t for t in brid if t >= 0.026 - 1e-9]
    bad = [t for t in after if not two(plain[t]) or not two(brid[t])]
    print(f'{len(after)} evaluations from 0.026 s: both counts 2 agglomerates'
          f' (6 and 5): {"ok" if after and not bad else "FAIL"}')
    if bad:
        print('  first off:', bad[0], plain[bad[0]], brid[bad[0]])
    ok &= bool(after) and not bad
    print('passed' if ok else 'FAIL')
    return 0 if ok else 1


def main():
    if sys.argv[1] == '--bridged':
        return bridged(Path(sys.argv[2]))
    case = Path(sys.argv[1])
    ok = True
    n = 15
    data = rows(case)
    early = [r for r in data if r[0] < 0.01 - 1e-9]
    late = [r for r in data if r[0] >= 0.02 - 1e-9]
    bad_early = [r for r in early
                 if r[1] != 0 or abs(r[4] - 1 / n) > 1e-12 or r[6] != n]
    print(f'{len(early)} evaluations before 0.01 s: no agglomerate, the'
          f' largest one bead: {"ok" if early and not bad_early else "FAIL"}')
    ok = ok and bool(early) and not bad_early
    bad_late = [r for r in late
                if r[1] != 2 or abs(r[2] - 11 / n) > 1e-12
                or abs(r[4] - 6 / n) > 1e-12 or abs(r[5] - 5.5) > 1e-12
                or r[6] != n or abs(r[3] - r[2]) > 1e-12]
    print(f'{len(late)} evaluations from 0.02 s: 2 agglomerates (6 and 5),'
          f' fractions 11/15 of the beads and of the mass, largest 6/15,'
          f' mean size 5.5: {"ok" if late and not bad_late else "FAIL"}')
    if bad_late:
        print('  first off:', bad_late[0])
    ok = ok and bool(late) and not bad_late
    switch = [r[0] for r in data if r[1] > 0]
    print(f'first evaluation with an agglomerate: t = '
          f'{switch[0] if switch else None} s (10 ms after the first'
          f' contacts close)')

    hist = (case / 'postProcessing/agglomerates/0.03/agglomerateSizes.dat')
    pairs = sorted(tuple(int(v) for v in line.split())
                   for line in hist.read_text().splitlines()
                   if line.strip() and not line.startswith('#'))
    print(f'histogram at 0.03 s: {pairs} (expected [(5, 1), (6, 1)])')
    ok = ok and pairs == [(5, 1), (6, 1)]

    ids = lagrangian_list(case / '0.03/lagrangian/cloud/agglomerateId', 'i')
    groups = sorted(ids.count(v) for v in set(ids) if v >= 0)
    free = ids.count(-1)
    print(f'agglomerateId at 0.03 s: groups {groups}, {free} free, ids'
          f' {sorted(set(ids))} (expected [5, 6], 4, [-1, 0, 1])')
    ok = ok and groups == [5, 6] and free == 4 and sorted(set(ids)) == [-1, 0, 1]

    if len(sys.argv) > 2:
        serial = rows(Path(sys.argv[2]))
        same = len(serial) == len(data) and all(
            a[0] == b[0] and a[1] == b[1] and a[6] == b[6]
            and abs(a[2] - b[2]) < 1e-12 and abs(a[4] - b[4]) < 1e-12
            for a, b in zip(serial, data))
        print(f'2 ranks against serial, every evaluation (count, fractions):'
              f' {"same" if same else "FAIL"}')
        ok = ok and same
    print('passed' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
