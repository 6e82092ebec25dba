#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks of the heatConvection runs (see ./run): work/K1, work/K2."""
import math
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / 'lib'))
from foamFiles import foam_list  # noqa: E402


def history(case):
    """(time, mean parcel T, gas T, voidage, number of parcels) per write."""
    rows = []
    for d in case.iterdir():
        if re.fullmatch(r'[\d.e-]+', d.name) and d.name != '0':
            Tp = foam_list(d / 'lagrangian/cloud/T')
            rows.append((float(d.name), sum(Tp) / len(Tp),
                         foam_list(d / 'T')[0], foam_list(d / 'voidage')[0],
                         len(Tp)))
    return sorted(rows)


def main():
    work = Path(sys.argv[1])
    k1, k2 = history(work / 'K1'), history(work / 'K2')
    Tp0, Tg0 = 600.0, 300.0
    dT0 = Tp0 - Tg0
    ok = True

    # Properties of the case (constant/*, system/settings)
    rho_p, cp_p, dp, n = 2500.0, 840.0, 5e-4, 8
    rho_g, cp_g, mu, Pr, V = 1.16, 1005.0, 1.8e-5, 0.7, 1e-6
    kappa = cp_g * mu / Pr
    Vs = n * math.pi / 6 * dp**3
    eps = 1 - Vs / V
    print(f"parcels: K=1 {k1[-1][4]}, K=2 {k2[-1][4]}; voidage K=1 {k1[-1][3]:.10f},"
          f" K=2 {k2[-1][3]:.10f}, 1 - Vs/V = {eps:.10f}")
    if k1[-1][4] != 8 or k2[-1][4] != 1:
        print("FAIL: expected 8 and 1 parcels")
        return 1

    # 1. K = 2 against K = 1
    worst = 0
    for a, b in zip(k1, k2):
        worst = max(worst, abs(a[1] - b[1]) / dT0, abs(a[2] - b[2]) / dT0)
    good = worst <= 1e-9 and len(k1) == len(k2)
    ok &= good
    print(f"{'ok  ' if good else 'FAIL'} K=2 parcel vs mean of K=1 parcels, and gases:"
          f" max difference {worst:.2e} of the initial difference (tolerance 1e-9)")

    # 2. The two-body exchange, RK4 in steps of 1e-5 s
    Cp = n * rho_p * math.pi / 6 * dp**3 * cp_p
    Cg = eps * rho_g * V * cp_g
    Nu = 7 - 10 * eps + 5 * eps**2       # Gunn, eq 4.8, Re = 0

    def rates(Tp, Tg):
        Ts = (2 * Tp + Tg) / 3           # ThermoCloud's film temperature
        G = n * math.pi * kappa * Ts / Tg * dp * Nu
        q = G * (Tg - Tp)
        return q / Cp, -q / Cg

    t, Tp, Tg, h = 0.0, Tp0, Tg0, 1e-5
    worst = 0
    for time, Tpm1, Tg1, _, _ in k1:
        while t < time - h / 2:
            a1, b1 = rates(Tp, Tg)
            a2, b2 = rates(Tp + h / 2 * a1, Tg + h / 2 * b1)
            a3, b3 = rates(Tp + h / 2 * a2, Tg + h / 2 * b2)
            a4, b4 = rates(Tp + h * a3, Tg + h * b3)
            Tp += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4)
            Tg += h / 6 * (b1 + 2 * b2 + 2 * b3 + b4)
            t += h
        e = max(abs(Tpm1 - Tp), abs(Tg1 - Tg)) / dT0
        worst = max(worst, e)
        print(f"  t {time:4.2f} s: parcels {Tpm1:9.4f} K (two-body {Tp:9.4f}),"
              f" gas {Tg1:9.4f} K ({Tg:9.4f})")
    good = worst <= 5e-3
    ok &= good
    print(f"{'ok  ' if good else 'FAIL'} against the two-body exchange: max difference"
          f" {worst:.2e} of the initial difference (tolerance 5e-3)")
    if k1[-1][1] - k1[-1][2] > 0.5 * dT0:
        print("FAIL: the parcels and the gas exchanged under half their difference;"
              " the comparison would prove little")
        ok = False

    # 3. Enthalpy of gas and parcels
    H0 = Cp * Tp0 + Cg * Tg0
    worst = max(abs(Cp * r[1] + Cg * r[2] - H0) / (Cp * dT0) for r in k1)
    good = worst <= 1e-5
    ok &= good
    print(f"{'ok  ' if good else 'FAIL'} enthalpy of gas and parcels: max change"
          f" {worst:.2e} of the parcels' initial excess (tolerance 1e-5: the gas"
          f" the injection displaces leaves, then the flow settles)")
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
