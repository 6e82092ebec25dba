# SPDX-License-Identifier: GPL-3.0-or-later
"""Checking the `key value` lines the project's bin/ tools print."""


def key_values(*paths):
    """The `key value` lines of the files, later files overriding"""
    got = {}
    for path in paths:
        for line in open(path):
            k = line.split()
            if len(k) == 2:
                got[k[0]] = k[1]
    return got


def failed_keys(got, expect, source, floor=0.0, rel=1e-4):
    """Compares each expected key with |got - v| <= rel max(floor, |v|),
    printing one line per key; returns the number that failed"""
    bad = 0
    for k, v in expect.items():
        ok = k in got and abs(float(got[k]) - v) <= rel * max(floor, abs(v))
        print(f"{k}: {got.get(k)} ({source} {v}, relative tolerance {rel:g}):"
              f" {'ok' if ok else 'FAIL'}")
        bad += not ok
    return bad
