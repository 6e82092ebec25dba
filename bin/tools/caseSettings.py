# SPDX-License-Identifier: GPL-3.0-or-later
"""A number of a case-settings file (caseSettings.*: `key value;` lines):

    setting(key, *paths)   the value of key in the first of paths that
                           sets it; exits naming the key and the files
                           when none does"""
import re
import sys


def setting(key, *paths):
    pattern = re.compile(r'^%s\s+([-+.eE\d]+)\s*;' % re.escape(key))
    for path in paths:
        with open(path) as f:
            for line in f:
                m = pattern.match(line)
                if m:
                    return float(m.group(1))
    sys.exit(f'no {key} in {" or ".join(paths)}')
