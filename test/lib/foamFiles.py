# SPDX-License-Identifier: GPL-3.0-or-later
"""Reading OpenFOAM files in the tests' checks."""
import re
from pathlib import Path


def foam_list(path):
    """Values of an ascii OpenFOAM field or lagrangian list (internal part)."""
    text = Path(path).read_text()
    text = re.sub(r'/\*.*?\*/', '', text, flags=re.S)
    text = re.sub(r'//[^\n]*', '', text)
    body = text.split('FoamFile', 1)[1].split('}', 1)[1]
    m = re.search(r'internalField\s+uniform\s+([-+.eE\d]+)', body)
    if m:
        return [float(m.group(1))]
    m = re.search(r'(\d+)\s*\{\s*([-+.eE\d]+)\s*\}', body)
    if m:
        return [float(m.group(2))] * int(m.group(1))
    m = re.search(r'(\d+)\s*\((.*?)\)', body, flags=re.S)
    values = [float(x) for x in m.group(2).split()]
    assert len(values) == int(m.group(1)), path
    return values


def lagrangian_list(path, kind):
    """A lagrangian field of labels (kind 'i', 32-bit) or scalars ('d'),
    ascii or binary, a list or uniform (N{value})."""
    import struct
    raw = Path(path).read_bytes()
    head_end = raw.index(b'}', raw.index(b'FoamFile')) + 1
    binary = re.search(rb'format\s+binary', raw[:head_end]) is not None
    conv = int if kind == 'i' else float
    m = re.compile(rb'(\d+)\s*([({])').search(raw, head_end)
    n = int(m.group(1))
    if m.group(2) == b'{':
        return [conv(raw[m.end():raw.index(b'}', m.end())])] * n
    if binary:
        size = 4 if kind == 'i' else 8
        return list(struct.unpack(f'<{n}{kind}', raw[m.end():m.end() + size * n]))
    return [conv(v) for v in raw[m.end():raw.index(b')', m.end())].split()]
