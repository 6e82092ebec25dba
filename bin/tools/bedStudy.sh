# SPDX-License-Identifier: GPL-3.0-or-later
# The machinery of the bed studies' drivers (validation/labBedSintering,
# validation/coarseGraining), sourced by them: runs of the labBed tutorial
# in segments that resume where they stopped, bases that fluidize a bed up
# to the activation of the bridges and cells that branch from a base's
# state there.
#
# A case's settings are system/caseSettings.case (written by the driver:
# #include lines and key value; lines) and, for each segment,
# system/caseSettings.run: caseSettings.case and the segment's endTime.
#
# The driver sets, before calling these:
#   work        the work directory (a file STOP there stops the driver
#               before the next segment)
#   np          MPI ranks per run
#   segment     simulated time per solver run [s]
#   activation  the time the bases stop and the cells start [s]
#   keepEvery   the times kept besides the activation time and the
#               latest [s]
#   tutorial    the case copied (tutorials/sinterFoam/labBed)
#   studyFiles  (array) files copied into a new base: SOURCE:DEST, DEST
#               relative to the case
#   writeInterval  (may be empty) the controlDict's writeInterval
#   segmentWrites  (may be empty) yes: each segment's caseSettings.run sets
#               writeInterval to the segment's length, so that the run
#               writes at its end wherever it restarted
# The solver reads caseSettings.run through LABBED_SETTINGS (labBed); a
# driver of another case exports its own variable (pseudo2DChapter4:
# PSEUDO2D_SETTINGS=caseSettings.run).
# and defines
#   keepSummary CASE   keeps a run's summary after each segment
# Temperatures in kelvin.

bedStudy_mpi() {
    if [ "$np" -gt 1 ]; then
        mpirun -np "$np" "$@" -parallel
    else
        "$@"
    fi
}

# Times of a case (of processor0 when decomposed), ascending
bedStudy_times() {  # bedStudy_times CASE
    local d=$1
    [ -d "$d/processor0" ] && d=$d/processor0
    (cd "$d" && ls -d [0-9]* 2>/dev/null | grep -v '^0$' | sort -g) || true
}

# A run stopped or killed while writing leaves its latest time without
# sinterFoam's mark of a whole time (uniform/sinterFoamWritten), which
# sinterFoam refuses to start from: remove that time
bedStudy_repair() {  # bedStudy_repair CASE
    local t p
    t=$(bedStudy_times "$1" | tail -1)
    [ -n "$t" ] || return 0
    local parts=("$1"/processor*)
    [ -d "${parts[0]}" ] || parts=("$1")     # a serial case
    for p in "${parts[@]}"; do
        if [ ! -f "$p/$t/uniform/sinterFoamWritten" ]; then
            echo "  $(basename "$1"): its latest time $t was not written whole; removing it"
            rm -rf "$1"/processor*/"$t" "${1:?}/$t"
            return 0
        fi
    done
}

# Keep the activation time, every keepEvery and the latest
bedStudy_prune() {  # bedStudy_prune CASE
    local latest t
    latest=$(bedStudy_times "$1" | tail -1)
    for t in $(bedStudy_times "$1"); do
        [ "$t" = "$latest" ] && continue
        awk -v t="$t" -v a="$activation" -v k="$keepEvery" 'BEGIN {
            r = (t - a)/k; exit !(t < a - 1e-9 || (r - int(r + 0.5))^2 > 1e-12) }' \
            && rm -rf "$1"/processor*/"$t" "${1:?}/$t"
    done
}

# Run CASE to END in segments, resuming; after each segment the run's
# times are pruned and its summary kept
bedStudy_advance() {  # bedStudy_advance CASE END
    local c=$1 end=$2 latest next
    bedStudy_repair "$c"
    while :; do
        latest=$(bedStudy_times "$c" | tail -1)
        latest=${latest:-0}
        awk -v a="$latest" -v b="$end" 'BEGIN { exit !(a >= b - 1e-9) }' && break
        if [ -f "$work/STOP" ]; then
            echo "STOP in $work: stopping before $(basename "$c") continues from $latest s"
            exit 0
        fi
        next=$(awk -v a="$latest" -v s="$segment" -v b="$end" 'BEGIN {
            n = (int(a/s + 1e-6) + 1)*s; if (n > b) n = b; printf "%.10g", n }')
        {
            echo '#include "caseSettings.case"'
            echo "endTime     $next;"
            # The write times count from the restart: one write, at next
            [ "${segmentWrites:-}" != yes ] || awk -v a="$latest" -v n="$next" \
                'BEGIN { printf "writeInterval %.10g;\n", n - a }'
        } > "$c/system/caseSettings.run"
        echo "  $(date +%H:%M) $(basename "$c"): $latest -> $next s"
        (
            cd "$c"
            export LABBED_SETTINGS=caseSettings.run
            bedStudy_mpi sinterFoam >> log.sinterFoam 2>&1
        ) || { echo "FAILED $(basename "$c") (see $c/log.sinterFoam)"; exit 1; }
        if awk -v a="$(bedStudy_times "$c" | tail -1)" -v b="$latest" \
            'BEGIN { exit !(a + 0 <= b + 1e-12) }'; then
            echo "FAILED $(basename "$c"): the run wrote no time after $latest s" \
                "(its writeInterval does not reach $next s?)"
            exit 1
        fi
        bedStudy_prune "$c"
        keepSummary "$c" | sed 's/^/  /' || echo "  summary failed for $c"
    done
}

# A new base: the tutorial with the study's files, its settings from
# standard input (caseSettings.case), meshed (and decomposed); nothing
# if it exists
bedStudy_create() {  # bedStudy_create CASE < settings
    local b=$1 f
    if [ -d "$b/system" ]; then
        cat > /dev/null
        return 0
    fi
    mkdir -p "$b"
    cp -r "$tutorial"/{0,constant,system} "$b"
    rm -rf "$b/0/uniform" "$b/0/lagrangian" "$b/constant/polyMesh"
    for f in "${studyFiles[@]}"; do
        cp "${f%%:*}" "$b/${f#*:}"
    done
    [ -z "${writeInterval:-}" ] || sed -i \
        "s/^writeInterval .*/writeInterval   $writeInterval;/" "$b/system/controlDict"
    sed -i "s/^numberOfSubdomains .*/numberOfSubdomains $np;/" \
        "$b/system/decomposeParDict"
    cat > "$b/system/caseSettings.case"
    cp "$b/system/caseSettings.case" "$b/system/caseSettings.run"
    (
        cd "$b"
        export LABBED_SETTINGS=caseSettings.run
        blockMesh > log.blockMesh 2>&1
        if [ "$np" -gt 1 ]; then
            decomposePar > log.decomposePar 2>&1
        fi
    ) || { echo "FAILED mesh of $b"; exit 1; }
}

# A new cell from its base's state at the activation time, its settings
# from standard input (caseSettings.case); nothing if it exists
bedStudy_branch() {  # bedStudy_branch BASE CELL < settings
    local b=$1 c=$2 p
    if [ -d "$c/system" ]; then
        cat > /dev/null
        return 0
    fi
    mkdir -p "$c"
    cp -r "$b"/{0,constant,system} "$c"
    if [ "$np" -gt 1 ]; then
        for p in "$b"/processor*; do
            mkdir -p "$c/$(basename "$p")"
            cp -r "$p/constant" "$p/$activation" "$c/$(basename "$p")"
        done
    else
        cp -r "$b/$activation" "$c"
    fi
    rm -f "$c"/log.*
    cat > "$c/system/caseSettings.case"
}
