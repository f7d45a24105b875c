# Solver-level tests of segregationDegradationFoam, sourced by tests/run.
# Each function runs in a subshell with the OpenFOAM environment; it prints
# what it measured and returns non-zero on failure. Work directories live
# under $workRoot (build/tests).

validationDir="$projectDir/tutorials/validation"
fieldStats="$projectDir/tests/solver/fieldStats.py"

# Fresh copy of a case without run outputs
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

test_unit_models()
{
    local dir="$workRoot/unitCase"
    rm -rf "$dir"; cp -r tests/unit/testCase "$dir"
    blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || return 1
    granularModelsTest -case "$dir"
}

# A small prepared column case (validation column, 10 cells) for bad input
prepare_small_case()
{
    local dir="$1"
    copy_case "$validationDir/segregationDiffusionColumn" "$dir"
    echo "N 10; endTime 0.05;" > "$dir/system/caseParameters"
    blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || return 1
    cp -r "$dir/0.orig" "$dir/0"
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

# Closed box (cyclic in x, walls elsewhere) with shear flow, percolation,
# kinetic sieving and diffusion, a partly empty initial state: mass of every
# species conserved to 1e-10 relative, 0 <= n_i <= phi at all times
test_closed_box()
{
    local dir="$workRoot/closedBox"
    rm -rf "$dir"; cp -r tests/solver/closedBox "$dir"
    blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || { cat "$dir/log.blockMesh"; return 1; }
    cp -r "$dir/0.orig" "$dir/0"
    setFields -case "$dir" > "$dir/log.setFields" 2>&1 || { cat "$dir/log.setFields"; return 1; }
    segregationDegradationFoam -case "$dir" > "$dir/log.solver" 2>&1 || { tail -30 "$dir/log.solver"; return 1; }
    python3 - "$dir/log.solver" <<'PY' || return 1
import re, sys
vols = {}
for line in open(sys.argv[1]):
    if line.startswith("Solids:"):
        for name, v in re.findall(r"(n\.\w+) volume (\S+)", line):
            vols.setdefault(name, []).append(float(v))
ok = True
for name, v in vols.items():
    rel = max(abs(x - v[0]) for x in v) / v[0]
    print("%s: initial volume %.12e, max relative change over %d steps %.2e" % (name, v[0], len(v), rel))
    ok &= rel < 1e-10
if not vols or len(next(iter(vols.values()))) < 10:
    print("too few steps parsed"); ok = False
sys.exit(0 if ok else 1)
PY
    python3 "$fieldStats" "$dir" changed --tol 0.05 || return 1
    python3 "$fieldStats" "$dir" bounds --tol 1e-8
}

# silo2D for a few seconds: the top cells go from full to empty, every field
# stays finite and bounded, and the solids that left through the outlet
# balance the loss of solids in the silo
test_silo_empties()
{
    local dir="$workRoot/siloEmpties"
    copy_case "$projectDir/tutorials/silo2D" "$dir"
    foamDictionary -entry writeFields -set "(T gammaDot dMean D nTotal)" "$dir/constant/granularProperties" > /dev/null
    foamDictionary -entry endTime -set 4 "$dir/system/controlDict" > /dev/null
    foamDictionary -entry writeInterval -set 1 "$dir/system/controlDict" > /dev/null
    : > "$dir/system/caseParameters"
    blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || return 1
    cp -r "$dir/0.orig" "$dir/0"
    segregationDegradationFoam -case "$dir" > "$dir/log.solver" 2>&1 || { tail -30 "$dir/log.solver"; return 1; }
    python3 "$fieldStats" "$dir" emptied || return 1
    python3 "$fieldStats" "$dir" bounds --tol 1e-8 || return 1
    python3 - "$dir" <<'PY'
import re, sys
case = sys.argv[1]
total = [float(m.group(1)) for m in re.finditer(r"Solids: total volume (\S+)", open(case + "/log.solver").read())]
# volume of solids leaving: sum over species of cumulative mass / rho (2500)
rows = [l.split() for l in open(case + "/postProcessing/outletComposition/0/outlet.dat") if not l.startswith("#")]
cum = sum(float(x) for x in rows[-1][-2:]) / 2500.0
top = [l.split() for l in open(case + "/postProcessing/outletComposition/0/top.dat") if not l.startswith("#")]
cumTop = sum(float(x) for x in top[-1][-2:]) / 2500.0
initial = total[0] + sum(float(x) for x in rows[0][-2:]) / 2500.0  # first logged step already lost a little
balance = (initial - total[-1]) - (cum + cumTop)
print("solids lost from the silo %.6e m3, left through outlet+top %.6e m3, imbalance %.2e (relative %.2e)"
      % (initial - total[-1], cum + cumTop, balance, abs(balance) / (initial - total[-1])))
sys.exit(0 if abs(balance) / (initial - total[-1]) < 1e-6 else 1)
PY
}

# silo2D decomposed on 2 ranks gives the serial answer to solver tolerance
test_silo_parallel()
{
    local serial="$workRoot/siloSerial" parallel="$workRoot/siloParallel"
    local d
    for d in "$serial" "$parallel"
    do
        copy_case "$projectDir/tutorials/silo2D" "$d"
        foamDictionary -entry endTime -set 1 "$d/system/controlDict" > /dev/null
        foamDictionary -entry writeInterval -set 1 "$d/system/controlDict" > /dev/null
        : > "$d/system/caseParameters"
        blockMesh -case "$d" > "$d/log.blockMesh" 2>&1 || return 1
        cp -r "$d/0.orig" "$d/0"
    done
    segregationDegradationFoam -case "$serial" > "$serial/log.solver" 2>&1 || { tail -20 "$serial/log.solver"; return 1; }
    decomposePar -case "$parallel" > "$parallel/log.decomposePar" 2>&1 || { tail -20 "$parallel/log.decomposePar"; return 1; }
    mpirun -np 2 segregationDegradationFoam -parallel -case "$parallel" > "$parallel/log.solver" 2>&1 || { tail -20 "$parallel/log.solver"; return 1; }
    reconstructPar -latestTime -case "$parallel" > "$parallel/log.reconstructPar" 2>&1 || return 1
    python3 "$fieldStats" "$parallel" compare "$serial" --tol 1e-8
}

test_convergence_study()
{
    tutorials/validation/convergenceStudy --no-docs --work "$workRoot/validation"
}

# Kinematic bulk flow on silo2D: the Beverloo rate by hand, the wedge's share
# of it through the outlet, a divergence-free flux and the outlet record
test_kinematic_discharge()
{
    local dir="$workRoot/kinematicDischarge"
    copy_case "$projectDir/tutorials/silo2D" "$dir"
    foamDictionary -entry endTime -set 0.01 "$dir/system/controlDict" > /dev/null
    : > "$dir/system/caseParameters"
    blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || return 1
    cp -r "$dir/0.orig" "$dir/0"
    segregationDegradationFoam -case "$dir" > "$dir/log.solver" 2>&1 || { tail -30 "$dir/log.solver"; return 1; }
    python3 - "$dir" <<'PY'
import math, re, sys
case = sys.argv[1]
log = open(case + "/log.solver").read()
Q = float(re.search(r"Beverloo discharge rate Q = (\S+)", log).group(1))
Qmesh = float(re.search(r"outlet flux (\S+) m3/s on the mesh", log).group(1))
div = float(re.search(r"max \|div\(phi\)\| V / sum\|phi\| = (\S+)", log).group(1))
# Beverloo by hand: C sqrt(g) (D0 - k d)^2.5 (tan 30)^-0.35, d = 0.8*1 mm + 0.2*2 mm
Qhand = 0.58 * math.sqrt(9.81) * (0.04 - 1.5 * 1.2e-3) ** 2.5 * math.tan(math.radians(30)) ** -0.35
share = math.sin(math.radians(5)) / (2 * math.pi)   # 5 deg wedge of the outlet disc
rows = [l.split() for l in open(case + "/postProcessing/outletComposition/0/outlet.dat") if not l.startswith("#")]
Qout, mass, fracFine = float(rows[0][1]), float(rows[0][2]), float(rows[0][5])
print("Beverloo Q %.6e (hand %.6e); outlet flux %.6e = %.6f of Q (wedge share %.6f);"
      " max div %.1e; first outlet Q %.6e, mass flow %.6e (expected %.6e), fine fraction %.6f"
      % (Q, Qhand, Qmesh, Qmesh / Q, share, div, Qout, mass, Qmesh * 0.6 * 2500, fracFine))
ok = abs(Q / Qhand - 1) < 1e-8 and abs(Qmesh / Q / share - 1) < 1e-3 and div < 1e-8
ok = ok and abs(Qout / Qmesh - 1) < 1e-9 and abs(mass / (Qmesh * 0.6 * 2500) - 1) < 1e-6 and abs(fracFine - 0.8) < 1e-4
sys.exit(0 if ok else 1)
PY
}

# Gray-Thornton chute with second-order TVD schemes for the bulk advection
# (shared limiter) and the segregation flux: bounds to 1e-8, n.fine +
# n.coarse = 1, meeting point within 2 % (the check's assertions)
test_chute_tvd()
{
    local dir="$workRoot/chuteTVD"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/grayThorntonChute" "$dir/"
    "$dir/grayThorntonChute/Allrun" -n 40 -div "Gauss vanLeer01" -reconstruct vanLeer -tol 0.02
}

# periodicDEM front door: a short driven cell in a case directory writes an
# HDF5 file that h5dump reads, with T at its target and D of both species
test_periodic_dem()
{
    local dir="$workRoot/periodicDEM"
    rm -rf "$dir"; cp -r "$projectDir/tutorials/periodicDEM/binaryDriven" "$dir"
    rm -rf "$dir/postProcessing"
    local d="$dir/system/periodicDEMDict"
    foamDictionary -entry particles -set 200 "$d" > /dev/null
    foamDictionary -entry equilibrationTime -set 0.002 "$d" > /dev/null
    foamDictionary -entry samplingTime -set 0.005 "$d" > /dev/null
    periodicDEM -case "$dir" > "$dir/log.periodicDEM" 2>&1 || { tail -20 "$dir/log.periodicDEM"; return 1; }
    local h5="$dir/postProcessing/periodicDEM/binaryDriven.h5"
    h5dump -H "$h5" > "$dir/h5dump.txt" || { echo "h5dump cannot read $h5"; return 1; }
    grep -q "GROUP" "$dir/h5dump.txt" || { echo "no groups in $h5"; return 1; }
    grep -E "^  T = |D_GK" "$dir/log.periodicDEM"
    python3 - "$dir/log.periodicDEM" <<'PY'
import re, sys
log = open(sys.argv[1]).read()
T = float(re.search(r"^  T = (\S+)", log, re.M).group(1))
D = [float(x) for x in re.findall(r"D_GK = (\S+)", log)]
print("T = %.6g (target 0.01), D_GK = %s" % (T, D))
ok = abs(T / 0.01 - 1) < 0.02 and len(D) == 2 and all(d > 0 for d in D)
sys.exit(0 if ok else 1)
PY
}

# periodicDEM bad input: unknown entry, restitution outside (0, 1], unknown
# mode: a
# FatalIOError naming the entry, no result file
test_periodic_dem_bad_input()
{
    local dir="$workRoot/periodicDEMBad" kind
    for kind in unknownEntry restitution mode
    do
        rm -rf "$dir"; cp -r "$projectDir/tutorials/periodicDEM/binaryDriven" "$dir"
        rm -rf "$dir/postProcessing"
        local d="$dir/system/periodicDEMDict" expect
        case "$kind" in
            unknownEntry) foamDictionary -entry sampleEvry -set 10 "$d" > /dev/null; expect="sampleEvry" ;;
            restitution) foamDictionary -entry contact/restitution -set 1.5 "$d" > /dev/null; expect="restitution" ;;
            mode) foamDictionary -entry mode -set shearing "$d" > /dev/null; expect="mode" ;;
        esac
        if periodicDEM -case "$dir" > "$dir/log" 2>&1
        then
            echo "$kind accepted"; return 1
        fi
        grep -A3 "FOAM FATAL" "$dir/log" | head -6
        grep -q "$expect" "$dir/log" || { echo "message lacks '$expect'"; return 1; }
        [ ! -e "$dir/postProcessing/periodicDEM/binaryDriven.h5" ] || { echo "result file written"; return 1; }
    done
}

#------------------------------------------------------------------------------
# calibrateGranularMixture (tutorials/calibration/binary21: 8 small DEM
# conditions, about 10 s)
calibrationCase="$projectDir/tutorials/calibration/binary21"

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

    calibrateGranularMixture -case "$dir" -noFit > "$dir/log.1" 2>&1 &
    local pid=$! i
    for i in $(seq 1 600)
    do
        grep -q "done in" "$dir/log.1" 2>/dev/null && break
        sleep 0.05
    done
    kill -9 "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    local stored
    stored=$(h5ls "$dir/constant/calibration.h5/conditions" 2>/dev/null | wc -l)
    echo "killed after $stored stored conditions"
    [ "$stored" -ge 1 ] && [ "$stored" -lt 8 ] || { echo "kill did not land mid-run"; return 1; }

    calibrateGranularMixture -case "$dir" -noFit > "$dir/log.2" 2>&1 || { tail -20 "$dir/log.2"; return 1; }
    local skipped ran
    skipped=$(grep -c "^skipping .*(already in calibration.h5)" "$dir/log.2")
    ran=$(grep -c "done in" "$dir/log.2")
    echo "rerun: $skipped skipped, $ran run"
    [ "$skipped" -eq "$stored" ] && [ "$ran" -eq $((8 - stored)) ] || { echo "rerun repeated or missed conditions"; return 1; }

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
    local kinds="unknownCoefficient unknownLaw emptyPhi invertedT jammedPhi negativeT xOutside textStore foreignHdf5"
    [ -f "$workRoot/calibration/constant/calibration.h5" ] && kinds="$kinds truncatedStore settingsChanged"
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

# Serial reference for the parallel tests: the tutorial's conditions run one
# at a time (concurrentConditions 1), stored without a fit
calibration_serial_reference()
{
    copy_calibration_case "$1"
    foamDictionary -entry concurrentConditions -set 1 "$1/system/calibrationDict" > /dev/null
    calibrateGranularMixture -case "$1" -noFit > "$1/log" 2>&1 || { tail -20 "$1/log"; return 1; }
    grep -q "8 conditions to run, 1 at once" "$1/log" || { echo "reference did not run 1 at once"; return 1; }
    dump_conditions "$1/constant/calibration.h5" > "$1/conditions.txt"
    [ -s "$1/conditions.txt" ] || { echo "empty dump of the reference"; return 1; }
}

# same_conditions REF DIR: the condition groups of DIR (timing excluded)
# are identical to those of the reference
same_conditions()
{
    dump_conditions "$2/constant/calibration.h5" > "$2/conditions.txt"
    diff -q "$1/conditions.txt" "$2/conditions.txt" > /dev/null \
        || { echo "conditions differ from the serial reference:"; diff "$1/conditions.txt" "$2/conditions.txt" | head -20; return 1; }
    echo "identical to the serial reference ($(wc -l < "$2/conditions.txt") dump lines, timing groups excluded)"
}

# Two conditions at once (threads) give bitwise the conditions of a one at
# a time run
test_calibration_concurrent()
{
    local ref="$workRoot/calibrationSerial" dir="$workRoot/calibrationConcurrent"
    calibration_serial_reference "$ref" || return 1
    copy_calibration_case "$dir"
    foamDictionary -entry concurrentConditions -set 2 "$dir/system/calibrationDict" > /dev/null
    calibrateGranularMixture -case "$dir" -noFit > "$dir/log" 2>&1 || { tail -20 "$dir/log"; return 1; }
    grep -q "8 conditions to run, 2 at once" "$dir/log" || { echo "did not run 2 at once"; grep "at once" "$dir/log"; return 1; }
    [ "$(grep -c "done in" "$dir/log")" -eq 8 ] || { echo "not 8 progress lines"; return 1; }
    grep -E "^DEM:" "$ref/log" "$dir/log"
    same_conditions "$ref" "$dir" || return 1

    # killed (kill -9) after its first finished condition, with the other
    # worker still running: the rerun skips what was stored, runs the rest
    local killed="$workRoot/calibrationConcurrentKill"
    copy_calibration_case "$killed"
    foamDictionary -entry concurrentConditions -set 2 "$killed/system/calibrationDict" > /dev/null
    calibrateGranularMixture -case "$killed" -noFit > "$killed/log.1" 2>&1 &
    local pid=$! i
    for i in $(seq 1 600)
    do
        grep -q "done in" "$killed/log.1" 2>/dev/null && break
        sleep 0.05
    done
    kill -9 "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    local stored
    stored=$(h5ls "$killed/constant/calibration.h5/conditions" 2>/dev/null | wc -l)
    [ "$stored" -ge 1 ] && [ "$stored" -lt 8 ] || { echo "kill did not land mid-run ($stored stored)"; return 1; }
    calibrateGranularMixture -case "$killed" -noFit > "$killed/log.2" 2>&1 || { tail -20 "$killed/log.2"; return 1; }
    local skipped ran
    skipped=$(grep -c "^skipping .*(already in calibration.h5)" "$killed/log.2")
    ran=$(grep -c "done in" "$killed/log.2")
    echo "2 workers killed after $stored stored conditions; rerun: $skipped skipped, $ran run"
    [ "$skipped" -eq "$stored" ] && [ "$ran" -eq $((8 - stored)) ] || { echo "rerun repeated or missed conditions"; return 1; }
    same_conditions "$ref" "$killed"
}

# -parallel on 2 MPI ranks (no decomposition): both ranks run conditions,
# the master merges the processor stores, the result equals the serial run
test_calibration_parallel()
{
    local ref="$workRoot/calibrationSerial" dir="$workRoot/calibrationParallel"
    [ -s "$ref/conditions.txt" ] || calibration_serial_reference "$ref" || return 1
    copy_calibration_case "$dir"
    mpirun --allow-run-as-root --oversubscribe -np 2 calibrateGranularMixture -parallel -case "$dir" > "$dir/log" 2>&1 \
        || { tail -20 "$dir/log"; return 1; }
    local r0 r1
    r0=$(grep -c "^\[0\] condition .* done in" "$dir/log")
    r1=$(grep -c "^\[1\] condition .* done in" "$dir/log")
    echo "rank 0 ran $r0, rank 1 ran $r1 conditions"
    [ "$r0" -eq 4 ] && [ "$r1" -eq 4 ] || { echo "conditions not spread 4 + 4 over the ranks"; return 1; }
    grep -q "Merged 8 conditions of 2 processor stores" "$dir/log" || { echo "no merge of 8 conditions"; return 1; }
    ls "$dir/constant" | grep -q "processor" && { echo "processor stores left behind"; return 1; }
    [ ! -e "$dir/processor0" ] || { echo "processor0 directory created"; return 1; }
    local law
    law=$(foamDictionary -entry D/law -value "$dir/constant/granularCoefficients") || { echo "master wrote no granularCoefficients"; return 1; }
    echo "D/law = $law (fitted by the master)"
    same_conditions "$ref" "$dir"
}

# A -parallel run killed (kill -9, every rank) after its first finished
# condition loses nothing: the next (serial) run merges the processor
# stores left behind, skips what they hold, runs the rest, and ends with
# the serial reference's conditions
test_calibration_parallel_kill()
{
    local ref="$workRoot/calibrationSerial" dir="$workRoot/calibrationParallelKill"
    [ -s "$ref/conditions.txt" ] || calibration_serial_reference "$ref" || return 1
    copy_calibration_case "$dir"
    mpirun --allow-run-as-root --oversubscribe -np 2 calibrateGranularMixture -parallel -case "$dir" -noFit > "$dir/log.1" 2>&1 &
    local pid=$! i
    for i in $(seq 1 1200)
    do
        grep -q "done in" "$dir/log.1" 2>/dev/null && break
        kill -0 "$pid" 2>/dev/null || { tail -20 "$dir/log.1"; echo "the parallel run ended before it was killed"; return 1; }
        sleep 0.05
    done
    # the ranks are mpirun's children in their own process groups: kill
    # them by id, then mpirun, and wait until none is left
    local ranks
    ranks=$(ps -o pid= --ppid "$pid")
    kill -9 $ranks "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    for i in $(seq 1 100)
    do
        ps -o pid= -p "$(echo $ranks | tr ' ' ',')" > /dev/null 2>&1 || break
        sleep 0.05
    done
    local left stored=0 f n
    left=$(ls "$dir/constant" | grep -c "^calibration.processor[0-9]*.h5$")
    for f in "$dir"/constant/calibration.processor*.h5
    do
        [ -f "$f" ] || continue
        n=$(h5ls "$f/conditions" 2>/dev/null | wc -l)
        stored=$((stored + n))
    done
    echo "killed with $stored conditions in $left processor stores"
    [ "$stored" -ge 1 ] && [ "$stored" -lt 8 ] || { echo "kill did not land mid-run"; return 1; }
    [ ! -e "$dir/constant/calibration.h5" ] || { echo "calibration.h5 written before the end of the run"; return 1; }

    calibrateGranularMixture -case "$dir" -noFit > "$dir/log.2" 2>&1 || { tail -20 "$dir/log.2"; return 1; }
    grep -q "Merged $stored conditions of $left processor stores" "$dir/log.2" || { echo "leftover stores not merged"; grep Merged "$dir/log.2"; return 1; }
    local skipped ran
    skipped=$(grep -c "^skipping .*(already in calibration.h5)" "$dir/log.2")
    ran=$(grep -c "done in" "$dir/log.2")
    echo "rerun: $skipped skipped, $ran run"
    [ "$skipped" -eq "$stored" ] && [ "$ran" -eq $((8 - stored)) ] || { echo "rerun repeated or missed conditions"; return 1; }
    ls "$dir/constant" | grep -q "processor" && { echo "processor stores left behind"; return 1; }
    same_conditions "$ref" "$dir"
}

# -fromCase on a hand-made case (tests/solver/calibrationFromCase, 5 cells,
# no mesh): the envelope derived from the fields equals the hand values
# (cells below phiMin ignored, phi clipped to 0.6, T log-spaced), a named
# time with uniform fields gives a one-point envelope and runs it, the
# coefficients follow the mechanisms switched on, nothing to calibrate
# stops cleanly, a missing T is a FatalError naming T and writeFields
test_calibration_from_case()
{
    local dir="$workRoot/calibrationFromCase" log
    fresh_from_case() { rm -rf "$dir"; cp -r "$projectDir/tests/solver/calibrationFromCase" "$dir"; }
    expect_lines() # LOG LINE...: every LINE appears verbatim in LOG
    {
        local f="$1" l; shift
        for l in "$@"
        do
            grep -qF -- "$l" "$f" || { echo "missing in $f: '$l'"; grep -- "-fromCase\|FATAL" -A1 "$f" | head -20; return 1; }
        done
    }

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

    # T missing from the case but given in calibrationDict: that list is used
    fresh_from_case
    rm "$dir/2/T"
    log="$dir/log.dictT"
    calibrateGranularMixture -case "$dir" -fromCase -dryRun > "$log" 2>&1 || { tail -20 "$log"; return 1; }
    expect_lines "$log" "the T list of system/calibrationDict is used: (0.005 0.02)" "18 of 18 conditions would run" || return 1
    grep -q "entry 'T' of .* is overridden" "$log" && { echo "T reported overridden although used"; return 1; }
    echo "T from calibrationDict when the field is missing: ok"
}

# silo2D with the shipped DEM calibration (Allrun -calibrated -quick, short):
# the calibrated law is used, every field finite and bounded
test_silo_calibrated()
{
    local dir="$workRoot/siloCalibrated"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$projectDir/tutorials/silo2D/"* "$dir/"
    "$dir/Allrun" -calibrated -quick -endTime 2 -writeInterval 1 > "$dir/log.Allrun" 2>&1 \
        || { tail -20 "$dir/log.Allrun"; return 1; }
    grep -E "Selecting diffusivity model calibrated" "$dir/log.segregationDegradationFoam" || { echo "calibrated model not used"; return 1; }
    grep -E "calibrated D: powerLaw" "$dir/log.segregationDegradationFoam" || return 1
    python3 "$fieldStats" "$dir" bounds --tol 1e-8
}

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
    granularModelsTest -case "$dir" --gtest_filter='*RunDEM*' \
        > "$dir/log.granularModelsTest" 2>&1 \
        || { tail -30 "$dir/log.granularModelsTest"; return 1; }
    grep "runDEM" "$dir/log.granularModelsTest"
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
    printf 'endTime 1;\nwriteInterval 1;\n' > "$dir/system/caseParameters"
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
    python3 "$fieldStats" "$dir" bounds --tol 1e-8 || return 1

    rm -rf "$dir/0" "$dir/1" "$dir/postProcessing"
    cp -r "$dir/0.orig" "$dir/0"
    segregationDegradationFoam -case "$dir" > "$dir/log.solverRerun" 2>&1 \
        || { tail -30 "$dir/log.solverRerun"; return 1; }
    ! grep -q "runDEM: phi" "$dir/log.solverRerun" \
        || { echo "the rerun ran DEM conditions again"; return 1; }
}
