# shellcheck shell=bash
# Shared by the test files (sourced by tests/run before them): where the
# cases and helpers are, and a fresh copy of a case. The tests run from the
# project directory ($projectDir) with the OpenFOAM environment; each test
# works in its own directory under $workRoot (build/tests).

validationDir="$projectDir/validation"
calibrationCase="$projectDir/tutorials/calibration/binary21"

# copy_case FROM TO: a fresh copy of a case without run outputs or mesh
copy_case()
{
    local from="$1" to="$2"
    rm -rf "$to"
    mkdir -p "$to"
    cp -r "$from/0.orig" "$from/constant" "$from/system" "$to/"
    [ -f "$from/Allrun" ] && cp "$from/Allrun" "$from/Allclean" "$to/" 2>/dev/null
    rm -rf "$to/constant/polyMesh"
    true
}

# kill_after_first_condition CASE LOG: run calibrateGranularMixture -noFit on
# CASE in the background (output to LOG), kill it (kill -9) once its first
# condition is done, and print how many conditions calibration.h5 holds then
kill_after_first_condition()
{
    local dir="$1" log="$2"
    calibrateGranularMixture -case "$dir" -noFit > "$log" 2>&1 &
    local pid=$! i
    for i in $(seq 1 600)
    do
        grep -q "done in" "$log" 2>/dev/null && break
        sleep 0.05
    done
    kill -9 "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    h5ls "$dir/constant/calibration.h5/conditions" 2>/dev/null | wc -l
}

# check_resumed_rerun LOG STORED TOTAL: the rerun's log LOG skipped exactly
# the STORED conditions and ran the other TOTAL - STORED
check_resumed_rerun()
{
    local log="$1" stored="$2" total="$3" skipped ran
    skipped=$(grep -c "^skipping .*(already in calibration.h5)" "$log")
    ran=$(grep -c "done in" "$log")
    echo "rerun after $stored stored conditions: $skipped skipped, $ran run"
    [ "$skipped" -eq "$stored" ] && [ "$ran" -eq $((total - stored)) ] \
        || { echo "rerun repeated or missed conditions"; return 1; }
}

# retaining_top_worked LOG: the open top closed faces to the bulk at some
# step (so the test exercised prghBulkRetainingTotalPressure) and its
# re-solves never reached their cap
retaining_top_worked()
{
    local closed
    closed=$(sed -n 's/.*muI: open top: \([0-9]*\) face(s) closed.*/\1/p' "$1" | sort -n | tail -1)
    echo "open top: at most ${closed:-0} face(s) closed to the bulk in a corrector"
    [ "${closed:-0}" -gt 0 ] || { echo "no face of the open top was ever closed"; return 1; }
    if grep -q "still switched" "$1"
    then
        echo "the open top's re-solves reached their cap:"; grep -m3 "still switched" "$1"; return 1
    fi
}

# check_refusal DIR APP EXPECT...: APP on DIR (log: DIR/log.APP) exits
# non-zero with a fatal error holding every EXPECT (the program's own
# message, not just a name that any error about the file would carry),
# does not crash, and writes no time directory
check_refusal()
{
    local dir="$1" app="$2"; shift 2
    if "$app" -case "$dir" > "$dir/log.$app" 2>&1
    then
        echo "$app accepted the bad input"; return 1
    fi
    local fatal
    fatal=$(sed -n '/FOAM FATAL/,/FOAM exiting\|FOAM aborting/p' "$dir/log.$app")
    echo "$fatal" | head -12
    [ -n "$fatal" ] || { echo "no FOAM FATAL error"; tail -5 "$dir/log.$app"; return 1; }
    local e
    for e in "$@"
    do
        if ! grep -qF -- "$e" <<< "$fatal"
        then
            echo "the fatal error lacks '$e'"; return 1
        fi
    done
    if grep -q "Segmentation\|printStack" "$dir/log.$app"
    then
        echo "crashed instead of a clear error"; return 1
    fi
    local written
    written=$(find "$dir" -mindepth 1 -maxdepth 1 -type d -regextype posix-extended -regex '.*/[0-9.eE+-]+' ! -name 0 | head -1)
    [ -z "$written" ] || { echo "a time directory was written: $written"; return 1; }
}
