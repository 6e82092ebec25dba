#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The settled bed of a sinterFoam run as a DPMFoam (kinematic colliding)
cloud:  convertSettled.py SRC_TIME DEST_TIME

Reads SRC_TIME/lagrangian/cloud (sinterFoam's cloud, binary or ascii) and
writes DEST_TIME/lagrangian/kinematicCloud and its uniform/ entry, in
ascii: the positions (the same mesh, so the same cells), the kinematic
parcel fields (d, U, rho, nParticle, ...) as they are, the angular momentum
from sinterFoam's angular velocity (solid sphere: I = m d^2/10), and the
colliding-parcel fields DPMFoam must read but sinterFoam does not have: no
force or torque yet, and no contact history (pairCollision's tangential
springs start from zero).
"""
import math
import re
import struct
import sys
from pathlib import Path

NCOMP = {'label': 1, 'scalar': 1, 'vector': 3, 'position': 4}


def _header(data):
    start = data.index(b'FoamFile')
    end = data.index(b'}', start)
    text = data[start:end].decode()
    fmt = re.search(r'format\s+(\w+)', text).group(1)
    arch = re.search(r'label=(\d+)', text)
    return fmt, int(arch.group(1)) if arch else 32, end + 1


def _skip(data, k):
    """Past white space and comments."""
    while True:
        while k < len(data) and data[k:k + 1].isspace():
            k += 1
        if data.startswith(b'//', k):
            k = data.index(b'\n', k)
        elif data.startswith(b'/*', k):
            k = data.index(b'*/', k) + 2
        else:
            return k


def _numbers(text):
    return [float(x) for x in re.findall(rb'[-+]?[\d.]+(?:[eE][-+]?\d+)?', text)]


def read(path, kind):
    """The list in a lagrangian field file: a list of numbers (label,
    scalar) or of tuples (vector; position: x, y, z, cell)."""
    data = path.read_bytes()
    fmt, labelBits, k = _header(data)
    k = _skip(data, k)
    m = re.match(rb'\d+', data[k:])
    n = int(m.group(0))
    k = _skip(data, k + m.end())
    opener = data[k:k + 1]
    k += 1
    nc = NCOMP[kind]
    lab = 'i' if labelBits == 32 else 'q'
    if fmt == 'binary':
        if kind == 'position':
            # each: ( x y z [scalars] celli [label] ) and a newline
            size = 24 + labelBits // 8
            values = []
            for _ in range(n):
                k = _skip(data, k)
                assert data[k:k + 1] == b'(', path
                x, y, z = struct.unpack_from('<3d', data, k + 1)
                (cell,) = struct.unpack_from('<' + lab, data, k + 25)
                values.append((x, y, z, cell))
                k += size + 2
            return values
        code = lab if kind == 'label' else 'd'
        count = 1 if opener == b'{' else n
        flat = struct.unpack_from('<%d%s' % (count*nc, code), data, k)
    else:
        close = b'}' if opener == b'{' else b')'
        # the list ends at the last closing bracket before the footer
        body = data[k:data.rindex(close)]
        flat = _numbers(body)
        if kind == 'label':
            flat = [int(x) for x in flat]
        if kind == 'position':
            flat = [int(x) if (i % 4 == 3) else x for i, x in enumerate(flat)]
    items = [flat[i] if nc == 1 else tuple(flat[i:i + nc])
             for i in range(0, len(flat), nc)]
    if opener == b'{':
        items = items * n
    assert len(items) == n, (path, len(items), n)
    return items


def _fmt(value):
    if isinstance(value, str):
        return value
    if isinstance(value, tuple):
        return '(' + ' '.join(_fmt(v) for v in value) + ')'
    if isinstance(value, int):
        return str(value)
    return '%.17g' % value


def write(path, cls, values, uniform=None, n=None):
    """An ascii list file; uniform: the single value of all n entries."""
    head = ('// SPDX-License-Identifier: GPL-3.0-or-later\n'
            '// Written by convertSettled.py from a sinterFoam cloud\n'
            'FoamFile { version 2.0; format ascii; class %s; object %s; }\n'
            % (cls, path.name))
    with path.open('w') as out:
        out.write(head)
        if uniform is not None:
            out.write('%d{%s}\n' % (n, uniform))
            return
        out.write('%d\n(\n' % len(values))
        for v in values:
            out.write(_fmt(v) + '\n')
        out.write(')\n')


def main():
    src = Path(sys.argv[1]) / 'lagrangian' / 'cloud'
    dest = Path(sys.argv[2]) / 'lagrangian' / 'kinematicCloud'
    dest.mkdir(parents=True, exist_ok=True)

    positions = read(src / 'positions', 'position')
    n = len(positions)
    write(dest / 'positions', 'Cloud<basicKinematicCollidingParcel>',
          ['(%.17g %.17g %.17g) %d' % p for p in positions])

    fields = {}
    for name, kind, cls in (
            ('origProcId', 'label', 'labelField'),
            ('origId', 'label', 'labelField'),
            ('active', 'label', 'labelField'),
            ('typeId', 'label', 'labelField'),
            ('nParticle', 'scalar', 'scalarField'),
            ('d', 'scalar', 'scalarField'),
            ('dTarget', 'scalar', 'scalarField'),
            ('rho', 'scalar', 'scalarField'),
            ('age', 'scalar', 'scalarField'),
            ('tTurb', 'scalar', 'scalarField'),
            ('U', 'vector', 'vectorField'),
            ('UTurb', 'vector', 'vectorField')):
        fields[name] = read(src / name, kind)
        assert len(fields[name]) == n, name
        write(dest / name, cls, fields[name])

    # pairCollision's sub-step count depends on the fastest bead's speed:
    # keep the spin as well
    if (src / 'angularVelocity').exists():
        omega = read(src / 'angularVelocity', 'vector')
    else:
        omega = [(0.0, 0.0, 0.0)]*n
    L = []
    for w, d, rho in zip(omega, fields['d'], fields['rho']):
        inertia = 0.1*rho*math.pi/6*d**3*d**2
        L.append(tuple(inertia*c for c in w))
    write(dest / 'angularMomentum', 'vectorField', L)
    for name in ('f', 'torque'):
        write(dest / name, 'vectorField', None, '(0 0 0)', n)

    # no contact history: each parcel's lists empty, in the compact format
    # (offsets of the n sub-lists, then the elements)
    for name, cls in (
            ('PairAccessed', 'labelFieldCompactField'),
            ('PairOrigProcOfOther', 'labelFieldCompactField'),
            ('PairOrigIdOfOther', 'labelFieldCompactField'),
            ('PairData', 'vectorFieldCompactField'),
            ('WallAccessed', 'labelFieldCompactField'),
            ('WallPRel', 'vectorFieldCompactField'),
            ('WallData', 'vectorFieldCompactField')):
        path = dest / ('collisionRecords' + name)
        write(path, cls, None, '0', n + 1)
        with path.open('a') as out:
            out.write('0()\n')

    # positions as x y z and cell, not barycentric coordinates; new parcels
    # (none here) would be numbered on from n
    uniform = Path(sys.argv[2]) / 'uniform' / 'lagrangian' / 'kinematicCloud'
    uniform.mkdir(parents=True, exist_ok=True)
    (uniform / 'cloudProperties').write_text(
        '// SPDX-License-Identifier: GPL-3.0-or-later\n'
        '// Written by convertSettled.py from a sinterFoam cloud\n'
        'FoamFile { version 2.0; format ascii; class dictionary; '
        'object cloudProperties; }\n'
        'geometry positions;\n'
        'processor0 { particleCount %d; }\n' % n)

    print('%d parcels: %s -> %s' % (n, src, dest))


if __name__ == '__main__':
    main()
