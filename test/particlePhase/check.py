#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks of particleStatistics and solidsFlux on the four beads (./run).

    check.py serial CASE
    check.py parallel CASE SERIALCASE
    check.py restart CASE SERIALCASE

Hand values: beads of d = 0.5 mm, z(t) = 5 mm + U t, U = 0.09 m/s (two,
at x = 0.6 and 4.6 mm) and -0.04 m/s (two), one step 1e-4 s, 300 steps;
the mesh's floor at z = 0, gravity along -z: mean height 5 mm + 0.025 t,
highest 5 mm + 0.09 t.
Tolerances: 1e-12 relative (the values are sums of a few doubles; the
positions that decide cells and slab are never within 1e-9 m of a face).
"""
import math
import sys
from pathlib import Path

DT = 1e-4
STEPS = 300
V = math.pi / 6 * 5e-4 ** 3
TOL = 1e-12


def rows(path):
    return [[float(v) for v in line.split()] for line in path.read_text().splitlines()
            if line.strip() and not line.startswith('#')]


def close(a, b, tol=TOL):
    return abs(a - b) <= tol * max(abs(b), 1e-300) if b != 0 else abs(a) <= 1e-300


def z_up(t):
    return 5e-3 + 0.09 * t


def serial(case):
    ok = True
    stats = rows(case / 'postProcessing/particles/0/particleStatistics.dat')
    flux = rows(case / 'postProcessing/flux/0/solidsFlux.dat')
    if len(stats) != STEPS or len(flux) != STEPS:
        print(f'FAIL: {len(stats)} and {len(flux)} lines, expected {STEPS}')
        return False
    theta_pair = (0.065 ** 2) / 3          # (1/3) var_z of 0.09 and -0.04
    bad = 0
    n_in = 0
    for k in range(STEPS):
        t = (k + 1) * DT
        s = stats[k]
        shared = z_up(t) < 6e-3            # each rising bead in its pair's cell
        expect = [t, 4, 4, 300, 0, 300, 300, 0.065, 0.025, 0.09,
                  theta_pair if shared else 0,
                  5e-3 + 0.025 * t, z_up(t)]     # heights above the floor z = 0
        good = len(s) == len(expect) and all(close(a, b) for a, b in zip(s, expect))
        in_slab = 6.5e-3 <= z_up(t) < 7.5e-3
        n_in += in_slab
        q = 2 * V * 0.09 / (6e-3 * 6e-3 * 1e-3) if in_slab else 0
        fexp = [t, q, q, 0, 2 if in_slab else 0]
        good &= len(flux[k]) == len(fexp) and all(close(a, b) for a, b in zip(flux[k], fexp))
        if not good:
            bad += 1
            if bad <= 3:
                print(f'differs at t = {t:g}: stats {s}, expected {expect};'
                      f' flux {flux[k]}, expected {fexp}')
    print(f'{STEPS} evaluations: {bad} differ from the hand values'
          f' (granular temperature {theta_pair:.6g} m2/s2 until'
          f' {sum(1 for k in range(STEPS) if z_up((k + 1) * DT) < 6e-3)} steps;'
          f' {n_in} steps with the rising beads in the slab)')
    ok &= bad == 0

    # Profile at 0.03 s: bins x in [0, 2), [2, 4), [4, 6) mm
    prof = rows(case / 'postProcessing/flux/0.03/solidsFluxProfile.dat')
    per_bin = V * 0.09 / (2e-3 * 6e-3 * 1e-3) * n_in / STEPS
    pexp = [[1e-3, per_bin], [3e-3, 0], [5e-3, per_bin]]
    pgood = len(prof) == 3 and all(len(r) == 2 for r in prof) and all(
        close(a, b, 1e-12) for r, e in zip(prof, pexp) for a, b in zip(r, e))
    print(f'time-averaged profile {[r[1] for r in prof]}, by hand'
          f' {[e[1] for e in pexp]}: {"ok" if pgood else "FAIL"}')
    ok &= pgood and len(prof) == 3

    # Distributions at 0.03 s: speed 6 bins of [0, 0.15), T 4 bins of [290, 310)
    speed = rows(case / 'postProcessing/particles/0.03/speedDistribution.dat')
    w = [r[3] for r in speed]
    sgood = w == [0, 2, 0, 2, 0, 0] and all(close(speed[b][5], 20) for b in (1, 3))
    print(f'speed distribution weights {w} (by hand [0, 2, 0, 2, 0, 0], pdf 20 s/m):'
          f' {"ok" if sgood else "FAIL"}')
    temp = rows(case / 'postProcessing/particles/0.03/temperatureDistribution.dat')
    tw = [r[3] for r in temp]
    tgood = tw == [0, 0, 4, 0] and close(temp[2][5], 0.2)
    print(f'temperature distribution weights {tw} (by hand [0, 0, 4, 0], 300 K on'
          f' the edge of [300, 305)): {"ok" if tgood else "FAIL"}')
    ok &= sgood and tgood

    # cellZone upper (the cells above z = 6 mm): the rising beads once
    # they cross 6 mm, alone in their cells
    upper = rows(case / 'postProcessing/upper/0/particleStatistics.dat')
    bad = 0
    first = None
    for k in range(STEPS):
        t = (k + 1) * DT
        if z_up(t) < 6e-3:
            expect = [t] + [0] * 12
        else:
            first = first if first is not None else t
            expect = [t, 2, 2, 300, 0, 300, 300, 0.09, 0, 0.09, 0,
                      z_up(t), z_up(t)]
        u = upper[k] if k < len(upper) else []
        if not (len(u) == len(expect) and all(close(a, b) for a, b in zip(u, expect))):
            bad += 1
            if bad <= 3:
                print(f'cellZone upper differs at t = {t:g}: {u}, expected {expect}')
    print(f'cellZone upper: {len(upper)} evaluations, {bad} differ from the hand'
          f' values (empty until t = {first:g} s, then the two rising beads)')
    ok &= len(upper) == STEPS and bad == 0
    speed = rows(case / 'postProcessing/upper/0.03/speedDistribution.dat')
    w = [r[3] for r in speed]
    temp = rows(case / 'postProcessing/upper/0.03/temperatureDistribution.dat')
    tw = [r[3] for r in temp]
    zgood = (w == [0, 0, 0, 2, 0, 0] and close(speed[3][5], 40)
             and tw == [0, 0, 2, 0] and close(temp[2][5], 0.2))
    print(f'cellZone upper distributions: speed {w} (by hand [0, 0, 0, 2, 0, 0],'
          f' pdf 40 s/m), temperature {tw} (by hand [0, 0, 2, 0]):'
          f' {"ok" if zgood else "FAIL"}')
    ok &= zgood
    return ok


def same(a_path, b_path, tol=TOL):
    a, b = rows(a_path), rows(b_path)
    if len(a) != len(b) or not a:
        print(f'FAIL: {a_path} has {len(a)} lines, {b_path} {len(b)}')
        return False
    bad = sum(1 for ra, rb in zip(a, b)
              if len(ra) != len(rb) or not all(close(x, y, tol) or x == y for x, y in zip(ra, rb)))
    print(f'{a_path.relative_to(a_path.parents[3])}: {len(a)} lines, {bad} differ')
    return bad == 0


def main():
    mode, case = sys.argv[1], Path(sys.argv[2])
    if mode == 'serial':
        ok = serial(case)
    elif mode == 'parallel':
        ref = Path(sys.argv[3])
        ok = True
        for f in ('particles/0/particleStatistics.dat', 'flux/0/solidsFlux.dat',
                  'flux/0.03/solidsFluxProfile.dat',
                  'particles/0.03/speedDistribution.dat',
                  'particles/0.03/temperatureDistribution.dat',
                  'upper/0/particleStatistics.dat',
                  'upper/0.03/speedDistribution.dat',
                  'upper/0.03/temperatureDistribution.dat'):
            ok &= same(case / 'postProcessing' / f, ref / 'postProcessing' / f)
    elif mode == 'restart':
        ref = Path(sys.argv[3])
        ok = same(case / 'postProcessing/flux/0.03/solidsFluxProfile.dat',
                  ref / 'postProcessing/flux/0.03/solidsFluxProfile.dat')
    else:
        sys.exit(f'check.py: unknown mode {mode}')
    print('PASS' if ok else 'FAIL')
    sys.exit(0 if ok else 1)


main()
