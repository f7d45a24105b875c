# shellcheck shell=bash
# calibrateGranularMixture running several conditions at once (threads) or
# on MPI ranks gives bitwise the conditions of a one-at-a-time run, also
# after a kill (sourced by tests/run; tests calibration/parallel/*).

# Serial reference for the parallel tests: the tutorial's conditions run one
# at a time (concurrentConditions 1), stored without a fit
calibration_serial_reference()
{
    copy_calibration_case "$1"
    foamDictionary -entry concurrentConditions -set 1 "$1/system/calibrationDict" > /dev/null
    calibrateGranularMixture -case "$1" -noFit > "$1/log" 2>&1 || { tail -20 "$1/log"; return 1; }
    grep -q "8 conditions to run, 1 at once" "$1/log" || { echo "reference did not run 1 at once"; return 1; }
    dump_conditions "$1/constant/calibration.h5" > "$1/conditions.txt"
    [ -s "$1/conditions.txt" ] || { echo "empty dump of the reference"; return 1; }
}

# same_conditions REF DIR: the condition groups of DIR (timing excluded)
# are identical to those of the reference
same_conditions()
{
    dump_conditions "$2/constant/calibration.h5" > "$2/conditions.txt"
    diff -q "$1/conditions.txt" "$2/conditions.txt" > /dev/null \
        || { echo "conditions differ from the serial reference:"; diff "$1/conditions.txt" "$2/conditions.txt" | head -20; return 1; }
    echo "identical to the serial reference ($(wc -l < "$2/conditions.txt") dump lines, timing groups excluded)"
}

# Two conditions at once (threads) give bitwise the conditions of a one at
# a time run
test_calibration_concurrent()
{
    local ref="$workRoot/calibrationSerial" dir="$workRoot/calibrationConcurrent"
    calibration_serial_reference "$ref" || return 1
    copy_calibration_case "$dir"
    foamDictionary -entry concurrentConditions -set 2 "$dir/system/calibrationDict" > /dev/null
    calibrateGranularMixture -case "$dir" -noFit > "$dir/log" 2>&1 || { tail -20 "$dir/log"; return 1; }
    grep -q "8 conditions to run, 2 at once" "$dir/log" || { echo "did not run 2 at once"; grep "at once" "$dir/log"; return 1; }
    [ "$(grep -c "done in" "$dir/log")" -eq 8 ] || { echo "not 8 progress lines"; return 1; }
    grep -E "^DEM:" "$ref/log" "$dir/log"
    same_conditions "$ref" "$dir" || return 1

    # killed (kill -9) after its first finished condition, with the other
    # worker still running: the rerun skips what was stored, runs the rest
    local killed="$workRoot/calibrationConcurrentKill"
    copy_calibration_case "$killed"
    foamDictionary -entry concurrentConditions -set 2 "$killed/system/calibrationDict" > /dev/null
    local stored
    stored=$(kill_after_first_condition "$killed" "$killed/log.1")
    [ "$stored" -ge 1 ] && [ "$stored" -lt 8 ] || { echo "kill did not land mid-run ($stored stored)"; return 1; }
    calibrateGranularMixture -case "$killed" -noFit > "$killed/log.2" 2>&1 || { tail -20 "$killed/log.2"; return 1; }
    echo "2 workers killed after $stored stored conditions"
    check_resumed_rerun "$killed/log.2" "$stored" 8 || return 1
    same_conditions "$ref" "$killed"
}

# -parallel on 2 MPI ranks (no decomposition): both ranks run conditions,
# the master merges the processor stores, the result equals the serial run
test_calibration_parallel()
{
    local ref="$workRoot/calibrationSerial" dir="$workRoot/calibrationParallel"
    calibration_serial_reference "$ref" || return 1   # always fresh: a stale reference from an earlier run could pass or fail for the wrong reason
    copy_calibration_case "$dir"
    mpirun --allow-run-as-root --oversubscribe -np 2 calibrateGranularMixture -parallel -case "$dir" > "$dir/log" 2>&1 \
        || { tail -20 "$dir/log"; return 1; }
    local r0 r1
    r0=$(grep -c "^\[0\] condition .* done in" "$dir/log")
    r1=$(grep -c "^\[1\] condition .* done in" "$dir/log")
    echo "rank 0 ran $r0, rank 1 ran $r1 conditions"
    [ "$r0" -eq 4 ] && [ "$r1" -eq 4 ] || { echo "conditions not spread 4 + 4 over the ranks"; return 1; }
    grep -q "Merged 8 conditions of 2 processor stores" "$dir/log" || { echo "no merge of 8 conditions"; return 1; }
    ls "$dir/constant" | grep -q "processor" && { echo "processor stores left behind"; return 1; }
    [ ! -e "$dir/processor0" ] || { echo "processor0 directory created"; return 1; }
    local law
    law=$(foamDictionary -entry D/law -value "$dir/constant/granularCoefficients") || { echo "master wrote no granularCoefficients"; return 1; }
    echo "D/law = $law (fitted by the master)"
    same_conditions "$ref" "$dir"
}

# A -parallel run killed (kill -9, every rank) after its first finished
# condition loses nothing: the next (serial) run merges the processor
# stores left behind, skips what they hold, runs the rest, and ends with
# the serial reference's conditions
test_calibration_parallel_kill()
{
    local ref="$workRoot/calibrationSerial" dir="$workRoot/calibrationParallelKill"
    calibration_serial_reference "$ref" || return 1   # always fresh: a stale reference from an earlier run could pass or fail for the wrong reason
    copy_calibration_case "$dir"
    mpirun --allow-run-as-root --oversubscribe -np 2 calibrateGranularMixture -parallel -case "$dir" -noFit > "$dir/log.1" 2>&1 &
    local pid=$! i
    for i in $(seq 1 1200)
    do
        grep -q "done in" "$dir/log.1" 2>/dev/null && break
        kill -0 "$pid" 2>/dev/null || { tail -20 "$dir/log.1"; echo "the parallel run ended before it was killed"; return 1; }
        sleep 0.05
    done
    # the ranks are mpirun's children in their own process groups: kill
    # them by id, then mpirun, and wait until none is left
    local ranks
    ranks=$(ps -o pid= --ppid "$pid")
    kill -9 $ranks "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    for i in $(seq 1 100)
    do
        ps -o pid= -p "$(echo $ranks | tr ' ' ',')" > /dev/null 2>&1 || break
        sleep 0.05
    done
    local left stored=0 f n
    left=$(ls "$dir/constant" | grep -c "^calibration.processor[0-9]*.h5$")
    for f in "$dir"/constant/calibration.processor*.h5
    do
        [ -f "$f" ] || continue
        n=$(h5ls "$f/conditions" 2>/dev/null | wc -l)
        stored=$((stored + n))
    done
    echo "killed with $stored conditions in $left processor stores"
    [ "$stored" -ge 1 ] && [ "$stored" -lt 8 ] || { echo "kill did not land mid-run"; return 1; }
    [ ! -e "$dir/constant/calibration.h5" ] || { echo "calibration.h5 written before the end of the run"; return 1; }

    calibrateGranularMixture -case "$dir" -noFit > "$dir/log.2" 2>&1 || { tail -20 "$dir/log.2"; return 1; }
    grep -q "Merged $stored conditions of $left processor stores" "$dir/log.2" || { echo "leftover stores not merged"; grep Merged "$dir/log.2"; return 1; }
    check_resumed_rerun "$dir/log.2" "$stored" 8 || return 1
    ls "$dir/constant" | grep -q "processor" && { echo "processor stores left behind"; return 1; }
    same_conditions "$ref" "$dir"
}
