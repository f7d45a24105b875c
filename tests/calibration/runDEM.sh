# shellcheck shell=bash
# runDEM, the calibrated models' runner of missing DEM conditions (sourced by
# tests/run; tests calibration/runDEM/*): its store is shared with
# calibrateGranularMixture, and it grows the table during a silo2D run.

# runDEM of the solver's calibrated models (mode tabulated) stores conditions
# that calibrateGranularMixture recognises: the unit test's runDEM, with the
# tutorial's DEM settings, adds the phi 0.42 slice (4 conditions) to a
# synthetic 2x2x2 table; the utility, asked for that slice with the same
# settings, skips all four (same settings key and layout) and runs nothing
test_calibrated_run_dem()
{
    local dir="$workRoot/calibratedRunDEM"
    rm -rf "$dir"; cp -r tests/unit/testCase "$dir"
    blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || return 1
    sed -e 's/^phi .*/phi (0.42);/' -e 's/^x .*/x (0.2 0.4);/' \
        -e 's/^T .*/T (0.005 0.02);/' -e 's/^plot .*/plot false;/' \
        "$calibrationCase/system/calibrationDict" > "$dir/system/calibrationDict"
    calibratedModelsTest -case "$dir" --gtest_filter='*RunDEM*' \
        > "$dir/log.calibratedModelsTest" 2>&1 \
        || { tail -30 "$dir/log.calibratedModelsTest"; return 1; }
    grep "runDEM" "$dir/log.calibratedModelsTest"
    mv "$dir/constant/calibrationRunDEM.h5" "$dir/constant/calibration.h5"
    calibrateGranularMixture -noFit -case "$dir" \
        > "$dir/log.calibrateGranularMixture" 2>&1 \
        || { tail -30 "$dir/log.calibrateGranularMixture"; return 1; }
    local skipped
    skipped=$(grep -c "^skipping condition" "$dir/log.calibrateGranularMixture")
    grep -E "^skipping|^DEM:" "$dir/log.calibrateGranularMixture"
    [ "$skipped" -eq 4 ] || { echo "the utility skipped $skipped of the 4 runDEM conditions"; return 1; }
    grep -q "^DEM: 0 conditions run" "$dir/log.calibrateGranularMixture" \
        || { echo "the utility ran conditions runDEM had stored"; return 1; }
}

# silo2D with the tabulated diffusivity and runDEM: a 2x2x2 store from
# calibrateGranularMixture (small DEM settings: 100 particles, 0.002 s
# sampling), 1 s of discharge: runDEM grows the grid (phi to the packed 0.6,
# the quiet T floor, x as the mixture segregates), every run is stored, the
# fields stay bounded; a rerun on the grown store runs no DEM (cached)
test_silo_tabulated_run_dem()
{
    local dir="$workRoot/siloTabulatedRunDEM"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$projectDir/tutorials/silo2D/"{0.orig,constant,system} "$dir/"
    rm -rf "$dir/constant/polyMesh" "$dir/constant/granularCoefficients" \
        "$dir/constant/granularPropertiesOverrides" "$dir/constant/calibration.h5"
    sed -e 's/^particles .*/particles 100;/' -e 's/^samplingTime .*/samplingTime 0.002;/' \
        -e 's/^plot .*/plot false;/' \
        "$calibrationCase/system/calibrationDict" > "$dir/system/calibrationDict"
    calibrateGranularMixture -noFit -case "$dir" > "$dir/log.calibrateGranularMixture" 2>&1 \
        || { tail -30 "$dir/log.calibrateGranularMixture"; return 1; }
    printf 'endTime 1;\nwriteInterval 1;\nlibs ("libcalibratedModels.so");\n' > "$dir/system/caseParameters"
    cat > "$dir/constant/granularPropertiesOverrides" <<'OVERRIDES'
diffusivity
{
    model       calibrated;
    calibratedCoeffs { mode tabulated; outsideEnvelope runDEM; }
}
OVERRIDES
    blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || return 1
    cp -r "$dir/0.orig" "$dir/0"
    local start=$SECONDS
    segregationDegradationFoam -case "$dir" > "$dir/log.solver" 2>&1 \
        || { tail -30 "$dir/log.solver"; return 1; }
    echo "solver with runDEM: $((SECONDS - start)) s"
    ! grep -q "FOAM FATAL" "$dir/log.solver" || { tail -30 "$dir/log.solver"; return 1; }
    grep -E "^runDEM|new grid values" "$dir/log.solver"
    local runs stored
    runs=$(grep -c "runDEM: phi.* done in" "$dir/log.solver")
    [ "$runs" -gt 0 ] || { echo "runDEM ran nothing"; return 1; }
    stored=$(h5ls "$dir/constant/calibration.h5/conditions" | wc -l)
    [ "$stored" -eq $((8 + runs)) ] || { echo "$stored conditions stored, expected 8 + $runs"; return 1; }
    python3 -m sdfoam.fieldStats "$dir" bounds --tol 1e-8 || return 1

    rm -rf "$dir/0" "$dir/1" "$dir/postProcessing"
    cp -r "$dir/0.orig" "$dir/0"
    segregationDegradationFoam -case "$dir" > "$dir/log.solverRerun" 2>&1 \
        || { tail -30 "$dir/log.solverRerun"; return 1; }
    ! grep -q "runDEM: phi" "$dir/log.solverRerun" \
        || { echo "the rerun ran DEM conditions again"; return 1; }
}

# The tabulated models interpolate one value per (phi, x, T) grid point: a
# store of a finite-size calibration (cells of several sizes per point) and
# a store of sheared cells (no T grid) are refused with a FatalIOError naming
# the reason, before any time step
test_table_refuses_sized_and_sheared_stores()
{
    local dir="$workRoot/tableRefusals" kind expect
    for kind in finiteSize sheared
    do
        rm -rf "$dir"; mkdir -p "$dir"
        cp -r "$projectDir/tutorials/silo2D/"{0.orig,constant,system} "$dir/"
        rm -rf "$dir/constant/polyMesh" "$dir/constant/granularCoefficients" \
            "$dir/constant/granularPropertiesOverrides" "$dir/constant/calibration.h5"
        sed -e 's/^samplingTime .*/samplingTime 0.002;/' -e 's/^plot .*/plot false;/' \
            -e 's/^phi .*/phi (0.3);/' -e 's/^x .*/x (0.2);/' \
            "$calibrationCase/system/calibrationDict" > "$dir/system/calibrationDict"
        local d="$dir/system/calibrationDict"
        if [ "$kind" = finiteSize ]
        then
            foamDictionary -entry particles -remove "$d" > /dev/null
            foamDictionary -entry finiteSize -set "{ particles (100 200); }" "$d" > /dev/null
            expect="finite-size calibration"
        else
            foamDictionary -entry particles -set 100 "$d" > /dev/null
            foamDictionary -entry mode -set leesEdwards "$d" > /dev/null
            foamDictionary -entry T -remove "$d" > /dev/null
            foamDictionary -entry gammaDot -set "(20 40)" "$d" > /dev/null
            for e in equilibrationTime maxEquilibrationTime samplingTime
            do
                foamDictionary -entry "$e" -remove "$d" > /dev/null
            done
            foamDictionary -entry samplingStrain -set 1 "$d" > /dev/null
            expect="is a sheared cell"
        fi
        calibrateGranularMixture -noFit -case "$dir" > "$dir/log.calibrateGranularMixture" 2>&1 \
            || { tail -30 "$dir/log.calibrateGranularMixture"; return 1; }
        printf 'endTime 1;\nwriteInterval 1;\nlibs ("libcalibratedModels.so");\n' > "$dir/system/caseParameters"
        printf 'diffusivity { model calibrated; calibratedCoeffs { mode tabulated; } }\n' \
            > "$dir/constant/granularPropertiesOverrides"
        blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || return 1
        cp -r "$dir/0.orig" "$dir/0"
        if segregationDegradationFoam -case "$dir" > "$dir/log.solver" 2>&1
        then
            echo "$kind store accepted as a table"; return 1
        fi
        echo "$kind: $(grep -A3 "FOAM FATAL" "$dir/log.solver" | grep -o "condition.*" | head -1)"
        grep -q "FOAM FATAL IO ERROR" "$dir/log.solver" || { tail -10 "$dir/log.solver"; return 1; }
        grep -q "$expect" "$dir/log.solver" || { echo "message lacks '$expect'"; tail -10 "$dir/log.solver"; return 1; }
        [ ! -d "$dir/1" ] || { echo "a time step was written"; return 1; }
    done
}
