#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks of bedPressureDrop's window statistics and defluidization flag.

    check.py window DAT WINDOW RATIO STD DURATION STATE
        dp_mean and dp_std of every row recomputed here from the dp column
        over the samples t_i of the last WINDOW seconds (t - t_i < WINDOW
        to half a step); dp_mean within 1e-9 relative, dp_std within
        1e-7 dp_mean (the file prints dp to 11 digits); both flags of
        every row equal to the rule applied here: a step is still when
        the window is full, W/A > 0 and dp_std/(W/A) < STD, and looks
        defluidized when still with dp_mean/(W/A) < RATIO, frozen when
        still with dp_mean/(W/A) >= RATIO; a flag is up once every step
        for DURATION seconds has looked so. The flag of STATE
        (defluidized or frozen) must trip, once; the other never.
    check.py balance DAT WALLDAT TOL
        the vertical momentum balance of the still bed, with wallLoad's
        file WALLDAT (gravity along -z): each patch's share of the weight
        recomputed as -F_z/W and the sum of the shares as the sum of the
        columns, within 1e-9 (1 + |share|) (the file's 11 digits); over
        the rows where either flag is up (the bed at rest; at least one),
        the mean of dp/(W/A) + sum of the shares is 1 within TOL (what the
        gas does not carry, the distributor and walls do) and every row
        within 4 TOL (a row is one CFD step: a packed bed that still
        creeps accelerates for a step now and then, and the balance
        leaves out the bed's acceleration).
    check.py restart FULLDAT RESTARTDAT
        every row of the restarted run equal to the uninterrupted run's: dp and dp_mean within 1e-9 relative, dp_std
        within 1e-7 dp_mean, both flags the same.
"""
import sys

import numpy as np


def load(path):
    rows = [[float(v) for v in line.split()] for line in open(path)
            if line.strip() and not line.startswith('#')]
    if not rows:
        sys.exit(f'FAIL: no rows in {path}')
    return np.array(rows)


def window(path, win, ratio, stdmax, duration, state):
    d = load(path)
    t, dp, wa, mean_f, std_f = d[:, 0], d[:, 1], d[:, 2], d[:, 5], d[:, 6]
    written = {'defluidized': d[:, 7], 'frozen': d[:, 8]}
    dt = t[1] - t[0]
    ok = True
    first = 0
    since = {k: None for k in written}
    flag = {k: False for k in written}
    trips = {k: [] for k in written}
    bad_mean = bad_std = 0
    bad_flag = {k: 0 for k in written}
    for k in range(len(t)):
        while t[k] - t[first] >= win - 0.5 * dt:
            first += 1
        w = dp[first:k + 1]
        m = w.mean()
        s = np.sqrt(((w - m) ** 2).mean())
        if abs(m - mean_f[k]) > 1e-9 * abs(m):
            bad_mean += 1
        if abs(s - std_f[k]) > 1e-7 * abs(m):
            bad_std += 1
        full = t[k] - t[0] >= win - 0.5 * dt
        still = full and wa[k] > 0 and s / wa[k] < stdmax
        looks = {'defluidized': still and m / wa[k] < ratio,
                 'frozen': still and m / wa[k] >= ratio}
        for name in written:
            if not looks[name]:
                since[name] = None
                flag[name] = False
            else:
                if since[name] is None:
                    since[name] = t[k]
                if not flag[name] and t[k] - since[name] >= duration - 0.5 * dt:
                    flag[name] = True
                    trips[name].append((t[k], since[name], m / wa[k], s / wa[k]))
            if int(flag[name]) != int(written[name][k]):
                bad_flag[name] += 1
    print(f'{len(t)} rows: dp_mean off in {bad_mean}, dp_std off in {bad_std},'
          f' flags off in {bad_flag}')
    for name in written:
        for tt, s0, r, sr in trips[name]:
            print(f'{name} flag trips at t = {tt:g} s (looked so since {s0:g} s;'
                  f' dp_mean/(W/A) {r:.4f}, dp_std/(W/A) {sr:.2e})')
        f = written[name]
        print(f'{name} flag trips in the file at'
              f' {[t[k] for k in range(1, len(t)) if f[k] == 1 and f[k - 1] == 0]}')
    if bad_mean or bad_std or any(bad_flag.values()):
        ok = False
    for name in written:
        want = 1 if name == state else 0
        if len(trips[name]) != want:
            print(f'FAIL: expected the {name} flag to trip {want} time(s),'
                  f' not {len(trips[name])}')
            ok = False
    return ok


def restart(full_path, restart_path):
    f = load(full_path)
    r = load(restart_path)
    by_time = {round(row[0], 9): row for row in f}
    n = bad = 0
    for row in r:
        ref = by_time.get(round(row[0], 9))
        if ref is None:
            print(f'FAIL: time {row[0]} not in the full run')
            return False
        n += 1
        m = abs(ref[5])
        if (abs(row[1] - ref[1]) > 1e-9 * abs(ref[1])
                or abs(row[5] - ref[5]) > 1e-9 * m
                or abs(row[6] - ref[6]) > 1e-7 * m
                or row[7] != ref[7] or row[8] != ref[8]):
            bad += 1
            if bad <= 3:
                print(f'differs at t = {row[0]}: restarted {row[1:]}, full {ref[1:]}')
    print(f'restarted run from t = {r[0][0]}: {n} rows compared, {bad} differ;'
          f' first row dp_mean {r[0][5]:.10g} (full run {by_time[round(r[0][0], 9)][5]:.10g}),'
          f' dp {r[0][1]:.10g}')
    return n > 0 and bad == 0


def balance(path, wall_path, tol):
    d = load(path)
    w = load(wall_path)
    if len(w) != len(d) or np.any(np.abs(w[:, 0] - d[:, 0]) > 1e-12):
        print(f'FAIL: {wall_path} and {path} have other times')
        return False
    weight, shares = w[:, 1], w[:, 5:-1:4]
    fz = w[:, 4:-1:4]
    full = weight > 0
    ok = True
    recomputed = np.where(full[:, None], -fz/np.where(full, weight, 1)[:, None], 0)
    worst = np.max(np.abs(recomputed - shares)/(1 + np.abs(shares)))
    if worst > 1e-9:
        print(f'FAIL: a share differs from -F_z/W by {worst:.3g}')
        ok = False
    if np.max(np.abs(shares.sum(axis=1) - w[:, -1])
              / (1 + np.abs(shares).sum(axis=1))) > 1e-9:
        print('FAIL: sum_s is not the sum of the shares')
        ok = False
    still = (d[:, 7] > 0) | (d[:, 8] > 0)
    if not np.any(still):
        print('FAIL: no row with a flag up')
        return False
    total = d[still, 3] + w[still, -1]
    off = abs(total.mean() - 1)
    worst = np.max(np.abs(total - 1))
    print(f'{still.sum()} still rows: dp/(W/A) {d[still, 3].min():.4f}-'
          f'{d[still, 3].max():.4f}, patches\' shares (mean) '
          + ' '.join(f'{v:.4f}' for v in shares[still].mean(axis=0))
          + f'; dp/(W/A) + sum: mean {total.mean():.5f} (tolerance {tol}),'
          f' rows {total.min():.5f}-{total.max():.5f} (tolerance {4*tol})')
    return ok and off <= tol and worst <= 4*tol


def main():
    mode = sys.argv[1]
    if mode == 'window':
        ok = window(sys.argv[2], *[float(v) for v in sys.argv[3:7]], sys.argv[7])
    elif mode == 'balance':
        ok = balance(sys.argv[2], sys.argv[3], float(sys.argv[4]))
    elif mode == 'restart':
        ok = restart(sys.argv[2], sys.argv[3])
    else:
        sys.exit(f'check.py: unknown mode {mode}')
    print('PASS' if ok else 'FAIL')
    sys.exit(0 if ok else 1)


main()
