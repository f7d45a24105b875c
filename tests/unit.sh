# shellcheck shell=bash
# Tests of tests/unit/ (sourced by tests/run): the GoogleTest program
# granularModelsTest and calibratedModelsTest on their small case.

test_unit_models()
{
    local dir="$workRoot/unitCase"
    rm -rf "$dir"; cp -r tests/unit/testCase "$dir"
    blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || return 1
    granularModelsTest -case "$dir"
}

test_unit_calibrated_models()
{
    local dir="$workRoot/unitCalibratedCase"
    rm -rf "$dir"; cp -r tests/unit/testCase "$dir"
    blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || return 1
    calibratedModelsTest -case "$dir"
}

test_unit_breakage_models()
{
    local dir="$workRoot/unitBreakageCase"
    rm -rf "$dir"; cp -r tests/unit/breakageCase "$dir"
    blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || return 1
    breakageModelsTest -case "$dir"
}
