#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks of a finished thermalBox run (see ./run)."""
import math
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


def patch_entry(path, patch, key):
    """A list entry (nonuniform or uniform) of a patch of a field file."""
    text = Path(path).read_text()
    block = text.split('boundaryField', 1)[1].split(patch, 1)[1]
    rest = re.split(r'\n\s*' + key + r'(?=\s)', block, maxsplit=1)[1]
    m = re.match(r'\s+uniform\s+([-+.eE\d]+)', rest)
    if m:
        return float(m.group(1))
    m = re.match(r'\s+nonuniform\s+List<scalar>\s*(\d+)\s*\((.*?)\)', rest, re.S)
    values = [float(x) for x in m.group(2).split()]
    assert len(values) == int(m.group(1))
    return values


def patch_cells(case, patch):
    """The cell of each face of a patch, from the polyMesh."""
    boundary = (case / 'constant/polyMesh/boundary').read_text()
    block = boundary.split(patch, 1)[1].split('}', 1)[0]
    n = int(re.search(r'nFaces\s+(\d+)', block).group(1))
    start = int(re.search(r'startFace\s+(\d+)', block).group(1))
    owner = [int(x) for x in foam_list(case / 'constant/polyMesh/owner')]
    return owner[start:start + n]


def check_thermal_wall(case, last, loss_rate):
    """The written coefficients of the thermal wall condition against eq
    4.14-4.24 evaluated here from the written cell fields."""
    h, Text = 350.0, 400.0
    kf = 1.8e-5 * 1005 / 0.7          # constant transport: mu Cp/Pr
    ks, rho, cp, d = 1.4, 2500.0, 840.0, 5e-4
    delta = 1 / 1e-3                  # 2 mm cells: 1 mm to the wall
    omega = 7.26e-3
    cells = patch_cells(case, 'walls')
    eps = foam_list(last / 'voidage')
    theta = foam_list(last / 'granularTemperature')
    if len(theta) == 1:
        theta = theta * len(eps)
    Tc = foam_list(last / 'T')
    kb = patch_entry(last / 'T', 'walls', 'kb')
    f = patch_entry(last / 'T', 'walls', 'valueFraction')
    Tw = patch_entry(last / 'T', 'walls', 'value')
    worst = 0.0
    worst_Tw = 0.0
    solids = 0
    wall_rate = 0.0
    for i, c in enumerate(cells):
        e = eps[c]
        k = (1 - math.sqrt(1 - e)) * kf
        if e < 1:
            solids += 1
            A = ks / kf
            B = 1.25 * ((1 - e) / e) ** (10 / 9)
            r = 1 - B / A
            gamma = 2 / r * ((A - 1) / r**2 * B / A * math.log(A / B)
                             - (B - 1) / r - (B + 1) / 2)
            kmol = (omega * A + (1 - omega) * gamma) / math.sqrt(1 - e) * kf
            kkin = rho * cp * d * math.sqrt(theta[c]) * math.sqrt(math.pi) / 16
            k += (1 - e) * (kmol + kkin)
        fv = h / (h + k * delta)
        Twv = fv * Text + (1 - fv) * Tc[c]
        worst = max(worst, abs(kb[i] - k) / k, abs(f[i] - fv) / fv)
        worst_Tw = max(worst_Tw, abs(Tw[i] - Twv) / Twv)
        wall_rate += h * (Text - Tw[i]) * 4e-6
    # k_b and f: round-off. T_w: the gas temperature's face value comes
    # back from the energy's (OpenFOAM's mixedEnergy), whose correction
    # term holds the previous iteration's face and cell temperatures: the
    # relation holds to the last iteration's change, not to round-off
    print(f"thermal wall: {len(cells)} faces, {solids} with particles in"
          f" their cell; k_b {min(kb):.4g}..{max(kb):.4g} W/(m K); worst"
          f" relative difference of k_b and f from eq 4.14-4.24"
          f" {worst:.2e} (tolerance 1e-12), of T_w = f T_ext + (1 - f) T_c"
          f" {worst_Tw:.2e} (tolerance 1e-6); walls give the gas"
          f" {wall_rate:.4g} W")
    if solids == 0 or max(theta[c] for c in cells) <= 0:
        print("FAIL: no wall cell with moving particles: the solids' terms"
              " would go untested")
        return False
    if not abs(wall_rate) > 0.01 * loss_rate:
        print(f"FAIL: the walls exchange under 1 % of the beads' mean loss"
              f" rate {loss_rate:.4g} W: the balance would not test them")
        return False
    return worst <= 1e-12 and worst_Tw <= 1e-6


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
    t, Hp, Hg, Hout, imbalance, Hwall = rows[-1][:6]
    lost = Hp0 - Hp
    gained = Hg - rows[0][2]
    rel = abs(imbalance) / lost
    print(f"particles lost {lost:.6g} J; gas gained {gained:.6g} J; "
          f"carried/conducted out {Hout:.6g} J; walls gave the beads "
          f"{Hwall:.6g} J")
    if mode == 'balanceThermalWall' and not check_thermal_wall(case, last, lost / t):
        return 1
    if mode.startswith('balanceWithConduction') and not abs(Hwall) > 1e-3 * lost:
        print("FAIL: the walls conducted under 0.1 % of the loss;"
              " the conduction would go untested")
        return 1
    tol = 0.001 if mode in ('balanceWithConduction', 'balanceWithConductionLocalGas', 'balanceThermalWall') \
        else 0.005
    print(f"imbalance {imbalance:.3e} J = {100*rel:.4f} % of the loss "
          f"(tolerance {100*tol:g} %)")
    if lost <= 0.01 * Hp0:
        print("FAIL: the beads lost under 1 % of their enthalpy;"
              " the balance would prove nothing")
        return 1
    return 0 if rel <= tol else 1


if __name__ == '__main__':
    sys.exit(main())
