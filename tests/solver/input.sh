# shellcheck shell=bash
# Bad input to segregationDegradationFoam and calibrateGranularMixture
# (sourced by tests/run; tests solver/input/*): each kind of broken case
# stops with the program's own fatal error naming the entry and writes no
# time directory; the warning on Gauss linear gradients on a distorted mesh.

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

# write_nonfinite_field FILE: FILE (an ascii volScalarField on the small
# case's 10 cells) rewritten in binary with a NaN in its third cell: the
# only way a non-finite value gets past OpenFOAM's parser (`uniform nan` is
# a parse error), as from a field another program wrote
write_nonfinite_field()
{
    python3 - "$1" <<'PY'
import re, struct, sys
path = sys.argv[1]
text = open(path).read()
values = [0.3] * 10
values[2] = float("nan")
assert "format      ascii;" in text
text = text.replace("format      ascii;", 'format      binary;\n    arch        "LSB;label=32;scalar=64";')
head, tail = re.split(r"^internalField .*$", text, maxsplit=1, flags=re.M)
data = (head.encode() + b"internalField   nonuniform List<scalar> \n10\n("
        + struct.pack("<10d", *values) + b");" + tail.encode())
open(path, "wb").write(data)
PY
}

# break_case KIND DIR: break the small case DIR (or replace it by another
# case) one way; sets expect, the program's own message for it (each
# string must be in the fatal error), and app, the program that must
# refuse it. One arm per kind: a new bad input is one arm here and one
# add_test line in tests/run
break_case()
{
    local kind="$1" dir="$2"
    local gp="$dir/constant/granularProperties" cd="$dir/system/controlDict"
    app=segregationDegradationFoam
    expect=()
    case "$kind" in
        unknownModel)
            foamDictionary -entry diffusivity/model -set fancy "$gp" > /dev/null
            expect=("Unknown diffusivity model type fancy" "powerLaw" "kineticTheory" "constant" "none") ;;
        calibratedWithoutLibrary)
            foamDictionary -entry diffusivity/model -set calibrated "$gp" > /dev/null
            expect=("Unknown diffusivity model type calibrated" "libcalibratedModels.so" "system/controlDict") ;;
        missingField)
            rm "$dir/0/n.coarse"
            expect=("Missing field n.coarse of species 'coarse'" "constant/granularProperties" "in the start time directory 0") ;;
        badDiameter)
            foamDictionary -entry species/coarse/d -set -2e-3 "$gp" > /dev/null
            expect=("Non-positive diameter" "coarse") ;;
        negativeInitial)
            foamDictionary -entry internalField -set "uniform -0.1" "$dir/0/n.fine" > /dev/null
            expect=("n.fine" "-0.1" ">= 0") ;;
        nanInitial)
            write_nonfinite_field "$dir/0/n.fine"
            expect=('n.fine": value nan at cell 2' "A solids volume fraction must be finite and >= 0") ;;
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
        # Time-step controls of system/controlDict
        maxCoZero)
            foamDictionary -entry maxCo -set 0 "$cd" > /dev/null
            expect=("'maxCo 0' in $cd must be > 0" "valid: any positive number") ;;
        maxSegregationCoZero)
            foamDictionary -entry maxSegregationCo -set 0 "$cd" > /dev/null
            expect=("'maxSegregationCo 0' in $cd must be > 0" "valid: any positive number") ;;
        maxDeltaTNegative)
            foamDictionary -entry maxDeltaT -set -1 "$cd" > /dev/null
            expect=("'maxDeltaT -1' in $cd must be > 0" "valid: any positive number") ;;
        # Coefficients of the segregation and temperature models
        constantDNegative)
            foamDictionary -entry diffusivity/constantCoeffs/D -set -0.1 "$gp" > /dev/null
            expect=("Diffusivity 'D -0.1' must be >= 0 [m2/s]" "constantCoeffs") ;;
        grayThorntonSrNegative)
            foamDictionary -entry percolation/grayThorntonCoeffs/Sr -set -1 "$gp" > /dev/null
            expect=("Percolation velocity 'Sr -1' must be >= 0 [m/s]" "grayThorntonCoeffs") ;;
        powerLawANegative)
            foamDictionary -entry diffusivity -set "{ model powerLaw; powerLawCoeffs { A -6; m 1; } }" "$gp" > /dev/null
            expect=("powerLaw coefficients: A -6 and m 1 must be >= 0" "powerLawCoeffs") ;;
        powerLawMNegative)
            foamDictionary -entry diffusivity -set "{ model powerLaw; powerLawCoeffs { A 6; m -1; } }" "$gp" > /dev/null
            expect=("powerLaw coefficients: A 6 and m -1 must be >= 0" "powerLawCoeffs") ;;
        kineticTheoryPhiMax)
            foamDictionary -entry diffusivity -set "{ model kineticTheory; kineticTheoryCoeffs { e 0.9; phiMax 1.2; } }" "$gp" > /dev/null
            expect=("'phiMax 1.2' must lie in (0, 1)" "kineticTheoryCoeffs") ;;
        savageJeffreyR)
            foamDictionary -entry granularTemperature -set "{ model savageJeffrey; savageJeffreyCoeffs { R 0; } }" "$gp" > /dev/null
            expect=("Savage-Jeffrey parameter 'R 0' must be > 0" "savageJeffreyCoeffs") ;;
        velocityGradientEta)
            foamDictionary -entry kineticSieving -set "{ model velocityGradient; velocityGradientCoeffs { eta -1e-4; } }" "$gp" > /dev/null
            expect=("kinetic sieving: 'eta -0.0001' must be >= 0 [m2/s]" "velocityGradientCoeffs") ;;
        velocityGradientUmin)
            foamDictionary -entry kineticSieving -set "{ model velocityGradient; velocityGradientCoeffs { eta 1e-4; Umin 0; } }" "$gp" > /dev/null
            expect=("'Umin 0' > 0 [m/s]" "velocityGradientCoeffs") ;;
        shearRateDiffusivityC)
            foamDictionary -entry diffusivity -set "{ model shearRate; shearRateCoeffs { C -0.042; } }" "$gp" > /dev/null
            expect=("Diffusivity prefactor 'C -0.042' must be >= 0" "shearRateCoeffs") ;;
        shearRatePercolationC)
            foamDictionary -entry percolation -set "{ model shearRate; shearRateCoeffs { C_s -0.26; } }" "$gp" > /dev/null
            expect=("Segregation prefactor 'C_s -0.26' must be >= 0" "shearRateCoeffs") ;;
        # The mixture and its fields
        initialSumAboveOne)
            foamDictionary -entry internalField -set "uniform 0.8" "$dir/0/n.coarse" > /dev/null
            expect=("Total solids fraction sum of n.* = 1.1 > 1" "check the initial fields") ;;
        phiMinZero)
            foamDictionary -entry phiMin -set 0 "$gp" > /dev/null
            expect=("phiMin 0 must lie in (0, 1)" "granularProperties") ;;
        phiMinOne)
            foamDictionary -entry phiMin -set 1 "$gp" > /dev/null
            expect=("phiMin 1 must lie in (0, 1)" "granularProperties") ;;
        writeFieldsUnknown)
            foamDictionary -entry writeFields -set "(T velocity)" "$gp" > /dev/null
            expect=("Unknown entry 'velocity' in writeFields; valid:" "gammaDot" "brokenVolume") ;;
        fieldDimensions)
            foamDictionary -entry dimensions -set "[0 1 0 0 0 0 0]" "$dir/0/n.fine" > /dev/null
            expect=('n.fine" has dimensions [0 1 0 0 0 0 0]; a volume fraction is dimensionless') ;;
        noSpecies)
            foamDictionary -entry species -set "{}" "$gp" > /dev/null
            expect=("The dictionary 'species' in" "declares no species: at least one is needed") ;;
        # Breakage: the source's entries
        breakageAustinPhi)
            set_breakage "$gp" "model constant; constantCoeffs { S { coarse 0.1; } } daughterSizeDistribution { model austin; austinCoeffs { phi 1.5; gamma 1; beta 2; } }"
            expect=("'phi 1.5' in" "austinCoeffs\" must lie in [0, 1]") ;;
        breakageAustinGamma)
            set_breakage "$gp" "model constant; constantCoeffs { S { coarse 0.1; } } daughterSizeDistribution { model austin; austinCoeffs { phi 0.5; gamma 0; beta 2; } }"
            expect=("'gamma 0' and 'beta 2' in" "must be > 0 (B(x, y) must vanish") ;;
        breakageUnknownFines)
            set_breakage "$gp" "model constant; constantCoeffs { S { coarse 0.1; } } fines sand; daughterSizeDistribution { model uniformBinary; }"
            expect=("Unknown 'fines sand' in" "valid: finestClass" "dust") ;;
        breakageMissingDaughters)
            set_breakage "$gp" "model constant; constantCoeffs { S { coarse 0.1; } }"
            expect=("Missing dictionary 'daughterSizeDistribution' in" "e.g. daughterSizeDistribution { model uniformBinary; }") ;;
        breakageNoneUnknownFines)
            set_breakage "$gp" "model none; fines sand;"
            expect=("Unknown 'fines sand' in" "valid: finestClass") ;;
        breakageNoneBadDaughters)
            set_breakage "$gp" "model none; daughterSizeDistribution { model table; tableCoeffs { coarse { fine 0.9; } } }"
            expect=("coarse" "sum to 0.9" "must sum to 1") ;;
        # The calibrated law of granularCoefficients
        calibratedUnknownLaw|calibratedNonFiniteParameter)
            echo 'libs ("libcalibratedModels.so");' >> "$dir/system/caseParameters"
            foamDictionary -entry diffusivity -set "{ model calibrated; calibratedCoeffs { outsideEnvelope extrapolate; } }" "$gp" > /dev/null
            cp "$projectDir/tutorials/silo2D/constant/granularCoefficients.shipped" "$dir/constant/granularCoefficients"
            if [ "$kind" = calibratedUnknownLaw ]
            then
                foamDictionary -entry D/law -set fancy "$dir/constant/granularCoefficients" > /dev/null
                expect=("Unknown law 'fancy' for D; valid:" "powerLaw")
            else
                # nan: OpenFOAM's parser takes it as a word (a number that
                # overflows, 1e999, it refuses itself)
                foamDictionary -entry D/A -set nan "$dir/constant/granularCoefficients" > /dev/null
                expect=("Parameter 'A' of D is not a finite number: " "nan")
            fi ;;
        # The kinematic bulk flow (silo2D)
        kinematicB|beverlooC|beverlooK|hopperHalfAngle|dischargeRateUnknown)
            silo2D_case "$dir" || return 1
            gp="$dir/constant/granularProperties"
            local bev=bulkFlow/kinematicCoeffs/beverlooCoeffs
            case "$kind" in
                kinematicB) foamDictionary -entry bulkFlow/kinematicCoeffs/B -set 0 "$gp" > /dev/null
                    expect=("Kinematic constant 'B 0' must be > 0 [m]") ;;
                beverlooC) foamDictionary -entry $bev/C -set 0 "$gp" > /dev/null
                    expect=("Beverloo: 'C 0' must be > 0 and 'k 1.5' >= 0") ;;
                beverlooK) foamDictionary -entry $bev/k -set -1 "$gp" > /dev/null
                    expect=("Beverloo: 'C 0.58' must be > 0 and 'k -1' >= 0") ;;
                hopperHalfAngle) foamDictionary -entry $bev/hopperHalfAngle -set 90 "$gp" > /dev/null
                    expect=("'hopperHalfAngle 90' must lie in (0, 90) [degrees from the vertical]") ;;
                dischargeRateUnknown) foamDictionary -entry bulkFlow/kinematicCoeffs/dischargeRate -set fancy "$gp" > /dev/null
                    foamDictionary -entry bulkFlow/kinematicCoeffs/beverlooCoeffs -remove "$gp" > /dev/null
                    expect=("Unknown dischargeRate 'fancy'; valid: (beverloo given)") ;;
            esac ;;
        # calibrateGranularMixture's calibrationDict and species
        calibrationEqualDiameters|calibrationDuplicateEnvelope)
            copy_calibration_case "$dir"
            app=calibrateGranularMixture
            if [ "$kind" = calibrationEqualDiameters ]
            then
                foamDictionary -entry species/coarse/d -set 1e-3 "$dir/constant/granularProperties" > /dev/null
                expect=("The two species fine and coarse have the same diameter 'd 0.001'" "no fine and coarse")
            else
                foamDictionary -entry phi -set "(0.2 0.35 0.2)" "$dir/system/calibrationDict" > /dev/null
                expect=("Envelope entry 'phi': value 0.2 appears twice")
            fi ;;
        *) echo "unknown kind $kind"; return 1 ;;
    esac
}


# test_bad_input KIND: break the case one way (break_case), expect the
# program's own fatal error for it and no time directory written
test_bad_input()
{
    local kind="$1" dir="$workRoot/badInput-$1" expect=() app
    prepare_small_case "$dir" || return 1
    break_case "$kind" "$dir" || return 1
    check_refusal "$dir" "$app" "${expect[@]}" || return 1
    echo "clear fatal error for $kind, nothing written"
}

# The checks of missingField and nanInitial hold the solver to its own
# message: another error that names the same field (OpenFOAM's parser on
# a malformed n.coarse, on `uniform nan` in n.fine) must fail them
test_bad_input_checks_discriminate()
{
    local kind dir expect=() app
    for kind in missingField nanInitial
    do
        dir="$workRoot/badInputDiscriminate-$kind"
        prepare_small_case "$dir" || return 1
        break_case "$kind" "$dir" || return 1
        case "$kind" in
            missingField)
                cp "$dir/0.orig/n.coarse" "$dir/0/"
                sed -i 's/^internalField .*/internalField   uniform ;/' "$dir/0/n.coarse" ;;
            nanInitial)
                cp "$dir/0.orig/n.fine" "$dir/0/"
                sed -i 's/^internalField .*/internalField   uniform nan;/' "$dir/0/n.fine" ;;
        esac
        if check_refusal "$dir" "$app" "${expect[@]}" > "$dir/log.check"
        then
            cat "$dir/log.check"
            echo "$kind: the check passed on another error"; return 1
        fi
        grep -q "n\.\(coarse\|fine\)" "$dir/log.$app" || { echo "$kind: the other error does not name the field"; return 1; }
        echo "$kind: check fails on another error naming the field: $(grep -m1 "lacks" "$dir/log.check")"
    done
}

# The warning on Gauss linear species' gradients on a distorted mesh: the
# column (validation/unstructuredMeshes/study's meshes, 40 cells along) is
# warned on its distorted mesh with Gauss linear, and not on the uniform
# mesh nor with pointCellsLeastSquares; the warning is printed once
test_gauss_linear_distorted_warning()
{
    local work="$workRoot/gaussLinearWarning"
    rm -rf "$work"; mkdir -p "$work"
    echo 'gradSchemes { default pointCellsLeastSquares; }' > "$work/pointCellsLeastSquares"
    local setup kind schemes case count
    for setup in distorted:none uniform:none distorted:pointCellsLeastSquares
    do
        kind="${setup%%:*}"; schemes="${setup#*:}"
        case=$(python3 - "$work" "$kind" "$schemes" "$validationDir/unstructuredMeshes/study" <<'PY'
import importlib.machinery, importlib.util, os, sys
work, kind, schemes, path = sys.argv[1:]
loader = importlib.machinery.SourceFileLoader("study", path)
spec = importlib.util.spec_from_loader("study", loader)
study = importlib.util.module_from_spec(spec)
loader.exec_module(study)
case = study.setup(work, "column", kind, 40, None if schemes == "none" else os.path.join(work, schemes))
os.rename(case, case + "-" + schemes)
print(case + "-" + schemes)
PY
        ) || return 1
        # three steps are enough: the warning comes at start-up
        foamDictionary -entry endTime -set 0.003 "$case/system/controlDict" > /dev/null
        foamDictionary -entry adjustTimeStep -set no "$case/system/controlDict" > /dev/null
        segregationDegradationFoam -case "$case" > "$case/log.solver" 2>&1 || { tail -20 "$case/log.solver"; return 1; }
        count=$(grep -c "The species' gradient scheme is Gauss linear" "$case/log.solver")
        echo "$kind, $schemes: $(sed -n 's/^ *Mesh non-orthogonality Max: \([^ ]*\).*/checkMesh non-orthogonality \1/p;s/^ *Max skewness = \([^ ]*\).*/skewness \1/p' "$case/log.checkMesh" | tr '\n' ' ')warnings $count"
        if [ "$kind:$schemes" = distorted:none ]
        then
            [ "$count" -eq 1 ] || { echo "expected the warning once"; return 1; }
            grep -A6 "The species' gradient scheme is Gauss linear" "$case/log.solver"
            local e
            for e in "gradSchemes entry grad(n.fine) and 1 more" "system/fvSchemes" "pointCellsLeastSquares"
            do
                grep -A6 "The species' gradient scheme is Gauss linear" "$case/log.solver" | grep -qF -- "$e" \
                    || { echo "the warning lacks '$e'"; return 1; }
            done
        else
            [ "$count" -eq 0 ] || { echo "warned on $kind, $schemes"; return 1; }
        fi
    done
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
