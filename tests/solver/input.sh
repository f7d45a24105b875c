# shellcheck shell=bash
# Bad input to segregationDegradationFoam (sourced by tests/run; tests
# solver/input/*): each kind of broken case stops with a fatal error naming
# the entry and writes no time directory.

# A small prepared column case (validation column, 10 cells) for bad input
prepare_small_case()
{
    local dir="$1"
    copy_case "$validationDir/segregationDiffusionColumn" "$dir"
    echo "N 10; endTime 0.05;" > "$dir/system/caseParameters"
    blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || return 1
    cp -r "$dir/0.orig" "$dir/0"
}

# set_breakage FILE TEXT: replace the breakage dictionary of granularProperties
set_breakage()
{
    foamDictionary -entry breakage -remove "$1" > /dev/null
    echo "breakage { $2 }" >> "$1"
}

# test_bad_input KIND: break the case one way, expect a fatal error that
# names the entry, and no time directory written
test_bad_input()
{
    local kind="$1" dir="$workRoot/badInput-$1" expect=()
    prepare_small_case "$dir" || return 1
    local gp="$dir/constant/granularProperties"
    case "$kind" in
        unknownModel)
            foamDictionary -entry diffusivity/model -set fancy "$gp" > /dev/null
            expect=("Unknown diffusivity model type fancy" "powerLaw" "kineticTheory" "constant" "none") ;;
        calibratedWithoutLibrary)
            foamDictionary -entry diffusivity/model -set calibrated "$gp" > /dev/null
            expect=("Unknown diffusivity model type calibrated" "libcalibratedModels.so" "system/controlDict") ;;
        missingField)
            rm "$dir/0/n.coarse"
            expect=("n.coarse") ;;
        badDiameter)
            foamDictionary -entry species/coarse/d -set -2e-3 "$gp" > /dev/null
            expect=("Non-positive diameter" "coarse") ;;
        negativeInitial)
            foamDictionary -entry internalField -set "uniform -0.1" "$dir/0/n.fine" > /dev/null
            expect=("n.fine" "-0.1" ">= 0") ;;
        nanInitial)
            sed -i 's/^internalField .*/internalField   uniform nan;/' "$dir/0/n.fine"
            expect=("n.fine") ;;
        missingCoefficient)
            foamDictionary -entry percolation/grayThorntonCoeffs/Sr -remove "$gp" > /dev/null
            expect=("Sr" "grayThorntonCoeffs") ;;
        missingMechanism)
            foamDictionary -entry kineticSieving -remove "$gp" > /dev/null
            expect=("kineticSieving") ;;
        breakageNotConserving)
            set_breakage "$gp" "model constant; constantCoeffs { S { coarse 0.1; } } daughterSizeDistribution { model table; tableCoeffs { coarse { fine 0.9; } } }"
            expect=("coarse" "sum to 0.9" "must sum to 1") ;;
        breakageIntoCoarser)
            set_breakage "$gp" "model constant; constantCoeffs { S { fine 0.1; } } daughterSizeDistribution { model table; tableCoeffs { fine { coarse 1; } } }"
            expect=("'coarse'" "not finer than the parent fine") ;;
        breakageNegativeRate)
            set_breakage "$gp" "model constant; constantCoeffs { S { coarse -0.1; } } daughterSizeDistribution { model uniformBinary; }"
            expect=("S.coarse -0.1" ">= 0") ;;
        breakageNegativeMaterial)
            set_breakage "$gp" "model vogelPeukert; vogelPeukertCoeffs { fMat -2; xWmMin 0.05; } daughterSizeDistribution { model uniformBinary; }"
            expect=("fMat -2" ">= 0" "vogelPeukertCoeffs") ;;
        breakageWallImpactNegative)
            set_breakage "$gp" "model wallImpact; wallImpactCoeffs { fMat 0.9; xWmMin -0.12; impactEnergy normal; } daughterSizeDistribution { model uniformBinary; }"
            expect=("xWmMin -0.12" ">= 0" "wallImpactCoeffs") ;;
        breakageWallImpactUnknownEnergy)
            set_breakage "$gp" "model wallImpact; wallImpactCoeffs { fMat 0.9; xWmMin 0.12; impactEnergy kinetic; } daughterSizeDistribution { model uniformBinary; }"
            expect=("kinetic" "impactEnergy" "total" "normal" "angleFunction") ;;
        breakageUnknownModel)
            set_breakage "$gp" "model fancy; daughterSizeDistribution { model uniformBinary; }"
            expect=("Unknown breakage model type fancy" "constant" "powerLaw" "vogelPeukert" "none") ;;
        breakageUnknownDaughters)
            set_breakage "$gp" "model constant; constantCoeffs { S { coarse 0.1; } } daughterSizeDistribution { model fancy; }"
            expect=("Unknown daughterSizeDistribution model type fancy" "uniformBinary" "austin" "table") ;;
        breakageMissingCoefficient)
            set_breakage "$gp" "model powerLaw; powerLawCoeffs { dRef 1e-3; a 3; } daughterSizeDistribution { model uniformBinary; }"
            expect=("k" "powerLawCoeffs") ;;
        laplacianLimited)
            foamDictionary -entry "laplacianSchemes/laplacian(D,n)" -set "Gauss linear limited corrected 0.33" "$dir/system/fvSchemes" > /dev/null
            expect=("laplacian(D,n)" "limited" "Valid snGrad schemes: corrected, uncorrected") ;;
        gradNotLinear)
            foamDictionary -entry "gradSchemes/default" -set "fourth" "$dir/system/fvSchemes" > /dev/null
            expect=("gradSchemes" "grad(n.fine)" "fourth" "linear in the field" "pointCellsLeastSquares") ;;
        gradMismatch)
            foamDictionary -entry "gradSchemes/grad(n.coarse)" -set "leastSquares" "$dir/system/fvSchemes" > /dev/null
            expect=("gradSchemes" "grad(n.coarse)" "leastSquares" "Gauss linear" "the same gradient") ;;
        *) echo "unknown kind $kind"; return 1 ;;
    esac

    if segregationDegradationFoam -case "$dir" > "$dir/log.solver" 2>&1
    then
        echo "solver accepted bad input ($kind)"; return 1
    fi
    cat "$dir/log.solver" | sed -n '/FOAM FATAL/,/FOAM exiting\|FOAM aborting/p' | head -20
    local e
    for e in "${expect[@]}"
    do
        if ! grep -qF -- "$e" "$dir/log.solver"
        then
            echo "error message lacks '$e'"; return 1
        fi
    done
    if grep -q "Segmentation\|printStack" "$dir/log.solver"
    then
        echo "crashed instead of a clear error"; return 1
    fi
    local written
    written=$(find "$dir" -mindepth 1 -maxdepth 1 -type d -regextype posix-extended -regex '.*/[0-9.eE+-]+' ! -name 0 | head -1)
    [ -z "$written" ] || { echo "a time directory was written: $written"; return 1; }
    echo "clear fatal error for $kind, nothing written"
}

# A restart from fields the solver wrote: round-off negatives (-1e-22 ..
# -1e-11 in cells the solids have left; silo3D wrote n.coarse -1.06e-22)
# are accepted, anything below -1e-10 is still refused naming the field
test_round_off_initial_value()
{
    local dir="$workRoot/roundOffInitial"
    prepare_small_case "$dir" || return 1
    foamDictionary -entry internalField -set "uniform -1e-20" "$dir/0/n.fine" > /dev/null
    segregationDegradationFoam -case "$dir" > "$dir/log.solver" 2>&1 \
        || { sed -n '/FOAM FATAL/,/FOAM exiting/p' "$dir/log.solver" | head; echo "a -1e-20 initial value was refused"; return 1; }
    local written
    written=$(find "$dir" -mindepth 1 -maxdepth 1 -type d -regextype posix-extended -regex '.*/[0-9.eE+-]+' ! -name 0 | head -1)
    [ -n "$written" ] || { echo "no result written"; return 1; }
    echo "n.fine -1e-20 accepted, ran to ${written##*/}"
    rm -rf "$dir"
    prepare_small_case "$dir" || return 1
    foamDictionary -entry internalField -set "uniform -1e-9" "$dir/0/n.fine" > /dev/null
    if segregationDegradationFoam -case "$dir" > "$dir/log.solver" 2>&1
    then
        echo "a -1e-9 initial value was accepted"; return 1
    fi
    grep -qF "round-off down to -1e-10 accepted" "$dir/log.solver" || { echo "message lacks the round-off bound"; return 1; }
    grep -q 'n.fine' "$dir/log.solver" || return 1
    echo "n.fine -1e-9 refused: $(grep -m1 -o 'value -1e-09.*' "$dir/log.solver")"
}
