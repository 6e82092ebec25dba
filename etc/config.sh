# SPDX-License-Identifier: GPL-3.0-or-later
# Locations shared by etc/install and etc/bashrc.
: "${SINTERFOAM_OFDEV:=${XDG_CACHE_HOME:-$HOME/.cache}/sinterFoam/OpenFOAM-v1912}"
export SINTERFOAM_OFDEV
