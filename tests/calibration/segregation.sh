# shellcheck shell=bash
# calibrateGranularMixture's segregation velocity (coefficients
# (segregationVelocity)): the percolation length S of the coarse from sheared
# cells under gravity of the case's grains, fitted as a law of p*, written as
# constant/segregationVelocity, which `percolation calibrated` reads.
# Sourced by tests/run; tests calibration/segregation/*.

# segregation_case DIR "ENTRY": the tutorial's grains (1 and 2 mm, e 0.9,
# friction 0.3, k_n 2000 N/m) calibrating only the segregation velocity;
# small cells (1000 grains, the walls 3 coarse diameters thick, 0.25 s of
# development at U 0.8 m/s: the top wall carries its load within 2 %)
segregation_case()
{
    copy_calibration_case "$1"
    local d="$1/system/calibrationDict"
    foamDictionary -entry coefficients -set "(segregationVelocity)" "$d" > /dev/null
    foamDictionary -entry timeStep -set 1e-6 "$d" > /dev/null
    foamDictionary -entry segregationVelocity -set "{ particles 1000; heightRatio 6; wallSpeed 0.8; developmentTime 0.25; samplingTime 0.05; blocks 2; sampleEvery 100; diffusionStrain 0.2; driftEndStrain 3; $2 }" "$d" > /dev/null
}

# The calibration of 3 cells (sigma_N 100, 400, 1600 Pa; about 55 s on 2
# cores): each stored by its name with its segregation group and a top wall
# that carried its load; the written law is the AIC's choice, and its B, C
# minimise the weighted chi2 of the Trewhela form over the stored cells' p*,
# R, c and S (each moved by 1e-3 of itself, chi2 does not drop); C of the
# shear-rate diffusivity is the stored cells' weighted mean; a rerun runs
# nothing and writes the same file; percolation calibrated reads the file
# (the uniform shear column, its law's B in the log)
test_calibration_segregation()
{
    local dir="$workRoot/calibrationSegregation"
    segregation_case "$dir" "normalStress (100 400 1600);"
    local start=$SECONDS
    calibrateGranularMixture -case "$dir" > "$dir/log.1" 2>&1 || { tail -30 "$dir/log.1"; return 1; }
    echo "segregation calibration of 3 cells: $((SECONDS - start)) s"
    grep -E "^condition|^(fanSchlick|trewhela)|model choice|shear-rate" "$dir/log.1"
    local h5="$dir/constant/calibration.h5" file="$dir/constant/segregationVelocity"
    local groups
    groups=$(h5ls "$h5/conditions" | awk '{print $1}')
    [ "$(echo "$groups" | grep -c '^segregation_sigma')" -eq 3 ] || { echo "3 segregation cells expected in the store:"; echo "$groups"; return 1; }
    echo "$groups" | grep -q "^segregation_sigma400_x0.5_seed1$" || { echo "cell not stored by its name"; return 1; }
    local rows g
    rows=$(for g in $groups
    do
        local a=() k
        for k in pressureNumber sizeRatio coarseShare fineDiameter percolationLengthBalance \
                 percolationLengthBalanceError shearRateDiffusivity shearRateDiffusivityError topWallLoad
        do
            a+=(-a "/conditions/$g/segregation/$k")
        done
        h5dump "${a[@]}" -m "%.17g" "$h5" | awk '/\(0\):/ { $1 = ""; printf "%s ", $0 } END { print "" }'
    done)
    echo "store rows (p* R c d S Serr C Cerr load):"; echo "$rows"
    [ "$(foamDictionary -entry segregationVelocity/law -value "$file")" = trewhela ] \
        || { echo "the law written is not trewhela:"; cat "$file"; return 1; }
    local B C Cd
    B=$(foamDictionary -entry segregationVelocity/B -value "$file") || return 1
    C=$(foamDictionary -entry segregationVelocity/C -value "$file") || return 1
    Cd=$(foamDictionary -entry shearRateDiffusivity/C -value "$file") || return 1
    echo "written: trewhela B $B C $C; shearRateDiffusivity C $Cd"
    python3 - "$B" "$C" "$Cd" <<PY || return 1
import sys
B, C, Cd = (float(v) for v in sys.argv[1:])
rows = [tuple(float(v) for v in l.split()) for l in """$rows""".strip().splitlines()]
assert len(rows) == 3, rows
for r in rows:
    assert abs(r[8] - 1) <= 0.05, "a stored cell's top wall did not carry its load: %s" % (r,)
def chi2(b, c):
    return sum(((S - b*d*(1 - x + x*R)*(R - 1)/(c + p))/e)**2 for p, R, x, d, S, e, *_ in rows)
best = chi2(B, C)
worst = 0.0
for k in range(2):
    for sign in (-1, 1):
        p = [B, C]
        p[k] *= 1 + sign*1e-3
        worst = min(worst, chi2(*p) - best)
print("chi2 at the written B, C %.6g; largest drop when moved by 1e-3: %.3g" % (best, -worst))
assert worst > -1e-6*max(best, 1e-3), "B, C are not the weighted least-squares fit of the stored cells"
w = [1/r[7]**2 for r in rows]
mean = sum(wi*r[6] for wi, r in zip(w, rows))/sum(w)
print("C of the diffusivity: weighted mean of the stored cells %.6g, written %.6g" % (mean, Cd))
assert abs(mean - Cd) <= 1e-5*mean, "shearRateDiffusivity C is not the stored cells' weighted mean"
PY
    [ -s "$dir/postProcessing/calibration/segregation.dat" ] || { echo "no segregation.dat"; return 1; }

    # Resume: everything stored, nothing runs, the same file
    cp "$file" "$dir/segregationVelocity.1"
    calibrateGranularMixture -case "$dir" > "$dir/log.2" 2>&1 || { tail -20 "$dir/log.2"; return 1; }
    grep -q "^DEM: 0 conditions run and stored, 3 taken from" "$dir/log.2" || { grep "^DEM" "$dir/log.2"; echo "the rerun ran cells"; return 1; }
    diff -q "$file" "$dir/segregationVelocity.1" > /dev/null || { diff "$file" "$dir/segregationVelocity.1"; echo "the rerun changed the file"; return 1; }

    # The solver reads it: percolation calibrated in the uniform shear column
    rm -rf "$dir/column"; mkdir -p "$dir/column"
    cp -r "$validationDir/uniformShearColumn" "$dir/column/"
    local case="$dir/column/uniformShearColumn"
    sed -i '/^percolation/,/^}/s/model       shearRate;/model       calibrated;/' "$case/constant/granularProperties"
    echo 'libs ("libcalibratedModels.so");' >> "$case/system/controlDict"
    cp "$file" "$case/constant/granularCoefficients"
    "$case/Allrun" -n 50 > "$dir/log.column" 2>&1 || { tail -20 "$dir/log.column"; return 1; }
    grep "percolation calibrated" "$case/log.segregationDegradationFoam" | head -1
    grep -q "percolation calibrated: S = B\*dMean\*(R - 1)/(C + pStar).*, B = $B" "$case/log.segregationDegradationFoam" \
        || { echo "the solver did not report the calibrated law with B $B"; return 1; }
    (cd "$case" && ./check --bounds-only > "$dir/check.log" 2>&1) || { cat "$dir/check.log"; return 1; }
    tail -n 3 "$dir/check.log"
}

# -fromCase: the loads from the p* the case's law visited (the hand-made
# case of tests/calibration/fromCase, a field pStar of 5 cells, material in
# 1, 2, 4, 5): p* 0.5-120, from minPressureNumber 2, 4 points log-spaced; the
# field p (muI) instead: p over rho_s g dMean; neither: a FatalError naming
# both and the entry; the entry given: used
test_calibration_segregation_from_case()
{
    local dir="$workRoot/calibrationSegregationFromCase" log
    rm -rf "$dir"; cp -r "$projectDir/tests/calibration/fromCase" "$dir"
    foamDictionary -entry diffusivity/model -set none "$dir/constant/granularProperties" > /dev/null
    foamDictionary -entry kineticSieving/model -set none "$dir/constant/granularProperties" > /dev/null
    foamDictionary -entry coefficients -set "(segregationVelocity)" "$dir/system/calibrationDict" > /dev/null
    foamDictionary -entry segregationVelocity -set "{ particles 1000; heightRatio 6; }" "$dir/system/calibrationDict" > /dev/null
    sed 's/object T;/object pStar;/; s/\[0 2 -2 0 0 0 0\]/[0 0 0 0 0 0 0]/; s/5(0.004 0.04 10 0.01 0.001)/5(0.5 3 9 30 120)/' \
        "$dir/2/T" > "$dir/2/pStar"
    # rho_s g dMean: 2500 x 9.81 x 1.5 mm (x 0.5) = 36.7875 Pa
    log="$dir/log.pStar"
    calibrateGranularMixture -case "$dir" -fromCase -dryRun > "$log" 2>&1 || { tail -20 "$log"; return 1; }
    grep -e "-fromCase segregation" -e "sheared cells under gravity" "$log"
    local expected
    expected=$(python3 -c '
import math
def r4(v): return float("%.4g" % v)
lo, hi = 2.0, 120.0
ps = [r4(math.exp(math.log(lo) + i*(math.log(hi) - math.log(lo))/3)) for i in range(4)]
unit = 2500*9.81*1.5e-3
print("(" + " ".join("%g" % p for p in ps) + ") -> sigma_N (" + " ".join("%g" % (p*unit) for p in ps) + ") Pa")')
    expect_lines "$log" "-fromCase segregation: p* of the 4 cells holding material (field pStar) [0.5, 120], from minPressureNumber 2: p* $expected" \
        "Segregation velocity: 4 sheared cells under gravity" || return 1

    # the bulk's p (muI) instead of pStar: p* = p/(rho_s g dMean)
    rm "$dir/2/pStar"
    sed 's/object T;/object p;/; s/\[0 2 -2 0 0 0 0\]/[1 -1 -2 0 0 0 0]/; s/5(0.004 0.04 10 0.01 0.001)/5(36.7875 367.875 9 3678.75 7357.5)/' \
        "$dir/2/T" > "$dir/2/p"
    log="$dir/log.p"
    calibrateGranularMixture -case "$dir" -fromCase -dryRun > "$log" 2>&1 || { tail -20 "$log"; return 1; }
    expect_lines "$log" "(field p/(rho_s g dMean)) [1, 200], from minPressureNumber 2: p* (2 9.283 43.09 200)" || return 1
    grep -e "-fromCase segregation" "$log"

    # neither field: refused, naming both and the entry
    rm "$dir/2/p"
    log="$dir/log.none"
    if calibrateGranularMixture -case "$dir" -fromCase -dryRun > "$log" 2>&1
    then
        echo "-fromCase without pStar or p was accepted"; return 1
    fi
    expect_lines "$log" "no field pStar (written by percolation calibrated) or p (written by bulkFlow muI)" \
        "give segregationVelocity/normalStress [Pa]" || return 1

    # the entry given: used as it is
    foamDictionary -entry segregationVelocity/normalStress -set "(50 500 5000)" "$dir/system/calibrationDict" > /dev/null
    log="$dir/log.entry"
    calibrateGranularMixture -case "$dir" -fromCase -dryRun > "$log" 2>&1 || { tail -20 "$log"; return 1; }
    expect_lines "$log" "3 sheared cells under gravity (sigma_N (50 500 5000) Pa" || return 1
}

# Bad input, each refused by name before any cell runs (dry runs): the
# coefficient without its entry, the entry without the coefficient, no loads,
# a load <= 0, an unknown estimator, walls closer than 10 coarse diameters,
# zero gravity, fewer than 3 loads, too few layers, an early drift's window
# outside the development; and cells that never reach their state (a
# development too short for the top wall to land and finish its ramp before
# the early drift) are reported, nothing is stored for them
# and no segregationVelocity is written
test_calibration_segregation_refusals()
{
    local dir="$workRoot/calibrationSegregationRefusals" log d
    refused()   # refused "entry" "message"
    {
        segregation_case "$dir" "$1"
        log="$dir/log.refused"
        if calibrateGranularMixture -case "$dir" -dryRun > "$log" 2>&1
        then
            echo "accepted: $1"; return 1
        fi
        grep -qF -- "$2" "$log" || { echo "missing for '$1': '$2'"; grep -A4 FATAL "$log"; return 1; }
        echo "refused: $1 -> $2"
    }
    refused "" "Missing entry 'normalStress' [Pa]" || return 1
    refused "normalStress (100 400);" "Entry 'normalStress 2(100 400)': give at least 3 loads" || return 1
    refused "normalStress (100 400 1600); layers 3;" "entry 'layers': 3 layers leave fewer than two layers" || return 1
    refused "normalStress (100 400 1600); developmentTime 0.1;" "the early drift would be read from" || return 1
    refused "normalStress (0 100);" "Envelope entry 'normalStress' (the top wall's loads sigma_N [Pa], each > 0): value 0 is outside" || return 1
    refused "normalStress (100 400 1600); estimator steady;" "Entry 'estimator steady': valid: balance" || return 1
    refused "normalStress (100 400 1600); particles 300;" "the walls would be" || return 1
    refused "normalStress (100 400 1600); gravity 0;" "Entry 'gravity 0' (g [m/s^2], normal to the walls) must lie in (0" || return 1
    segregation_case "$dir" "normalStress (100 400 1600);"
    d="$dir/system/calibrationDict"
    foamDictionary -entry segregationVelocity -remove "$d" > /dev/null
    log="$dir/log.noEntry"
    if calibrateGranularMixture -case "$dir" -dryRun > "$log" 2>&1; then echo "no entry accepted"; return 1; fi
    grep -qF "'coefficients' holds segregationVelocity but the sub-dictionary 'segregationVelocity' is missing" "$log" \
        || { grep -A4 FATAL "$log"; return 1; }
    segregation_case "$dir" "normalStress (100 400 1600);"
    foamDictionary -entry coefficients -set "(D)" "$d" > /dev/null
    log="$dir/log.noCoefficient"
    if calibrateGranularMixture -case "$dir" -dryRun > "$log" 2>&1; then echo "entry without coefficient accepted"; return 1; fi
    grep -qF "Entry 'segregationVelocity' given, but 'coefficients' 1(D) does not hold segregationVelocity" "$log" \
        || { grep -A4 FATAL "$log"; return 1; }

    # cells that never reach their state: reported, not stored, no file
    segregation_case "$dir" "normalStress (100 400 1600); developmentTime 0.003; driftStartStrain 0.01; driftEndStrain 0; samplingTime 0.002;"
    log="$dir/log.unsheared"
    if calibrateGranularMixture -case "$dir" > "$log" 2>&1; then echo "a calibration of unsheared cells succeeded"; return 1; fi
    # (the wall not yet landed: either reason, by the sign of the noisy shear)
    [ "$(grep -cE "left out of the segregation fit, not stored \((the top wall had slid 0.000000 strains|refused by the DEM engine: the interior was not sheared)" "$log")" -eq 3 ] \
        || { grep "^condition" "$log"; return 1; }
    grep -qF "Only 0 sheared cells under gravity reached their condition (3 left out)" "$log" || { grep -A4 FATAL "$log"; return 1; }
    if [ -f "$dir/constant/calibration.h5" ] && h5ls "$dir/constant/calibration.h5/conditions" 2>/dev/null | grep -q segregation
    then
        echo "an unsheared cell was stored"; return 1
    fi
    [ ! -e "$dir/constant/segregationVelocity" ] || { echo "segregationVelocity written without cells"; return 1; }
    echo "unsheared cells: 3 left out, none stored, no segregationVelocity"
}

# Three sheared cells under gravity over 2 MPI ranks (-parallel, -noFit):
# dealt 2 + 1, both stores merged, and the merged store's cells (timings
# aside) identical to a serial run's, two cells at a time there (about 3.5
# min under the test suite's load when the serial run went one at a time)
test_calibration_segregation_parallel()
{
    local ref="$workRoot/calibrationSegregationSerial" dir="$workRoot/calibrationSegregationParallel" d
    for d in "$ref" "$dir"
    do
        segregation_case "$d" "normalStress (100 400 1600);"
    done
    calibrateGranularMixture -case "$ref" -noFit > "$ref/log" 2>&1 || { tail -20 "$ref/log"; return 1; }
    mpirun --allow-run-as-root --oversubscribe -np 2 calibrateGranularMixture -parallel -case "$dir" -noFit > "$dir/log" 2>&1 \
        || { tail -20 "$dir/log"; return 1; }
    local r0 r1
    r0=$(grep -c "^\[0\] condition .* done in" "$dir/log")
    r1=$(grep -c "^\[1\] condition .* done in" "$dir/log")
    echo "rank 0 ran $r0, rank 1 ran $r1 segregation cells"
    [ "$r0" -eq 2 ] && [ "$r1" -eq 1 ] || { echo "cells not spread 2 + 1 over the ranks"; return 1; }
    grep -q "Merged 3 conditions of 2 processor stores" "$dir/log" || { grep -i merged "$dir/log"; echo "no merge of 3 conditions"; return 1; }
    dump_conditions "$ref/constant/calibration.h5" > "$ref/conditions.txt"
    dump_conditions "$dir/constant/calibration.h5" > "$dir/conditions.txt"
    [ "$(grep -c 'GROUP "segregation"' "$ref/conditions.txt")" -eq 3 ] || { echo "the serial store lacks its 3 segregation groups"; return 1; }
    diff -q "$ref/conditions.txt" "$dir/conditions.txt" > /dev/null \
        || { echo "cells differ from the serial run:"; diff "$ref/conditions.txt" "$dir/conditions.txt" | head -20; return 1; }
    echo "3 cells on 2 ranks: the store ($(wc -l < "$dir/conditions.txt") dump lines) identical to the serial run's"
}
