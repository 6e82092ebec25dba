#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Initial lattice of the demBed benchmark, shared by sinterFoam and LIGGGHTS.

Spheres of d = 1e-3 m in the box [0, 30.5e-3]^2 x [0, open), NZ layers of
NX x NY, every odd layer shifted by half the spacing in x and y:
    o = 0.505e-3*(k % 2)
    x = 0.51e-3 + i*1.01e-3 + o
    y = 0.51e-3 + j*1.01e-3 + o
    z = 0.52e-3 + k*0.9e-3
ordered k (slowest), j, i (fastest); zero initial velocity.

The last column and row of a shifted layer would cross the walls at x, y =
30.5e-3. By default (--odd-last drop) the odd layers leave them out, so an
odd layer has (NX-1) x (NY-1) spheres (30 x 30 x 24: 20,892 in all). With
--odd-last unshifted they stay at their unshifted place, the formula
o*(i < NX-1), o*(j < NY-1) of the first draft (30 x 30 x 24: 21,600): that
puts them 0.505e-3 from their shifted neighbours (767 overlapping pairs,
0.495 d deep), and the bed blows apart instead of settling.

Writes the plain file ("n" line, then "x y z" per sphere) to -o (or stdout),
optionally a LIGGGHTS read_data file (atom_style granular), and prints a
summary (count, max z, closest pair, initial overlaps) on stderr.
"""

import argparse
import math
import sys

D = 1e-3
RHO = 2500.0
LX = LY = 30.5e-3
ZTOP = 40e-3


def lattice(nx, ny, nz, drop):
    pts = []
    for k in range(nz):
        odd = k % 2
        o = 0.505e-3*odd
        z = 0.52e-3 + k*0.9e-3
        for j in range(ny - (odd and drop)):
            y = 0.51e-3 + j*1.01e-3 + o*(j < ny - 1)
            for i in range(nx - (odd and drop)):
                x = 0.51e-3 + i*1.01e-3 + o*(i < nx - 1)
                pts.append((x, y, z))
    return pts


def overlaps(pts, d):
    """Closest centre distance and number of pairs closer than d (grid hash)."""
    cells = {}
    for n, (x, y, z) in enumerate(pts):
        cells.setdefault((int(x//d), int(y//d), int(z//d)), []).append(n)
    dmin, nover = math.inf, 0
    for (cx, cy, cz), members in cells.items():
        for ox in (-1, 0, 1):
            for oy in (-1, 0, 1):
                for oz in (-1, 0, 1):
                    other = cells.get((cx + ox, cy + oy, cz + oz))
                    if not other:
                        continue
                    for a in members:
                        pa = pts[a]
                        for b in other:
                            if b <= a:
                                continue
                            r = math.dist(pa, pts[b])
                            dmin = min(dmin, r)
                            nover += r < d
    return dmin, nover


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--nx", type=int, default=30)
    p.add_argument("--ny", type=int, default=30)
    p.add_argument("--nz", type=int, default=24)
    p.add_argument("--odd-last", choices=("drop", "unshifted"), default="drop",
                   help="last column/row of odd layers (default drop)")
    p.add_argument("-o", "--output", help="plain position file (default stdout)")
    p.add_argument("--liggghts-data", help="also write a LIGGGHTS read_data file")
    a = p.parse_args()

    pts = lattice(a.nx, a.ny, a.nz, a.odd_last == "drop")
    for x, y, z in pts:
        if not (D/2 <= x <= LX - D/2 and D/2 <= y <= LY - D/2 and D/2 <= z < ZTOP):
            sys.exit(f"makeBed.py: sphere at ({x}, {y}, {z}) is outside the box")

    out = open(a.output, "w") if a.output else sys.stdout
    out.write(f"{len(pts)}\n")
    for x, y, z in pts:
        out.write(f"{x:.9e} {y:.9e} {z:.9e}\n")
    if a.output:
        out.close()

    if a.liggghts_data:
        with open(a.liggghts_data, "w") as f:
            f.write("LIGGGHTS data file: demBed lattice from makeBed.py\n\n")
            f.write(f"{len(pts)} atoms\n1 atom types\n\n")
            f.write(f"0 {LX:.9e} xlo xhi\n0 {LY:.9e} ylo yhi\n0 {ZTOP:.9e} zlo zhi\n\n")
            f.write("Atoms\n\n")
            # atom_style granular: id type diameter density x y z
            for n, (x, y, z) in enumerate(pts, 1):
                f.write(f"{n} 1 {D:.9e} {RHO:g} {x:.9e} {y:.9e} {z:.9e}\n")

    dmin, nover = overlaps(pts, D)
    print(f"makeBed.py: {len(pts)} spheres, max z {max(q[2] for q in pts):.6e} m, "
          f"closest centres {dmin:.6e} m, {nover} initially overlapping pairs",
          file=sys.stderr)


if __name__ == "__main__":
    main()
