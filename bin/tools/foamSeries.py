# SPDX-License-Identifier: GPL-3.0-or-later
"""A function object's time series across restarts.

A run restarted at time t writes its function objects' files under
postProcessing/<function>/<t>/, from its first step after t; merged() joins
them in time, the rows of a later start replacing those from its first row
on (a run repeated after a stop). The earlier run's row at t itself, the
state the restart began from, is kept."""
import glob
import os

import numpy as np


def merged(case, function, name):
    """Rows of postProcessing/<function>/*/<name>, later starts overriding,
    or None if there are none"""
    parts = []
    for d in glob.glob(os.path.join(case, 'postProcessing', function, '*')):
        path = os.path.join(d, name)
        if os.path.exists(path):
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
