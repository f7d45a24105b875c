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
