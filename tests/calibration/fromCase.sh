# shellcheck shell=bash
# calibrateGranularMixture -fromCase on the hand-made case
# tests/calibration/fromCase (sourced by tests/run; tests
# calibration/fromCase/*).

# LOG LINE...: every LINE appears verbatim in LOG (else the log's -fromCase,
# rheology and error lines are shown)
expect_lines()
{
    local f="$1" l; shift
    for l in "$@"
    do
        grep -qF -- "$l" "$f" || { echo "missing in $f: '$l'"; grep -e "-fromCase" -e FATAL -e rheology -A1 "$f" | head -20; return 1; }
    done
}

# -fromCase on a hand-made case (tests/calibration/fromCase, 5 cells,
# no mesh): the envelope derived from the fields equals the hand values
# (cells below phiMin ignored, phi clipped to 0.6, T log-spaced), a named
# time with uniform fields gives a one-point envelope and runs it, the
# coefficients follow the mechanisms switched on, nothing to calibrate
# stops cleanly, a missing T is a FatalError naming T and writeFields; the
# same with the gammaDot field for a sheared calibration
test_calibration_from_case()
{
    local dir="$workRoot/calibrationFromCase" log
    fresh_from_case() { rm -rf "$dir"; cp -r "$projectDir/tests/calibration/fromCase" "$dir"; }

    # latest time (2): hand values
    fresh_from_case
    log="$dir/log.latest"
    calibrateGranularMixture -case "$dir" -fromCase -dryRun > "$log" 2>&1 || { tail -20 "$log"; return 1; }
    grep "^-fromCase" "$log"
    expect_lines "$log" \
        "coefficients (D)" \
        "fields at time 2 (case), 4 of 5 cells hold material (phi >= 0.05)" \
        "-fromCase phi: case range [0.4, 0.7], clipped [0.4, 0.6] -> (0.4 0.5 0.6)" \
        "-fromCase x: case range [0.25, 0.6], clipped [0.25, 0.6] -> (0.25 0.425 0.6)" \
        "-fromCase T: case range [0.001, 0.04], clipped [0.001, 0.04] -> (0.001 0.006325 0.04)" \
        "entry 'phi' of" "entry 'coefficients' of" \
        "27 of 27 conditions would run" || return 1
    [ ! -e "$dir/constant/calibration.h5" ] || { echo "-dryRun wrote calibration.h5"; return 1; }

    # the same fields decomposed (processor0: cells 1-2, processor1: cells
    # 3-5, no time 2 in the case itself): the same envelope
    local d0="$dir/processor0/2" d1="$dir/processor1/2"
    mkdir -p "$d0" "$d1"
    sed 's/5(0.3 0.2 0.01 0.35 0.5)/2(0.3 0.2)/' "$dir/2/n.small" > "$d0/n.small"
    sed 's/5(0.1 0.3 0.01 0.15 0.2)/2(0.1 0.3)/' "$dir/2/n.large" > "$d0/n.large"
    sed 's/5(0.004 0.04 10 0.01 0.001)/2(0.004 0.04)/' "$dir/2/T" > "$d0/T"
    sed 's/5(0.3 0.2 0.01 0.35 0.5)/3(0.01 0.35 0.5)/' "$dir/2/n.small" > "$d1/n.small"
    sed 's/5(0.1 0.3 0.01 0.15 0.2)/3(0.01 0.15 0.2)/' "$dir/2/n.large" > "$d1/n.large"
    sed 's/5(0.004 0.04 10 0.01 0.001)/3(10 0.01 0.001)/' "$dir/2/T" > "$d1/T"
    mv "$dir/2" "$dir/2.serial"
    log="$dir/log.decomposed"
    calibrateGranularMixture -case "$dir" -fromCase -dryRun > "$log" 2>&1 || { tail -20 "$log"; return 1; }
    expect_lines "$log" \
        "fields at time 2 (processor directories), 4 of 5 cells hold material" \
        "-> (0.4 0.5 0.6)" "-> (0.25 0.425 0.6)" "-> (0.001 0.006325 0.04)" || return 1
    echo "decomposed fields: the same envelope"
    rm -rf "$dir/processor0" "$dir/processor1"
    mv "$dir/2.serial" "$dir/2"

    # named time 1 (uniform fields): one condition, run and stored
    log="$dir/log.time1"
    calibrateGranularMixture -case "$dir" -fromCase 1 -noFit > "$log" 2>&1 || { tail -20 "$log"; return 1; }
    expect_lines "$log" "fields at time 1 (case)" "-> (0.3)" "-> (0.3333)" "-> (0.01)" "DEM: 1 conditions run" || return 1
    h5ls "$dir/constant/calibration.h5/conditions" | grep -q "^phi0.3_x0.3333_T0.01_seed1 " \
        || { echo "condition phi0.3_x0.3333_T0.01_seed1 not stored"; h5ls "$dir/constant/calibration.h5/conditions"; return 1; }
    echo "time 1: stored $(h5ls "$dir/constant/calibration.h5/conditions")"

    # kinetic sieving switched on: D and eta
    fresh_from_case
    foamDictionary -entry kineticSieving/model -set velocityGradient "$dir/constant/granularProperties" > /dev/null
    log="$dir/log.sieving"
    calibrateGranularMixture -case "$dir" -fromCase -dryRun > "$log" 2>&1 || { tail -20 "$log"; return 1; }
    expect_lines "$log" "kineticSieving velocityGradient" "coefficients (D eta)" || return 1
    echo "kinetic sieving on: $(grep -o "coefficients (.*)" "$log" | head -1)"

    # nothing switched on: a message, exit 0, nothing written
    fresh_from_case
    foamDictionary -entry diffusivity/model -set none "$dir/constant/granularProperties" > /dev/null
    log="$dir/log.none"
    calibrateGranularMixture -case "$dir" -fromCase > "$log" 2>&1 || { echo "nothing to calibrate is not a clean exit"; tail -20 "$log"; return 1; }
    expect_lines "$log" "Nothing to calibrate" || return 1
    [ -z "$(ls "$dir/constant" | grep -v granularProperties)" ] || { echo "something was written"; ls "$dir/constant"; return 1; }
    echo "no mechanism: $(grep "Nothing to calibrate" "$log")"

    # T missing from the case and from calibrationDict: FatalError naming T
    fresh_from_case
    rm "$dir/2/T"
    foamDictionary -entry T -remove "$dir/system/calibrationDict" > /dev/null
    log="$dir/log.noT"
    if calibrateGranularMixture -case "$dir" -fromCase > "$log" 2>&1
    then
        echo "missing T accepted"; return 1
    fi
    grep -A4 "FOAM FATAL" "$log" | head -6
    expect_lines "$log" "FOAM FATAL" "field T is missing" "2/T" "writeFields" || return 1
    grep -q "done in" "$log" && { echo "DEM ran"; return 1; }
    [ ! -e "$dir/constant/calibration.h5" ] || { echo "calibration.h5 written"; return 1; }

    # bad entries of the new options: FatalIOError naming the entry, no DEM run
    local kind expect
    for kind in points minTRatio fromCaseEntry concurrent
    do
        fresh_from_case
        case "$kind" in
            points) foamDictionary -entry fromCase/points -set 0 "$dir/system/calibrationDict" > /dev/null; expect="'fromCase/points'" ;;
            minTRatio) foamDictionary -entry fromCase/minTRatio -set 2 "$dir/system/calibrationDict" > /dev/null; expect="'fromCase/minTRatio'" ;;
            fromCaseEntry) foamDictionary -entry fromCase/pionts -set 3 "$dir/system/calibrationDict" > /dev/null; expect="pionts" ;;
            concurrent) foamDictionary -entry concurrentConditions -set -1 "$dir/system/calibrationDict" > /dev/null; expect="'concurrentConditions'" ;;
        esac
        log="$dir/log.bad-$kind"
        if calibrateGranularMixture -case "$dir" -fromCase 1 > "$log" 2>&1
        then
            echo "$kind accepted"; return 1
        fi
        echo "$kind: $(grep -A2 "FOAM FATAL" "$log" | sed -n 2p)"
        grep -q "FOAM FATAL IO ERROR" "$log" || { echo "no FatalIOError"; tail -5 "$log"; return 1; }
        grep -qF -- "$expect" "$log" || { echo "message lacks $expect"; return 1; }
        grep -q "done in" "$log" && { echo "DEM ran"; return 1; }
        [ ! -e "$dir/constant/calibration.h5" ] || { echo "calibration.h5 written"; return 1; }
    done

    # sheared calibration (mode leesEdwards): the envelope's third axis is the
    # gammaDot field (log-spaced above minGammaDotRatio times its largest
    # value); its absence is a FatalError naming gammaDot and writeFields
    fresh_from_case
    sed 's/object T;/object gammaDot;/; s/\[0 2 -2 0 0 0 0\]/[0 0 -1 0 0 0 0]/; s/5(0.004 0.04 10 0.01 0.001)/5(2 50 1e3 0.5 0.01)/' \
        "$dir/2/T" > "$dir/2/gammaDot"
    foamDictionary -entry T -remove "$dir/system/calibrationDict" > /dev/null
    foamDictionary -entry mode -set leesEdwards "$dir/system/calibrationDict" > /dev/null
    foamDictionary -entry fromCase/minGammaDotRatio -set 0.1 "$dir/system/calibrationDict" > /dev/null
    log="$dir/log.sheared"
    calibrateGranularMixture -case "$dir" -fromCase -dryRun > "$log" 2>&1 || { tail -20 "$log"; return 1; }
    # cells holding material: gammaDot 2, 50, 0.5, 0.01 -> clipped at 0.1 x 50
    expect_lines "$log" \
        "-fromCase gammaDot: case range [0.01, 50], clipped [5, 50] -> (5 15.81 50)" \
        "(3 phi x 3 x x 3 gammaDot x 1 replicas, sheared cells (Lees-Edwards))" \
        "27 of 27 conditions would run" || return 1
    echo "sheared: $(grep -- "-fromCase gammaDot" "$log")"
    rm "$dir/2/gammaDot"
    log="$dir/log.noGammaDot"
    if calibrateGranularMixture -case "$dir" -fromCase > "$log" 2>&1
    then
        echo "missing gammaDot accepted"; return 1
    fi
    expect_lines "$log" "FOAM FATAL" "field gammaDot is missing" "2/gammaDot" "writeFields (gammaDot" || return 1
    echo "missing gammaDot: $(grep -A1 "FOAM FATAL" "$log" | sed -n 2p)"

    # T missing from the case but given in calibrationDict: that list is used
    fresh_from_case
    rm "$dir/2/T"
    log="$dir/log.dictT"
    calibrateGranularMixture -case "$dir" -fromCase -dryRun > "$log" 2>&1 || { tail -20 "$log"; return 1; }
    expect_lines "$log" "the T list of system/calibrationDict is used: (0.005 0.02)" "18 of 18 conditions would run" || return 1
    grep -q "entry 'T' of .* is overridden" "$log" && { echo "T reported overridden although used"; return 1; }
    echo "T from calibrationDict when the field is missing: ok"
}

# -fromCase with the rheology calibrated: the rheology cells' pressure is
# the median of the case's p over the cells holding material that shear
# (gammaDot >= minGammaDotRatio x its largest); without gammaDot every cell
# holding material; the entry rheology/pressure is then optional and, when
# given, overridden (or used, when the case wrote no p); no p and no entry,
# or a median <= 0: FatalError naming p and the entry; without -fromCase the
# entry stays required
test_calibration_from_case_rheology()
{
    local dir="$workRoot/calibrationFromCaseRheology" log
    fresh_rheology_case()
    {
        rm -rf "$dir"; cp -r "$projectDir/tests/calibration/fromCase" "$dir"
        foamDictionary -entry diffusivity/model -set none "$dir/constant/granularProperties" > /dev/null
        foamDictionary -entry coefficients -set "(rheology)" "$dir/system/calibrationDict" > /dev/null
        foamDictionary -entry rheology -set "{ inertialNumber (0.05 0.1); }" "$dir/system/calibrationDict" > /dev/null
        # cells: material in 1, 2, 4, 5 (3 is below phiMin); gammaDot 2, 50,
        # 0.5, 0.01 of them: cell 5 below 1e-3 x 50
        sed 's/object T;/object p;/; s/\[0 2 -2 0 0 0 0\]/[1 -1 -2 0 0 0 0]/; s/5(0.004 0.04 10 0.01 0.001)/5(100 400 9 200 800)/' \
            "$dir/2/T" > "$dir/2/p"
        sed 's/object T;/object gammaDot;/; s/\[0 2 -2 0 0 0 0\]/[0 0 -1 0 0 0 0]/; s/5(0.004 0.04 10 0.01 0.001)/5(2 50 1e3 0.5 0.01)/' \
            "$dir/2/T" > "$dir/2/gammaDot"
    }

    # p of the shearing cells 100, 400, 200: the median 200 Pa
    fresh_rheology_case
    log="$dir/log.shearing"
    calibrateGranularMixture -case "$dir" -fromCase -dryRun > "$log" 2>&1 || { tail -20 "$log"; return 1; }
    grep -e "-fromCase rheology" -e sigma_yy "$log"
    expect_lines "$log" \
        "-fromCase rheology: p over 3 cells holding material with gammaDot >= 0.001 x its largest: [100, 400] Pa, median 200 Pa" \
        "x 1 replicas) at sigma_yy 200 Pa," || return 1

    # the entry given: overridden
    foamDictionary -entry rheology/pressure -set 3000 "$dir/system/calibrationDict" > /dev/null
    log="$dir/log.overridden"
    calibrateGranularMixture -case "$dir" -fromCase -dryRun > "$log" 2>&1 || { tail -20 "$log"; return 1; }
    expect_lines "$log" "median 200 Pa" "(the entry rheology/pressure 3000 Pa is overridden)" "x 1 replicas) at sigma_yy 200 Pa," || return 1

    # no gammaDot: every cell holding material, p 100, 400, 200, 800: the
    # upper median 400
    rm "$dir/2/gammaDot"
    log="$dir/log.noShear"
    calibrateGranularMixture -case "$dir" -fromCase -dryRun > "$log" 2>&1 || { tail -20 "$log"; return 1; }
    expect_lines "$log" "p over 4 cells holding material (no field gammaDot: every one): [100, 800] Pa, median 400 Pa" \
        "x 1 replicas) at sigma_yy 400 Pa," || return 1

    # no p, the entry given: the entry is used
    rm "$dir/2/p"
    log="$dir/log.noPEntry"
    calibrateGranularMixture -case "$dir" -fromCase -dryRun > "$log" 2>&1 || { tail -20 "$log"; return 1; }
    expect_lines "$log" "no field p at time 2" "the entry rheology/pressure 3000 Pa is used" "x 1 replicas) at sigma_yy 3000 Pa," || return 1
    echo "no p, the entry: $(grep "no field p" "$log")"

    # no p and no entry: FatalError naming p and the entry, nothing run
    fresh_rheology_case
    rm "$dir/2/p"
    log="$dir/log.noP"
    if calibrateGranularMixture -case "$dir" -fromCase > "$log" 2>&1
    then
        echo "no p and no pressure accepted"; return 1
    fi
    expect_lines "$log" "FOAM FATAL" "the field p is missing" "2/p" "give 'pressure' [Pa]" || return 1
    grep -q "done in" "$log" && { echo "DEM ran"; return 1; }
    [ ! -e "$dir/constant/calibration.h5" ] || { echo "calibration.h5 written"; return 1; }
    echo "no p: $(grep -A1 "FOAM FATAL" "$log" | sed -n 2p)"

    # the shearing cells' median <= 0 (a weightless case): refused
    fresh_rheology_case
    sed -i 's/5(100 400 9 200 800)/5(-100 0 9 -5 800)/' "$dir/2/p"
    log="$dir/log.negative"
    if calibrateGranularMixture -case "$dir" -fromCase -dryRun > "$log" 2>&1
    then
        echo "median pressure <= 0 accepted"; return 1
    fi
    expect_lines "$log" "FOAM FATAL" "median pressure -5 Pa" "is not > 0" || return 1
    echo "median <= 0: $(grep -A1 "FOAM FATAL" "$log" | sed -n 2p)"

    # without -fromCase the entry stays required
    fresh_rheology_case
    log="$dir/log.noFromCase"
    if calibrateGranularMixture -case "$dir" -dryRun > "$log" 2>&1
    then
        echo "no pressure accepted without -fromCase"; return 1
    fi
    expect_lines "$log" "FOAM FATAL IO ERROR" "Missing entry 'pressure'" || return 1
    echo "without -fromCase: $(grep -A1 "FOAM FATAL" "$log" | sed -n 2p)"
}
