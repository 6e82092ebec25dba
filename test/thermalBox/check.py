#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks of a finished thermalBox run (see ./run)."""
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / 'lib'))
from foamFiles import foam_list  # noqa: E402


def balance_rows(case):
    rows = []
    for line in (case / 'postProcessing/enthalpyBalance/0/enthalpyBalance.dat').open():
        if not line.startswith('#'):
            rows.append([float(x) for x in line.split()])
    return rows


def main():
    mode, case = sys.argv[1], Path(sys.argv[2])
    last = max((d for d in case.iterdir() if re.fullmatch(r'[\d.]+', d.name)
                and d.name != '0'), key=lambda d: float(d.name))
    Tgas = foam_list(last / 'T')
    Tp = foam_list(last / 'lagrangian/cloud/T')
    print(f"time {last.name}: {len(Tp)} parcels; gas T {min(Tgas)}..{max(Tgas)} K;"
          f" parcel T {min(Tp)}..{max(Tp)} K")
    if len(Tp) != 40:
        print(f"FAIL: expected 40 parcels, found {len(Tp)}")
        return 1

    if mode == 'uniform':
        # Round-off: 1e-12 relative to 300 K
        tol = 300 * 1e-12
        dev = max(abs(t - 300) for t in Tgas + Tp)
        print(f"max |T - 300 K| = {dev:.3e} K (tolerance {tol:.1e} K)")
        return 0 if dev <= tol else 1

    rows = balance_rows(case)
    Hp0 = rows[0][1]
    t, Hp, Hg, Hout, imbalance, Hwall = rows[-1]
    lost = Hp0 - Hp
    gained = Hg - rows[0][2]
    rel = abs(imbalance) / lost
    print(f"particles lost {lost:.6g} J; gas gained {gained:.6g} J; "
          f"carried/conducted out {Hout:.6g} J; walls gave the beads "
          f"{Hwall:.6g} J")
    if mode == 'balanceWithConduction' and not abs(Hwall) > 1e-3 * lost:
        print("FAIL: the walls conducted under 0.1 % of the loss;"
              " the conduction would go untested")
        return 1
    tol = 0.001 if mode == 'balanceWithConduction' else 0.005
    print(f"imbalance {imbalance:.3e} J = {100*rel:.4f} % of the loss "
          f"(tolerance {100*tol:g} %)")
    if lost <= 0.01 * Hp0:
        print("FAIL: the beads lost under 1 % of their enthalpy;"
              " the balance would prove nothing")
        return 1
    return 0 if rel <= tol else 1


if __name__ == '__main__':
    sys.exit(main())
