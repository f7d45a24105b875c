# shellcheck shell=bash
# calibrateGranularMixture on tutorials/calibration/binary21 (8 small DEM
# conditions, about 10 s), serial (sourced by tests/run; tests
# calibration/calibrateGranularMixture/*). copy_calibration_case and
# dump_conditions are shared with the other files of tests/calibration/.

copy_calibration_case()
{
    rm -rf "$1"; mkdir -p "$1"
    cp -r "$calibrationCase/constant" "$calibrationCase/system" "$1/"
    rm -f "$1/constant/calibration.h5"* "$1/constant/granularCoefficients"*
}

# h5dump of the condition groups without the timing groups (the only values
# that differ between identical runs)
dump_conditions()
{
    h5dump -g /conditions "$1" | python3 -c '
import sys
out, skip = [], 0
for line in sys.stdin:
    s = line.strip()
    if skip:
        skip += s.count("{") - s.count("}")
        continue
    if s.startswith("GROUP \"timing\""):
        skip = s.count("{") - s.count("}")
        continue
    out.append(line)
sys.stdout.write("".join(out[1:]))'
}

# A small calibration completes: calibration.h5 readable, one group per
# condition, granularCoefficients with D/law readable by foamDictionary
test_calibration_run()
{
    local dir="$workRoot/calibration"
    copy_calibration_case "$dir"
    local start=$SECONDS
    calibrateGranularMixture -case "$dir" > "$dir/log.calibrateGranularMixture" 2>&1 \
        || { tail -30 "$dir/log.calibrateGranularMixture"; return 1; }
    echo "calibration of 8 conditions: $((SECONDS - start)) s"
    h5dump -H "$dir/constant/calibration.h5" > "$dir/h5dump.txt" || { echo "h5dump cannot read calibration.h5"; return 1; }
    local n
    n=$(h5ls "$dir/constant/calibration.h5/conditions" | wc -l)
    [ "$n" -eq 8 ] || { echo "$n condition groups, expected 8"; return 1; }
    local law
    law=$(foamDictionary -entry D/law -value "$dir/constant/granularCoefficients") || return 1
    echo "D/law = $law"
    case "$law" in powerLaw|kineticTheoryGroups) ;; *) echo "unexpected law"; return 1 ;; esac
    grep -E "chosen for D|done in" "$dir/log.calibrateGranularMixture" | tail -3
    [ -s "$dir/postProcessing/calibration/D_x0.2.dat" ] || { echo "no D(T) data for the plot"; return 1; }
    if command -v gnuplot > /dev/null
    then
        [ -s "$dir/postProcessing/calibration/D_x0.2.png" ] || { echo "no D(T) plot"; return 1; }
    fi
}

# Resume: a run killed (kill -9) after its first stored condition, rerun,
# skips the stored conditions and ends with the same condition groups and
# values (bitwise) as an uninterrupted run
test_calibration_resume()
{
    local ref="$workRoot/calibrationResumeRef" dir="$workRoot/calibrationResume"
    copy_calibration_case "$ref"
    copy_calibration_case "$dir"
    calibrateGranularMixture -case "$ref" -noFit > "$ref/log" 2>&1 || { tail -20 "$ref/log"; return 1; }

    local stored
    stored=$(kill_after_first_condition "$dir" "$dir/log.1")
    echo "killed after $stored stored conditions"
    [ "$stored" -ge 1 ] && [ "$stored" -lt 8 ] || { echo "kill did not land mid-run"; return 1; }

    calibrateGranularMixture -case "$dir" -noFit > "$dir/log.2" 2>&1 || { tail -20 "$dir/log.2"; return 1; }
    check_resumed_rerun "$dir/log.2" "$stored" 8 || return 1

    dump_conditions "$ref/constant/calibration.h5" > "$ref/conditions.txt"
    dump_conditions "$dir/constant/calibration.h5" > "$dir/conditions.txt"
    [ -s "$ref/conditions.txt" ] || { echo "empty dump"; return 1; }
    diff -q "$ref/conditions.txt" "$dir/conditions.txt" > /dev/null \
        || { diff "$ref/conditions.txt" "$dir/conditions.txt" | head -20; return 1; }
    echo "resumed calibration.h5 identical to the uninterrupted one ($(wc -l < "$dir/conditions.txt") dump lines, timing groups excluded)"
}

# Bad input: a FatalIOError/FatalError naming the entry or file; no DEM run,
# no granularCoefficients, a foreign calibration.h5 left untouched
test_calibration_bad_input()
{
    local dir="$workRoot/calibrationBad" kind
    local kinds="unknownCoefficient unknownLaw emptyPhi invertedT jammedPhi negativeT xOutside textStore foreignHdf5 shearedMode pairUnknownSpecies pairSetsNothing pairRestitution"
    [ -f "$workRoot/calibration/constant/calibration.h5" ] && kinds="$kinds truncatedStore settingsChanged drivingChanged"
    for kind in $kinds
    do
        copy_calibration_case "$dir"
        local d="$dir/system/calibrationDict" expect
        case "$kind" in
            unknownCoefficient) foamDictionary -entry coefficients -set "(D viscosity)" "$d" > /dev/null; expect="viscosity" ;;
            unknownLaw) foamDictionary -entry laws -set "(powerLaw magic)" "$d" > /dev/null; expect="magic" ;;
            emptyPhi) foamDictionary -entry phi -set "()" "$d" > /dev/null; expect="'phi'" ;;
            invertedT) foamDictionary -entry T -set "(0.02 0.005)" "$d" > /dev/null; expect="increasing order" ;;
            jammedPhi) foamDictionary -entry phi -set "(0.3 0.7)" "$d" > /dev/null; expect="'phi'" ;;
            negativeT) foamDictionary -entry T -set "(0.01 -0.01)" "$d" > /dev/null; expect="'T'" ;;
            xOutside) foamDictionary -entry x -set "(0.2 1.5)" "$d" > /dev/null; expect="'x'" ;;
            textStore) echo "not an HDF5 file" > "$dir/constant/calibration.h5"; expect="calibration.h5" ;;
            foreignHdf5) h5mkgrp -p "$dir/constant/calibration.h5" /someone/else > /dev/null; expect="calibration.h5" ;;
            settingsChanged) cp "$workRoot/calibration/constant/calibration.h5" "$dir/constant/"
                foamDictionary -entry phi -set "(0.2 0.35 0.5)" "$d" > /dev/null
                foamDictionary -entry particles -set 300 "$d" > /dev/null; expect="other DEM settings" ;;
            shearedMode) foamDictionary -entry mode -set leesEdwards "$d" > /dev/null; expect="stochastic" ;;
            pairUnknownSpecies) foamDictionary -entry contact/pairs -set "{ glassSand { species (fine sand); restitution 0.7; } }" "$d" > /dev/null
                expect="unknown species 'sand'; valid: fine coarse" ;;
            pairSetsNothing) foamDictionary -entry contact/pairs -set "{ fineCoarse { species (fine coarse); } }" "$d" > /dev/null
                expect="contact/pairs/fineCoarse' sets nothing" ;;
            pairRestitution) foamDictionary -entry contact/pairs -set "{ fineCoarse { species (fine coarse); restitution 1.4; } }" "$d" > /dev/null
                expect="pair fine/coarse: restitution e = 1.4" ;;
            drivingChanged) cp "$workRoot/calibration/constant/calibration.h5" "$dir/constant/"
                foamDictionary -entry phi -set "(0.2 0.35 0.5)" "$d" > /dev/null
                foamDictionary -entry mode -set stochastic "$d" > /dev/null; expect="other DEM settings" ;;
            truncatedStore) head -c 3000 "$workRoot/calibration/constant/calibration.h5" > "$dir/constant/calibration.h5"; expect="calibration.h5" ;;
        esac
        local before=""
        [ -f "$dir/constant/calibration.h5" ] && before=$(md5sum < "$dir/constant/calibration.h5")
        if calibrateGranularMixture -case "$dir" > "$dir/log" 2>&1
        then
            echo "$kind accepted"; return 1
        fi
        echo "$kind: $(grep -A2 "FOAM FATAL" "$dir/log" | sed -n 2p)"
        grep -q "FOAM FATAL" "$dir/log" || { echo "no fatal error"; return 1; }
        grep -q "$expect" "$dir/log" || { echo "message lacks $expect"; return 1; }
        grep -q "done in" "$dir/log" && { echo "DEM ran"; return 1; }
        [ ! -e "$dir/constant/granularCoefficients" ] || { echo "granularCoefficients written"; return 1; }
        if [ -n "$before" ]
        then
            [ "$(md5sum < "$dir/constant/calibration.h5")" = "$before" ] || { echo "calibration.h5 modified"; return 1; }
        fi
    done
}

# A fit that does not converge is reported naming the law, and
# granularCoefficients is not written. The eta data of the small tutorial
# run: (1 + beta x) cannot follow their x dependence, so beta runs off.
# Reuses the stored conditions of test_calibration_run when present.
test_calibration_fit_failure()
{
    local dir="$workRoot/calibrationFitFailure"
    copy_calibration_case "$dir"
    [ -f "$workRoot/calibration/constant/calibration.h5" ] && cp "$workRoot/calibration/constant/calibration.h5" "$dir/constant/"
    foamDictionary -entry coefficients -set "(D eta)" "$dir/system/calibrationDict" > /dev/null
    # only the (1 + beta x) law, which cannot follow the engine's composition
    # dependence, and a small iteration budget: the fit cannot converge
    foamDictionary -entry etaLaws -set "(sievingPowerLaw)" "$dir/system/calibrationDict" > /dev/null
    foamDictionary -entry fitMaxIterations -set 5 "$dir/system/calibrationDict" > /dev/null
    if calibrateGranularMixture -case "$dir" > "$dir/log" 2>&1
    then
        echo "a fit limited to 5 iterations was reported as good"; return 1
    fi
    grep -A3 "FOAM FATAL" "$dir/log" | head -4
    grep -q "No law for eta could be fitted" "$dir/log" || { echo "failure not reported for eta"; return 1; }
    grep -q "sievingPowerLaw" "$dir/log" || { echo "failure does not name the law"; return 1; }
    [ ! -e "$dir/constant/granularCoefficients" ] || { echo "granularCoefficients written after a failed fit"; return 1; }
}

# eta of the coarse in m2/s: with the default candidate laws the fit converges on
# the tutorial's stored conditions and the dictionary holds the chosen eta law
test_calibration_eta()
{
    local dir="$workRoot/calibrationEta"
    copy_calibration_case "$dir"
    [ -f "$workRoot/calibration/constant/calibration.h5" ] && cp "$workRoot/calibration/constant/calibration.h5" "$dir/constant/"
    foamDictionary -entry coefficients -set "(D eta)" "$dir/system/calibrationDict" > /dev/null
    calibrateGranularMixture -case "$dir" > "$dir/log" 2>&1 || { tail -20 "$dir/log"; return 1; }
    grep -A4 "law sievingCompositionPowerLaw" "$dir/log"
    local law q E
    law=$(foamDictionary -entry eta/law -value "$dir/constant/granularCoefficients") || return 1
    [ "$law" = sievingCompositionPowerLaw ] || { echo "eta law '$law'"; return 1; }
    q=$(foamDictionary -entry eta/q -value "$dir/constant/granularCoefficients") || return 1
    E=$(foamDictionary -entry eta/E -value "$dir/constant/granularCoefficients") || return 1
    echo "eta: E = $E, q = $q"
    # eta grows with the coarse fraction (q > 0) and E is a finite positive number
    python3 -c "import sys, math; E, q = float('$E'), float('$q'); sys.exit(0 if (q > 0 and E > 0 and math.isfinite(E)) else 1)" \
        || { echo "implausible eta law"; return 1; }
    grep -q "eta of the coarse \[m^2/s\]" "$dir/postProcessing/calibration/eta_x0.2.dat" \
        || { echo "eta data not in m2/s"; return 1; }
}
