# SPDX-License-Identifier: GPL-3.0-or-later
"""The defluidization flag of the bedPressureDrop function object, read
off a kept series of Δp/(W/A) (a summary's pressureDrop.dat):

    flaggedAt(t, ratio, after)  the first time after `after` + WINDOW at
                                which the mean of Δp/(W/A) over the last
                                WINDOW seconds is below RATIO and its
                                standard deviation below STD, or None
    frozenAt(t, ratio, after)   the same for a frozen bed: the standard
                                deviation below STD, the mean RATIO or
                                more (the gas carries the still bed)
    moving(t, x, width)         the mean and STD of x over the window of
                                `width` seconds ending at each sample

RATIO and STD are the function object's ratioBelow and stdBelow
defaults; its window (0.2 s by default) and its `duration` are not
applied here: a kept series flags over WINDOW, at the first sample."""
import numpy as np

RATIO = 0.8
STD = 0.02
WINDOW = 0.1            # [s]


def moving(t, x, width):
    means, stds = np.empty(len(t)), np.empty(len(t))
    j = 0
    for i in range(len(t)):
        while t[j] < t[i] - width + 1e-12:
            j += 1
        means[i] = x[j:i + 1].mean()
        stds[i] = x[j:i + 1].std()
    return means, stds


def flaggedAt(t, ratio, after):
    m, s = moving(t, ratio, WINDOW)
    f = (t > after + WINDOW) & (m < RATIO) & (s < STD)
    return t[f][0] if f.any() else None


def frozenAt(t, ratio, after):
    m, s = moving(t, ratio, WINDOW)
    f = (t > after + WINDOW) & (m >= RATIO) & (s < STD)
    return t[f][0] if f.any() else None
