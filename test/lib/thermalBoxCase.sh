# SPDX-License-Identifier: GPL-3.0-or-later
# Source this. thermalBoxCase DEST UZ: a copy of the test/thermalBox case in
# DEST (its driver scripts removed) with gas and particles at 300 K and the
# gas velocity (0 0 UZ) m/s inside and at the inlet; the caller adds its
# own cloud and mesh files. Used by the tests and benchmarks built on it.
thermalBoxCase() {
    local dest=$1 uz=$2
    local box
    box="$(cd "$(dirname "${BASH_SOURCE[0]}")/../thermalBox" && pwd)"
    cp -r "$box" "$dest"
    rm -f "$dest/run" "$dest/check.py"
    sed -i 's/^Tgas .*/Tgas        300;/; s/^Tp .*/Tp          300;/' \
        "$dest/system/settings"
    local e
    for e in internalField boundaryField/inlet/inletVelocity boundaryField/inlet/value
    do
        foamDictionary -entry "$e" -set "uniform (0 0 $uz)" "$dest/0/U" > /dev/null
    done
}
