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
<name>.dat. That file is the later attempt and is taken instead.

A run killed while writing a line leaves that line short: rows with fewer
numbers than the file's widest row are left out (and counted)."""
import glob
import os
import re
import sys

import numpy as np


def rows(path):
    """(array of the file's complete numeric rows, number of rows left out)"""
    parsed = []
    with open(path) as f:
        for line in f:
            if line.startswith('#') or not line.strip():
                continue
            try:
                parsed.append([float(x) for x in line.split()])
            except ValueError:
                parsed.append([])
    if not parsed:
        return np.empty((0, 0)), 0
    width = max(len(r) for r in parsed)
    kept = [r for r in parsed if len(r) == width]
    return np.array(kept), len(parsed) - len(kept)


def latestAttempt(directory, name):
    """The file of the last run started at this directory's time, or None"""
    stem, ext = os.path.splitext(name)
    again = os.path.join(directory,
                         stem + '_' + os.path.basename(directory) + ext)
    for path in (again, os.path.join(directory, name)):
        if os.path.exists(path):
            return path
    return None


def startTimes(functionDir):
    """The start-time directories of postProcessing/<function>, as
    (time, path) in time order"""
    found = []
    for d in glob.glob(os.path.join(functionDir, '*')):
        try:
            found.append((float(os.path.basename(d)), d))
        except ValueError:
            continue
    return sorted(found)


def seriesName(functionDir):
    """The one file name written under every start time of
    postProcessing/<function> (a killed attempt's <name>_<t>.dat aside);
    raises ValueError if there is none or more than one"""
    names = set()
    for _, d in startTimes(functionDir):
        t = re.escape(os.path.basename(d))
        for path in glob.glob(os.path.join(d, '*.dat')):
            base = os.path.basename(path)
            if not re.search('_' + t + r'\.dat$', base):
                names.add(base)
    if len(names) != 1:
        raise ValueError(
            f'{functionDir}: expected one .dat file per start time, found '
            + (', '.join(sorted(names)) if names else 'none'))
    return names.pop()


def mergedDirectory(functionDir, name=None):
    """(rows of functionDir/*/<name> joined across restarts, or None;
    incomplete rows left out). name defaults to seriesName(functionDir)"""
    if name is None:
        name = seriesName(functionDir)
    series = None
    dropped = 0
    for _, d in startTimes(functionDir):
        path = latestAttempt(d, name)
        if path is None:
            continue
        part, short = rows(path)
        dropped += short
        if part.size == 0:
            continue
        if series is not None:
            if part.shape[1] != series.shape[1]:
                raise ValueError(f'{path}: {part.shape[1]} columns, the '
                                 f'earlier start times {series.shape[1]}')
            series = np.vstack([series[series[:, 0] < part[0, 0] - 1e-12], part])
        else:
            series = part
    return series, dropped


def series(path, name=None):
    """(rows, rows left out) of a file, or of a postProcessing/<function>
    directory joined across restarts (mergedDirectory; rows None if it
    has none)"""
    if os.path.isdir(path):
        return mergedDirectory(path, name)
    return rows(path)


def seriesOrExit(path, tool, columns, expected, name=None, label=None):
    """series(path, name) for a command-line tool: exits with a message
    naming the tool and the path (or label) if it cannot be read, holds no
    rows or has fewer than `columns` numbers per row (`expected` says
    what); says how many incomplete lines were left out"""
    try:
        d, dropped = series(path, name)
    except (OSError, ValueError) as e:
        sys.exit(f"{tool}: cannot read {label or path}: {e}")
    if dropped:
        print(f"{tool}: left out {dropped} incomplete line(s) of {path}")
    if d is None or d.size == 0:
        sys.exit(f"{tool}: no data in {path}")
    if d.shape[1] < columns:
        sys.exit(f"{tool}: {path} has {d.shape[1]} columns, {expected}")
    return d


def windowOrExit(t, t0, t1, tool):
    """(T0, T1, mask of T0 <= t <= T1) for a tool's --from/--to (None: the
    series' first or last time); exits with a message naming the tool if
    both are given the wrong way round or the window holds no row"""
    if t0 is not None and t1 is not None and t1 < t0:
        sys.exit(f"{tool}: --to {t1:g} is before --from {t0:g}")
    t0 = t[0] if t0 is None else t0
    t1 = t[-1] if t1 is None else t1
    w = (t >= t0) & (t <= t1)
    if not w.any():
        sys.exit(f"{tool}: no evaluation in {t0:g} <= t <= {t1:g}"
                 f" (the series runs {t[0]:g} to {t[-1]:g})")
    return t0, t1, w


def merged(case, function, name):
    """Rows of case/postProcessing/<function>/*/<name>, later starts
    overriding, or None if there are none"""
    return mergedDirectory(os.path.join(case, 'postProcessing', function), name)[0]
