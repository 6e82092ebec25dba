# SPDX-License-Identifier: GPL-3.0-or-later
# Checks of test/demParallel/run (see there): WORKDIR holds serial/,
# parallel/ (reconstructed) and roundTrip/ (serial 0.02 s write decomposed
# and reconstructed). ASCII lagrangian fields, one parcel per line.
import collections
import math
import os
import re
import sys

work = sys.argv[1]
number = re.compile(r'[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?')

POSITION_TOL = 1e-9     # [m], 2e-6 bead diameters
VELOCITY_TOL = 1e-6     # [m/s]
# [K]. A bead's conduction goes through its contact radii, a ~ sqrt(R* delta),
# so the round-off in the positions (the sums of forces differ in order
# between the runs) reaches the temperatures amplified by R*/delta, and the
# heat flows of a bead are summed in a different order too. The tolerance
# stays below what one contact's conduction over one DEM step moves a bead's
# temperature here (2 k a dT dt/(m c), about 1e-5 K for these soft beads
# 6 K apart), so a contact missed or counted twice across the processor
# boundary for a single step fails.
TEMPERATURE_TOL = 1e-6


def rows(case, time, name):
    """The parcel entries of a lagrangian field, as tuples of numbers"""
    text = open(f'{work}/{case}/{time}/lagrangian/cloud/{name}').read()
    body = text[text.index('}', text.index('FoamFile')) + 1:]
    lines = [l.strip() for l in body.split('\n')
             if l.strip() and not l.strip().startswith('//')]
    uniform = re.match(r'^(\d+)\{(.*)\}$', lines[0])
    if uniform:
        value = tuple(float(x) for x in number.findall(uniform.group(2)))
        return [value]*int(uniform.group(1))
    n = int(lines[0])
    assert lines[1] == '(', name
    return [tuple(float(x) for x in number.findall(l)) for l in lines[2:2 + n]]


def positions(case, time):
    return [r[:3] for r in rows(case, time, 'positions')]


failures = []


def check(ok, message):
    print(('ok   ' if ok else 'FAIL ') + message)
    if not ok:
        failures.append(message)


# 1. Contact counts of every step
def contactLines(case):
    # the contacts (the list builds differ: parcels that change processor
    # make the engine rebuild its lists in the parallel run)
    return [l.split(' s, ', 1)[1].split(';')[0]
            for l in open(f'{work}/{case}/log.sinterFoam')
            if l.strip().startswith('DEM:')]


s, p = contactLines('serial'), contactLines('parallel')
pairs = [int(l.split()[0]) for l in s]
walls = [int(l.split()[3]) for l in s]
check(len(s) == 200 and s == p,
      f'contact counts identical in all {len(s)} steps (serial max '
      f'{max(pairs)} particle-particle, {max(walls)} particle-wall)')
check(max(pairs) > 0 and max(walls) > 0, 'contacts of both kinds occurred')


# ... and the list builds of every step by cause ("lists built N times
# (skin n, ...)"): the first build of each run its start and no other,
# the beads' fall makes skin builds (with chemistry every later step is a
# requested build instead), every cause a known one, and N the sum of the
# causes written
def buildCauses(case):
    found = []
    for l in open(f'{work}/{case}/log.sinterFoam'):
        m = re.search(r'lists built (\d+) times(?: \(([^)]*)\))?', l)
        if m and l.strip().startswith('DEM:'):
            causes = {}
            for part in (m.group(2) or '').split(', '):
                if part:
                    name, n = part.rsplit(' ', 1)
                    causes[name] = int(n)
            found.append((int(m.group(1)), causes))
    return found


for case in ('serial', 'parallel'):
    b = buildCauses(case)
    total = collections.Counter()
    for n, c in b:
        total.update(c)
    check(len(b) == 200 and all(n == sum(c.values()) for n, c in b)
          and set(total) <= {'start', 'requested', 'particles changed', 'skin'}
          and b[0][1].get('start') == 1 and total['start'] == 1
          and (total['skin'] > 0 or total['requested'] >= len(b) - 1),
          f'{case}: list builds by cause, the start once and first '
          f'({", ".join(f"{k} {v}" for k, v in sorted(total.items()))})')


# 2. Positions, velocities and temperatures at 0.01 s, parcels matched by
# nearest position. Not at the end: from about 0.011 s the beads land on
# the floor and on each other, bridged, and that stretch amplifies any
# difference by orders of magnitude, by an amount that depends on the
# trajectory - a serial run with its input changed in the twelfth digit
# parts from itself beyond these tolerances by 0.02 s in some modes. By
# 0.01 s the beads have met across the processor boundary (the counts
# above) and 2 ranks differ from serial by round-off only
STATE_TIME = 0.01
xs, xp = positions('serial', STATE_TIME), positions('parallel', STATE_TIME)
us, up = rows('serial', STATE_TIME, 'U'), rows('parallel', STATE_TIME, 'U')
Ts, Tp = rows('serial', STATE_TIME, 'T'), rows('parallel', STATE_TIME, 'T')
check(len(xs) == len(xp) == 48, f'48 beads in both runs ({len(xs)}, {len(xp)})')
used = set()
dx = du = dT = 0.0
for a, ua, Ta in zip(xs, us, Ts):
    k = min(range(len(xp)), key=lambda k: math.dist(a, xp[k]))
    used.add(k)
    dx = max(dx, math.dist(a, xp[k]))
    du = max(du, math.dist(ua, up[k]))
    dT = max(dT, abs(Ta[0] - Tp[k][0]))
check(len(used) == len(xs), 'one-to-one match of the beads')

# ... decomposed, run and reconstructed: no contact record lost or gained,
# bead by bead (the first number of a bead's row is its record count), at
# the end
xs, xp = positions('serial', 0.02), positions('parallel', 0.02)
cs = [int(r[0]) for r in rows('serial', 0.02, 'demContactDuration')]
cp = [int(r[0]) for r in rows('parallel', 0.02, 'demContactDuration')]
twin = [min(range(len(xp)), key=lambda k: math.dist(a, xp[k])) for a in xs]
check(sum(cs) > 0 and sum(cs) == sum(cp)
      and all(cs[i] == cp[k] for i, k in enumerate(twin)),
      f'2 ranks reconstructed: {sum(cp)} contact records, serial {sum(cs)}, '
      f'bead by bead equal')
check(dx <= POSITION_TOL, f'largest position difference at {STATE_TIME:g} s {dx:.3g} m '
      f'(tolerance {POSITION_TOL:g} m)')
xe, xf = positions('serial', 0.02), positions('parallel', 0.02)
print(f'     (at 0.02 s, not checked: largest position difference '
      f'{max(min(math.dist(a, b) for b in xf) for a in xe):.3g} m)')
check(du <= VELOCITY_TOL, f'largest velocity difference {du:.3g} m/s '
      f'(tolerance {VELOCITY_TOL:g} m/s)')
check(dT <= TEMPERATURE_TOL, f'largest temperature difference {dT:.3g} K '
      f'(tolerance {TEMPERATURE_TOL:g} K; bead temperatures {min(t[0] for t in Ts):.6g}'
      f'..{max(t[0] for t in Ts):.6g} K)')

# 3. decomposePar + reconstructPar keep every parcel field exactly
fields = ['U', 'd', 'angularVelocity', 'contactForce', 'contactTorque',
          'demContactPartner', 'demContactSpring', 'demContactDuration',
          'demContactFaceCentre']
for optional in ('demContactBridge', 'demContactBridgeSquare', 'demContactIronBridge',
                 'demContactIronBridgeSquare', 'reductionDegree', 'rho'):
    if os.path.exists(f'{work}/serial/0.02/lagrangian/cloud/{optional}'):
        fields.append(optional)
ironNecks = f'{work}/serial/0.02/lagrangian/cloud/demContactIronBridge'
if os.path.exists(ironNecks):
    x7 = [float(v) for v in re.findall(r'[-+]?\d+\.?\d*[eE][-+]?\d+', open(ironNecks).read())]
    check(any(v > 0 for v in x7), f'iron necks grew: {sum(v > 0 for v in x7)} of the'
          f' contact records, largest x^7 {max(x7, default=0):.3g} m^7')
xo, xr = positions('serial', 0.02), positions('roundTrip', 0.02)
index = {x: k for k, x in enumerate(xr)}
check(len(xo) == len(xr) and all(x in index for x in xo),
      'round trip: every parcel at exactly its position')
records = sum(int(r[0]) for r in rows('serial', 0.02, 'demContactDuration'))
check(records > 0, f'round trip: {records} contact records to carry')
for name in fields:
    a, b = rows('serial', 0.02, name), rows('roundTrip', 0.02, name)
    same = all(a[k] == b[index[x]] for k, x in enumerate(xo) if x in index)
    check(same, f'round trip: {name} identical')

sys.exit(1 if failures else 0)
