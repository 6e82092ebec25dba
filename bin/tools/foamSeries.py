# SPDX-License-Identifier: GPL-3.0-or-later
"""A function object's time series across restarts.

A run restarted at time t writes its function objects' files under
postProcessing/<function>/<t>/, from its first step after t; merged() joins
them in time, the rows of a later start replacing those from its first row
on (a run repeated after a stop). The earlier run's row at t itself, the
state the restart began from, is kept.

A run killed before it wrote its first time is started again from the same
time t: its files are already in postProcessing/<function>/<t>/, and
OpenFOAM then names the new run's file <name>_<t>.dat beside the old
<name>.dat. That file is the later attempt and is taken instead."""
import glob
import os

import numpy as np


def latestAttempt(directory, name):
    """The file of the last run started at this directory's time, or None"""
    stem, ext = os.path.splitext(name)
    again = os.path.join(directory,
                         stem + '_' + os.path.basename(directory) + ext)
    for path in (again, os.path.join(directory, name)):
        if os.path.exists(path):
            return path
    return None


def merged(case, function, name):
    """Rows of postProcessing/<function>/*/<name>, later starts overriding,
    or None if there are none"""
    parts = []
    for d in glob.glob(os.path.join(case, 'postProcessing', function, '*')):
        path = latestAttempt(d, name)
        if path is not None:
            parts.append((float(os.path.basename(d)), path))
    rows = None
    for start, path in sorted(parts):
        d = np.loadtxt(path, comments='#', ndmin=2)
        if d.size == 0:
            continue
        if rows is not None:
            rows = np.vstack([rows[rows[:, 0] < d[0, 0] - 1e-12], d])
        else:
            rows = d
    return rows
