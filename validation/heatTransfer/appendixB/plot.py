#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""App. B figure: (T_p - T_p0)/(T_w - T_p0) against time, simulated (marks)
and analytic (lines), direct and indirect particle-wall conduction.
   plot.py RESULTS_DIR OUT.png"""
import sys
from pathlib import Path

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt


def read(path):
    rows = [[float(x) for x in l.split()] for l in open(path)
            if not l.startswith('#')]
    return [r[0] for r in rows], [r[1] for r in rows], [r[2] for r in rows]


def main():
    results, out = Path(sys.argv[1]), sys.argv[2]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    panels = [
        ('wallDirect', 'direct (Batchelor-O\'Brien), Fig B.5',
         lambda f: f'overlap {f} $r_p$'),
        ('wallIndirect', 'indirect (Rong-Horio), Fig B.2-B.4',
         lambda f: (f'gap {-f} $r_p$' if f < 0 else
                    ('touching' if f == 0 else f'overlap {f} $r_p$'))),
    ]
    worst = 0
    for ax, (prefix, title, label) in zip(axes, panels):
        files = sorted(results.glob(prefix + '_*.dat'),
                       key=lambda p: float(p.stem.split('_', 1)[1]))
        for i, path in enumerate(files):
            f = float(path.stem.split('_', 1)[1])
            t, sim, exact = read(path)
            worst = max(worst, max(abs(a - b) for a, b in zip(sim, exact)))
            colour = f'C{i}'
            ax.plot(t, exact, '-', color=colour, lw=1)
            ax.plot(t[::5], sim[::5], 'o', color=colour, ms=3.5,
                    label=label(f))
        ax.set_title(title, fontsize=10)
        ax.set_xlabel('t [s]')
        ax.set_ylabel(r'$(T_p - T_{p,0})/(T_w - T_{p,0})$')
        ax.set_ylim(0, 1.02)
        ax.legend(fontsize=8)
    fig.suptitle('1 mm glass particle on aluminium: DEM engine (marks)'
                 ' against eq B.1-B.4 (lines)', fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)

    # The figure is not blank, and the engine follows the analytic
    # solutions (the tests' tolerance, 1e-4 of the initial difference)
    import matplotlib.image
    pixels = matplotlib.image.imread(out)
    blank = float(pixels.std()) == 0.0
    print(f'{out}: largest difference from the analytic {worst:.2e}'
          f' (tolerance 1e-4); image {"blank" if blank else "not blank"}')
    return 1 if blank or worst > 1e-4 else 0


if __name__ == '__main__':
    sys.exit(main())
