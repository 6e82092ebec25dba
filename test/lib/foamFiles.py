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
