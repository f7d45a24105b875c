# shellcheck shell=bash
# Tests of tests/unit/ (sourced by tests/run): the GoogleTest program
# granularModelsTest on its small case.

test_unit_models()
{
    local dir="$workRoot/unitCase"
    rm -rf "$dir"; cp -r tests/unit/testCase "$dir"
    blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || return 1
    granularModelsTest -case "$dir"
}
