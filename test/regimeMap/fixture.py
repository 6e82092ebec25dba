#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Made-up summaries for validation/regimeMap/classify, and the check.
    fixture.py MAPDIR                 write MAPDIR/summaries/tiny/<T>K/
    fixture.py --check MAPDIR LOG     check MAPDIR/regimeMap.dat, .png

Powder tiny at 773.15 ... 1273.15 K every 50 K, bridges from 0.5 s, end
2.5 s (as caseSettings.regimeMap); a second realisation (seed 2, the run
<T>K-s2) at four temperatures. Δp/(W/A) every 1 ms, fluctuating as a
bubbling bed (STD 0.08) before activation and as each regime after:
  stable       Δp as before, largest agglomerate 0.05
  unstable     by a drop: Δp/(W/A) 0.1 lower from 1.5 s on, still
               fluctuating; by agglomerates: Δp as before, largest 0.5
  frozen       a lifted block: Δp/(W/A) 1.1 from 1 s on, STD 0.003,
               largest agglomerate 0.98
  defluidized  Δp/(W/A) 0.7 from 1 s on, STD 0.005
made as
  T [K]      seed 1                   seed 2
  773.15     stable                   unstable (drop): out of order for T_t
  823.15     stable
  873.15     stable                   unstable (drop)
  923.15     unstable (drop)          unstable (agglomerates)
  973.15     unstable (agglomerates)
  1023.15    unstable (agglomerates)  frozen
  1073.15    frozen                   defluidized
  1123.15    stopped at 2 s: left out
  >= 1173.15 defluidized
Expected: T_t between 823.15 and 923.15 K (600+-50 degC; 773.15 K seed 2
out of order), T_f between 973.15 and 1073.15 K (750+-50 degC), T_d
between 1023.15 and 1173.15 K (825+-75 degC: 1123.15 K left out)."""
import os
import sys

import numpy as np

TEMPERATURES = [773.15 + 50*i for i in range(11)]
MADE = {(773.15, 2): 'unstableDrop', (873.15, 2): 'unstableDrop',
        (923.15, 1): 'unstableDrop', (923.15, 2): 'unstableAgglomerates',
        (973.15, 1): 'unstableAgglomerates',
        (1023.15, 1): 'unstableAgglomerates', (1023.15, 2): 'frozen',
        (1073.15, 1): 'frozen', (1073.15, 2): 'defluidized'}
STOPPED = (1123.15, 1)


def made(T, seed):
    """The regime run (T, seed) is made in, or None if it is not made"""
    if (T, seed) in MADE:
        return MADE[(T, seed)]
    if seed != 1:
        return None
    if T <= 873.15:
        return 'stable'
    return 'defluidized'


def regime(T, seed):
    return {'unstableDrop': 'unstable',
            'unstableAgglomerates': 'unstable'}.get(made(T, seed),
                                                    made(T, seed))


def runs():
    return [(T, s) for T in TEMPERATURES for s in (1, 2) if made(T, s)]


def write(mapdir):
    rng = np.random.default_rng(3)
    for T, seed in runs():
        name = '%.2fK' % T + ('' if seed == 1 else '-s%d' % seed)
        d = os.path.join(mapdir, 'summaries', 'tiny', name)
        os.makedirs(d, exist_ok=True)
        end = 2.0 if (T, seed) == STOPPED else 2.5
        t = np.arange(1, int(round(end*1000)) + 1)*1e-3
        r = 1 + 0.08*rng.standard_normal(len(t))
        largest = np.full(len(t), 0.05)
        late = t >= 1.0
        kind = made(T, seed)
        if kind == 'unstableDrop':
            r[t >= 1.5] -= 0.1
        elif kind == 'unstableAgglomerates':
            largest[late] = 0.5
        elif kind == 'frozen':
            r[late] = 1.1 + 0.003*rng.standard_normal(late.sum())
            largest[late] = 0.98
        elif kind == 'defluidized':
            r[late] = 0.7 + 0.005*rng.standard_normal(late.sum())
        wa = 245.0
        with open(os.path.join(d, 'pressureDrop.dat'), 'w') as f:
            f.write('# time dp W/A dp/(W/A) voidage\n')
            for ti, ri in zip(t, r):
                f.write('%g %g %g %g 0.5\n' % (ti, ri*wa, wa, ri))
        with open(os.path.join(d, 'agglomerates.dat'), 'w') as f:
            f.write('# time agglomerates fraction massFraction largest meanSize\n')
            for ti, li in zip(t[::10], largest[::10]):
                f.write('%g 3 %g %g %g 10\n' % (ti, li, li, li))


def check(mapdir, log):
    ok = True

    def report(good, what):
        nonlocal ok
        print(('ok   ' if good else 'FAIL ') + what)
        ok = ok and good

    rows, crit = {}, None
    for line in open(os.path.join(mapdir, 'regimeMap.dat')):
        f = line.split()
        if len(f) >= 10 and f[0] == 'tiny' and not line.startswith('#'):
            rows[(float(f[1]), int(f[3]))] = f[-1]
        if line.startswith('# tiny'):
            crit = f
    for T, seed in runs():
        what = f'{T} K seed {seed}'
        if (T, seed) == STOPPED:
            report((T, seed) not in rows, f'{what} (not at the end) left out')
        else:
            report(rows.get((T, seed)) == regime(T, seed),
                   f'{what}: {rows.get((T, seed))} (made {regime(T, seed)})')
    report('tiny 1123.15 K' in open(log).read(),
           'the unfinished run is named in the log')
    for col, what, expected in ((2, 'T_t', '600+-50'), (5, 'T_d', '825+-75'),
                                (8, 'T_f', '750+-50'), (9, 'out of order', 'T_t:500')):
        got = crit[col] if crit and len(crit) > col else None
        report(got == expected, f'{what} {got} (expected {expected})')
    # the force balance of this tree (defluidizationMap run by classify)
    # next to Table 2.5's, tiny powder: 594 and 993 degC, within 5 K
    for col, what in ((4, 'T_t'), (7, 'T_d')):
        try:
            thesis, here = (float(v) for v in crit[col].split('/'))
            good = abs(here - thesis) <= 5 and thesis in (594, 993)
        except (TypeError, ValueError, IndexError):
            good = False
        report(good, f'force balance {what} (Table 2.5/here) '
                     f'{crit[col] if crit else None} degC')
    png = os.path.join(mapdir, 'regimeMap.png')
    if os.path.exists(png):
        import matplotlib.image as mpimg
        img = mpimg.imread(png)
        report(img.std() > 0.01, f'regimeMap.png not blank (pixel STD {img.std():.3f})')
    else:
        report(False, 'regimeMap.png written')
    return 0 if ok else 1


if __name__ == '__main__':
    if sys.argv[1] == '--check':
        sys.exit(check(sys.argv[2], sys.argv[3]))
    write(sys.argv[1])
