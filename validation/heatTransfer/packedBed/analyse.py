#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The packed bed's conductivity: what carries the heat, and Zehner-Schluender.

    analyse.py CASE SUMMARY [FIGURE]

From the last time of CASE:
  - the bead temperatures against height, a straight line fitted in the
    core of the bed (3 d above the plate to 3 d below the bed's top), and
    the solids fraction of that slab;
  - Q, the heat through the bed: what the hot plate gives (wallHeatFlow)
    and what leaves through the cold top, averaged over the last 0.05 s;
  - k_DEM = Q/(A |dT/dz|), the bed's effective conductivity;
  - the heat the contact network carries through three horizontal planes
    of the core, 4 smoothing lengths or more below the bed's surface,
    recomputed here from the written bead positions and
    temperatures with the laws of the case (an implementation of its own:
    the direct path Batchelor-O'Brien is negligible at these loads and left
    out; the gas lens of the case's indirect law, pair form, by quadrature:
    Rong-Horio, or lensSolidSeries with the beads' solid in series), plus
    the gas's own conduction eps k_eff dT/dz (eq 4.6);
  - k_b of Zehner-Schluender (eq 4.19-4.23, no kinetic part: the beads
    rest) at the slab's voidage, with the case's gas and bead
    conductivities.
Writes SUMMARY (key value lines) and, given FIGURE, the temperature profile.

Checks (exit status 1 if one fails):
  steady       the heat in at the bottom and out at the top agree within
               1 %, and the heat in changes by less than 1 % over the last
               0.05 s
  linear       the line explains more than 99 % of the beads' temperature
               variance in the core
  equilibrium  the gas in the core cells is within 2 % of the core's
               temperature difference of the beads' line
  network      at each plane the contacts and the gas carry Q within 3 %:
               the beads exchange heat with the gas where they are, and no
               heat crosses the bed through the gas-particle exchange
  zehnerSchlunder  (lensSolidSeries only) k_DEM within 20 % of k_b: a
               particle-scale law against a continuum correlation fitted
               to measured beds; the tolerance was set before the run
With Rong-Horio the ratio k_DEM/k_b is reported, not checked: its beads
are isothermal up to their surface, which glass in air (k_s/k_f = 54) is
not, and it conducts more than Zehner-Schluender (README).
"""
import math
import re
import sys
from pathlib import Path

import numpy as np


def entries(text):
    text = re.sub(r'//[^\n]*', '', text)
    return {k: float(v) for k, v in
            re.findall(r'(?:^|(?<=[;{]))\s*(\w+)\s+([-+.eE\d]+)\s*;',
                       text, re.M)}


def block(text, name):
    return re.search(r'\b' + name + r'\s*\{(.*?)\}', text, re.S).group(1)


def foam_list(path):
    """The values of an ascii OpenFOAM list file: scalars, or vectors each
    maybe followed by a cell label (positions)."""
    text = path.read_text()
    m = re.search(r'\n(\d+)\s*\n\(', text)
    n = int(m.group(1))
    inner = text[m.end():text.rindex(')')]
    if '(' in inner:
        vals = [tuple(map(float, v.split()))
                for v in re.findall(r'\(([^()]*)\)', inner)]
    else:
        vals = [float(v) for v in inner.split()]
    assert len(vals) == n, (path, len(vals), n)
    return np.array(vals)


def internal_field(path):
    text = path.read_text()
    m = re.search(r'internalField\s+nonuniform\s+List<scalar>\s*\n?(\d+)\s*'
                  r'\n?\(', text)
    n = int(m.group(1))
    return np.array([float(v) for v in text[m.end():].split(')')[0].split()
                     ][:n])


def zehner_schlunder(eps, kf, ks):
    A = ks / kf
    B = 1.25 * ((1 - eps) / eps) ** (10.0 / 9.0)
    w = 7.26e-3
    r = B / A
    gamma = 2 / (1 - r) * ((A - 1) / (1 - r) ** 2 * r * math.log(A / B)
                           - (B - 1) / (1 - r) - 0.5 * (B + 1))
    return kf * ((1 - math.sqrt(1 - eps))
                 + math.sqrt(1 - eps) * (w * A + (1 - w) * gamma))


def lens_pair_conductance(gap, r, kf, lens, s, ks, n=4000):
    """Through the gas lens between two equal spheres of radius r at
    surface gap `gap` (negative: overlap): the plane midway is a wall at
    gap/2 for each, the gas between them at ring radius rho is
    2 l = 2 (r + gap/2 - sqrt(r^2 - rho^2)) thick, at least s (Rong-Horio;
    s = 0 for lensSolidSeries), in series with the solid of both spheres
    from their centre planes, 2 sqrt(r^2 - rho^2) (lensSolidSeries; ks =
    inf for Rong-Horio): G = 2 pi int rho/(max(2 l, s)/k_f + 2 u/k_s) drho
    from the contact circle to r_out = sqrt(r_lens^2 - (r + gap/2)^2) (at
    most r), by the midpoint rule."""
    a = r + 0.5 * gap
    G = np.zeros_like(gap)
    on = a < lens
    a = a[on]
    rOut = np.minimum(np.sqrt(lens ** 2 - a ** 2), r)
    rIn = np.where(a < r, np.sqrt(np.maximum(r * r - a * a, 0)), 0.0)
    t = (np.arange(n) + 0.5) / n
    rho = rIn[:, None] + (rOut - rIn)[:, None] * t[None, :]
    u = np.sqrt(np.maximum(r * r - rho ** 2, 0))
    thick = 2 * (a[:, None] - u)
    resist = np.maximum(thick, s) / kf + 2 * u / ks
    integral = (rho / resist).sum(axis=1) * (rOut - rIn) / n
    G[on] = 2 * math.pi * integral
    return G


def network_flux(x, T, planes, r, kf, lens, s, ks):
    """Heat the lens conduction carries up through each plane z = planes[k]
    [W], from every pair within the lens."""
    reach = 2 * lens
    cell = np.floor(x / reach).astype(int)
    buckets = {}
    for i, c in enumerate(map(tuple, cell)):
        buckets.setdefault(c, []).append(i)
    I, J = [], []
    for c, members in buckets.items():
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    other = buckets.get((c[0] + dx, c[1] + dy, c[2] + dz))
                    if not other:
                        continue
                    for i in members:
                        for j in other:
                            if j > i:
                                I.append(i)
                                J.append(j)
    I, J = np.array(I), np.array(J)
    dist = np.linalg.norm(x[J] - x[I], axis=1)
    near = dist < reach
    I, J, dist = I[near], J[near], dist[near]
    G = lens_pair_conductance(dist - 2 * r, r, kf, lens, s, ks)
    q = G * (T[I] - T[J])          # from i to j
    out = []
    for zp in planes:
        up = (x[I, 2] < zp) & (x[J, 2] >= zp)
        down = (x[J, 2] < zp) & (x[I, 2] >= zp)
        out.append(q[up].sum() - q[down].sum())
    return out, int(np.sum(dist < 2 * r)), len(dist)


def main():
    case = Path(sys.argv[1])
    summary = Path(sys.argv[2])
    figure = Path(sys.argv[3]) if len(sys.argv) > 3 else None

    s = entries((case / 'system/settings').read_text())
    d, L, H = s['d'], s['L'], s['H']
    mix = (case / 'constant/thermophysicalProperties').read_text()
    Cp = entries(block(mix, 'thermodynamics'))['Cp']
    tr = entries(block(mix, 'transport'))
    kf = Cp * tr['mu'] / tr['Pr']
    mat = (case / 'constant/materialProperties').read_text()
    particle = re.search(r'^particle\s+(\w+)\s*;', mat, re.M).group(1)
    ks = entries(block(mat, particle))['thermalConductivity']
    cloud = (case / 'constant/cloudProperties').read_text()
    law = re.search(r'^\s*indirect\s+(\w+)\s*;', cloud, re.M).group(1)
    if law not in ('RongHorio', 'lensSolidSeries'):
        sys.exit(f'analyse.py: indirect {law} has no quadrature here')
    lensCoeffs = entries(block(cloud, law + 'Coeffs'))
    lens = lensCoeffs['lensRadius'] * 0.5 * d
    sMin = lensCoeffs['minimumDistance'] if law == 'RongHorio' else 0.0
    ksLens = ks if law == 'lensSolidSeries' else math.inf

    times = sorted((p for p in case.iterdir()
                    if re.fullmatch(r'[\d.eE+-]+', p.name) and p.name != '0'),
                   key=lambda p: float(p.name))
    last = times[-1]
    x = foam_list(last / 'lagrangian/cloud/positions')[:, :3]
    T = foam_list(last / 'lagrangian/cloud/T')
    z = x[:, 2]
    zTop = z.max() + 0.5 * d
    z0, z1 = 3 * d, zTop - 3 * d
    core = (z >= z0) & (z <= z1)
    n = int(core.sum())
    slope, intercept = np.polyfit(z[core], T[core], 1)
    fit = slope * z[core] + intercept
    r2 = 1 - np.sum((T[core] - fit) ** 2) / np.sum((T[core] - T[core].mean()) ** 2)
    phi = n * math.pi / 6 * d ** 3 / (L * L * (z1 - z0))
    eps = 1 - phi
    A = L * L

    rows = np.array([[float(v) for v in line.split()]
                     for line in (case / 'postProcessing/wallHeatFlow/0/'
                                  'wallHeatFlow.dat').read_text().splitlines()
                     if line.strip() and not line.startswith('#')])
    window = rows[rows[:, 0] > rows[-1, 0] - 0.05 + 1e-9]
    half = len(window) // 2
    Qin = window[:, 3].mean()
    Qout = -window[:, 6].mean()
    drift = window[half:, 3].mean() - window[:half, 3].mean()
    Q = 0.5 * (Qin + Qout)
    kDEM = Q / (A * abs(slope))
    kZS = zehner_schlunder(eps, kf, ks)

    # The planes 4 smoothing lengths or more below the bed's surface: the
    # heat the top beads give the gas is spread over L in it (the momentum's
    # spreading), and the gas gives a share of it back to the beads below
    coupling = (case / 'constant/couplingProperties').read_text()
    smooth = entries(coupling)['smoothingLength']
    zPlanes = zTop - 4 * smooth
    planes = [z0 + f * (zPlanes - z0) for f in (0.25, 0.5, 0.75)]
    Fnet, nTouch, nPairs = network_flux(x, T, planes, 0.5 * d, kf, lens, sMin,
                                        ksLens)
    Fgas = (1 - math.sqrt(1 - eps)) * kf * abs(slope) * A
    carried = [(f + Fgas) / Q for f in Fnet]

    # Gas in the core cells (uniform blockMesh: x fastest, then y, z)
    Tg = internal_field(last / 'T')
    nz = len(Tg) // 16
    dz = H / nz
    gasDev = 0.0
    for k in range(nz):
        zc = (k + 0.5) * dz
        if z0 + 0.5 * dz <= zc <= z1 - 0.5 * dz:
            gasDev = max(gasDev, abs(Tg[16 * k:16 * (k + 1)].mean()
                                     - (slope * zc + intercept)))
    dTcore = abs(slope) * (z1 - z0)

    checks = {
        'steady': abs(Qin - Qout) / Q < 0.01 and abs(drift) / Q < 0.01,
        'linear': r2 > 0.99,
        'equilibrium': gasDev < 0.02 * dTcore,
        'network': all(abs(c - 1) < 0.03 for c in carried),
    }
    if law == 'lensSolidSeries':
        checks['zehnerSchlunder'] = abs(kDEM / kZS - 1) < 0.2
    out = [
        f'time                {last.name}',
        f'beads               {len(z)}',
        f'bedTop              {zTop:.6g}      # [m]',
        f'coreBeads           {n}     # centres in [{z0:.4g}, {z1:.4g}] m',
        f'voidage             {eps:.5f}',
        f'gradient            {slope:.6g}     # dT/dz [K/m]',
        f'linearFitR2         {r2:.6f}',
        f'Qbottom             {Qin:.6g}      # [W]',
        f'Qtop                {Qout:.6g}      # [W]',
        f'Qdrift              {drift:.4g}      # [W] over the last 0.05 s',
        f'QbottomParticles    {window[:, 2].mean():.6g}      # [W] by contact',
        f'gasDeviation        {gasDev:.4g}      # [K], max over core cells',
        f'lensPairs           {nPairs}     # of which touching {nTouch}',
        f'networkCarries      {" ".join(f"{c:.4f}" for c in carried)}'
        f'      # (contacts + gas)/Q at z = '
        f'{" ".join(f"{p:.4g}" for p in planes)} m',
        f'indirect            {law}',
        f'kf                  {kf:.6g}      # [W/(m K)]',
        f'ks                  {ks:.6g}',
        f'kDEM                {kDEM:.6g}',
        f'kZehnerSchlunder    {kZS:.6g}',
        f'ratio               {kDEM / kZS:.4f}',
    ] + [f'check_{k:<16}{"pass" if v else "FAIL"}' for k, v in checks.items()]
    summary.write_text('\n'.join(out) + '\n')
    print('\n'.join(out))

    if figure:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(5.5, 4.5))
        ax.plot(T, z * 1e3, '.', ms=2, color='0.6', label='beads')
        zl = np.array([z0, z1])
        ax.plot(slope * zl + intercept, zl * 1e3, 'r-', lw=2,
                label=f'fit: $k_{{DEM}}$ = {kDEM:.3f} W/(m K)')
        zm = 0.5 * (z0 + z1)
        Tm = slope * zm + intercept
        gZS = -Q / (A * kZS)
        ax.plot(Tm + gZS * (zl - zm), zl * 1e3, 'b--', lw=1.5,
                label=f'Zehner-Schlünder: $k_b$ = {kZS:.3f} W/(m K)')
        ax.axhline(zTop * 1e3, color='k', lw=0.5)
        ax.set_xlabel('temperature [K]')
        ax.set_ylabel('height above the hot plate [mm]')
        ax.set_title(f'Glass beads in air on a hot plate, ε = {eps:.3f}')
        ax.legend(fontsize=8, loc='upper right')
        fig.tight_layout()
        fig.savefig(figure, dpi=120)

    sys.exit(0 if all(checks.values()) else 1)


if __name__ == '__main__':
    main()
