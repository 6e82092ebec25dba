# SPDX-License-Identifier: GPL-3.0-or-later
# Checks of test/latticeBed/run (see there).
#   check.py WORKDIR TIME BEDMASS R H RHO
import math
import re
import sys

work, time = sys.argv[1], sys.argv[2]
bedMass, R, H, rho, Uin, dt, nHeight = (float(x) for x in sys.argv[3:10])
number = re.compile(r'[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?')
GEOMETRY_TOL = 1e-6     # [m]: 5 steps of free fall are 1.2e-7 m
# [m]: the two runs' gas solutions agree to the solvers' tolerance (their
# parcels' 1.2e-7 m falls differ by about 1e-11 m); a parcel placed from
# another draw would be off by its jitter (up to 1e-5 m) or a lattice
# spacing (1e-3 m)
MATCH_TOL = 1e-9
failures = []


def check(ok, message):
    print(('ok   ' if ok else 'FAIL ') + message)
    if not ok:
        failures.append(message)


def rows(case, name):
    text = open(f'{work}/{case}/{time}/lagrangian/cloud/{name}').read()
    body = text[text.index('}', text.index('FoamFile')) + 1:]
    lines = [l.strip() for l in body.split('\n')
             if l.strip() and not l.strip().startswith('//')]
    n = int(lines[0])
    return [tuple(float(x) for x in number.findall(l)) for l in lines[2:2 + n]]


def parcels(case):
    pos = [r[:3] for r in rows(case, 'positions')]
    d = [r[0] for r in rows(case, 'd')]
    assert len(pos) == len(d)
    return pos, d


pos, d = parcels('serial')
n = len(pos)
mass = sum(rho*math.pi/6*x**3 for x in d)
mMean = mass/n
check(abs(mass - bedMass) <= 0.5*mMean,
      f'{n} parcels of {mass:.6g} kg, bedMass {bedMass:g} kg '
      f'(within half a parcel, {0.5*mMean:.3g} kg)')

# Pairs: a grid of the largest diameter
dMax = max(d)
grid = {}
for i, (x, y, z) in enumerate(pos):
    grid.setdefault((int(x//dMax), int(y//dMax), int(z//dMax)), []).append(i)
closest = math.inf
for (cx, cy, cz), members in grid.items():
    for ox in (-1, 0, 1):
        for oy in (-1, 0, 1):
            for oz in (-1, 0, 1):
                for j in grid.get((cx + ox, cy + oy, cz + oz), []):
                    for i in members:
                        if i < j:
                            gap = math.dist(pos[i], pos[j]) - 0.5*(d[i] + d[j])
                            closest = min(closest, gap)
check(closest > -GEOMETRY_TOL,
      f'no two parcels overlap (smallest surface gap {closest:.3g} m)')
wall = min(R - math.hypot(x, y) - 0.5*di for (x, y, z), di in zip(pos, d))
bottom = min(z - 0.5*di for (x, y, z), di in zip(pos, d))
top = min(H - z - 0.5*di for (x, y, z), di in zip(pos, d))
# The O-grid's wall faces are chords of the circle: inside it by up to
# R (1 - cos(pi/(4 nSquare))) = 1.2e-4 m for nSquare 4 between vertices
check(wall > -GEOMETRY_TOL,
      f'no parcel crosses the cylinder (smallest gap {wall:.3g} m)')
check(bottom > -GEOMETRY_TOL and top > -GEOMETRY_TOL,
      f'none crosses the inlet or the outlet (gaps {bottom:.3g}, {top:.3g} m)')

log = open(f'{work}/serial/log.sinterFoam').read()
dem = [l for l in log.split('\n') if l.strip().startswith('DEM:')]
counts = [l.split(' s, ', 1)[1].split(';')[0] for l in dem]
touching = [c for c in counts if not re.match(r'^0 [^0-9]+0 ', c)]
check(len(dem) == 5 and not touching,
      f'no contact in the {len(dem)} steps ({counts[0] if counts else "no DEM line"})')
check('placed into each other' not in log, 'no parcels placed into each other')
# The gas takes the placed bed as its initial state: no displacement flow.
# The inlet flow through the bed gives Co = U dt/dz with U = Uin/eps, at
# most Uin dt/(0.3 dz) at the voidage floor; had the bed's appearance pushed
# gas out of it, U would be about theta h/dt (0.3 of a bed 0.02 m high in
# one step: 60 m/s), hundreds of times larger.
coLimit = Uin*dt/(0.3*H/nHeight)
courant = [float(l.split()[-1]) for l in log.split('\n')
           if l.startswith('Courant Number max')]
check('A bed was placed: its voidage is the gas' in log
      and max(courant) < coLimit,
      f'the placed bed is the gas initial state (Courant max {max(courant):.3g}, '
      f'below that of the inlet flow at voidage 0.3, {coLimit:.3g})')

pp, dp = parcels('parallel')
check(len(pp) == n, f'2 ranks: {len(pp)} parcels (serial {n})')
ser = {}
for i, (x, y, z) in enumerate(pos):
    ser.setdefault((int(x//dMax), int(y//dMax), int(z//dMax)), []).append(i)
worst, worstD = 0.0, 0.0
for p, dd in zip(pp, dp):
    c = tuple(int(v//dMax) for v in p)
    best = min((math.dist(p, pos[i]), i)
               for ox in (-1, 0, 1) for oy in (-1, 0, 1) for oz in (-1, 0, 1)
               for i in ser.get((c[0] + ox, c[1] + oy, c[2] + oz), []))
    worst = max(worst, best[0])
    worstD = max(worstD, abs(dd - d[best[1]]))
check(worst <= MATCH_TOL and worstD <= 1e-15,
      f'2 ranks placed the same parcels (worst position {worst:.3g} m, '
      f'diameter {worstD:.3g} m)')

sys.exit(1 if failures else 0)
