#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Made-up summaries for validation/regimeMap/classify, and the check.
    fixture.py MAPDIR                 write MAPDIR/summaries/tiny/<T>K/
    fixture.py --check MAPDIR LOG     check MAPDIR/regimeMap.dat, .png

Powder tiny at 773.15 ... 1273.15 K every 50 K, bridges from 0.5 s, end
2.5 s (as caseSettings.regimeMap). Δp/(W/A) every 1 ms, fluctuating as a
bubbling bed (STD 0.08) before activation and as each regime after:
  <= 873.15 K              stable: as before, largest agglomerate 0.05
  923.15, 973.15 K         unstable: Δp/(W/A) 0.1 lower from 1.5 s on,
                           still fluctuating
  1023.15 K                unstable: Δp as before, largest agglomerate 0.5
  1073.15 K                frozen: a lifted block, Δp/(W/A) 1.1 from 1 s
                           on, STD 0.003, largest agglomerate 0.98
  >= 1123.15 K             defluidized: Δp/(W/A) 0.7 from 1 s on, STD 0.005
  1123.15 K                a run stopped at 2 s: left out
Expected: T_t 898.15 K (625 degC), T_f 1048.15 K (775 degC), T_d
1123.15 K (850 degC: between 1073.15 and 1173.15 K, 1123.15 K left
out)."""
import os
import sys

import numpy as np

TEMPERATURES = [773.15 + 50*i for i in range(11)]


def regime(T):
    if T <= 873.15:
        return 'stable'
    if T <= 1023.15:
        return 'unstable'
    if T == 1073.15:
        return 'frozen'
    return 'defluidized'


def write(mapdir):
    rng = np.random.default_rng(3)
    for T in TEMPERATURES:
        d = os.path.join(mapdir, 'summaries', 'tiny', '%.2fK' % T)
        os.makedirs(d, exist_ok=True)
        end = 2.0 if T == 1123.15 else 2.5
        t = np.arange(1, int(round(end*1000)) + 1)*1e-3
        r = 1 + 0.08*rng.standard_normal(len(t))
        largest = np.full(len(t), 0.05)
        if T in (923.15, 973.15):
            r[t >= 1.5] -= 0.1
        elif T == 1023.15:
            largest[t >= 1.0] = 0.5
        elif T == 1073.15:
            late = t >= 1.0
            r[late] = 1.1 + 0.003*rng.standard_normal(late.sum())
            largest[late] = 0.98
        elif T >= 1123.15:
            late = t >= 1.0
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
        if len(f) >= 9 and f[0] == 'tiny' and not line.startswith('#'):
            rows[float(f[1])] = f[-1]
        if line.startswith('# tiny'):
            crit = f
    for T in TEMPERATURES:
        if T == 1123.15:
            report(T not in rows, f'{T} K (not at the end) left out')
        else:
            report(rows.get(T) == regime(T),
                   f'{T} K: {rows.get(T)} (made {regime(T)})')
    report('tiny 1123.15 K' in open(log).read(),
           'the unfinished run is named in the log')
    report(crit is not None and crit[2] == '625',
           f'T_t {crit[2] if crit else None} degC (expected 625)')
    report(crit is not None and crit[5] == '850',
           f'T_d {crit[5] if crit else None} degC (expected 850)')
    report(crit is not None and crit[-1] == '775',
           f'T_f {crit[-1] if crit else None} degC (expected 775)')
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
