# SPDX-License-Identifier: GPL-3.0-or-later
"""A number of a case-settings file (caseSettings.*: `key value;` lines,
`#include "file"` lines read in place, the last value of a key in a file
being its value, as in an OpenFOAM dictionary; an included file that is
not there is passed over, as OpenFOAM passes it over with a warning: the
settings files of validation/ include the tutorial's, which sit beside
them only in a case):

    setting(key, *paths)   the value of key in the first of paths that
                           sets it; exits naming the key and the files
                           when none does"""
import os
import re
import sys


def _value(key, path, pattern):
    """key's last value in path and the files it includes, or None"""
    value = None
    with open(path) as f:
        for line in f:
            inc = re.match(r'\s*#include\s+"([^"]+)"', line)
            if inc:
                sub = os.path.join(os.path.dirname(path), inc.group(1))
                if os.path.isfile(sub):
                    sub = _value(key, sub, pattern)
                    value = sub if sub is not None else value
                continue
            m = pattern.match(line)
            if m:
                value = float(m.group(1))
    return value


def setting(key, *paths):
    pattern = re.compile(r'\s*%s\s+([-+.eE\d]+)\s*;' % re.escape(key))
    for path in paths:
        value = _value(key, path, pattern)
        if value is not None:
            return value
    sys.exit(f'no {key} in {" or ".join(paths)}')
