# shellcheck shell=bash
# Breakage calibrated from DEM (sourced by tests/run; tests
# calibration/breakage/*): calibrateGranularMixture fits the collision
# frequency omega.<species> and the mean impact energy Wmean.<species> of
# both species of the tutorial's mixture (8 small DEM conditions), -fromCase
# asks for them only when the case's breakage model is calibrated, and the
# solver runs a step with the calibrated breakage model on those laws.

# Reads constant/granularCoefficients ($1), n.<species> of the initial time
# directory $2 (the state S was evaluated on), T and S.<species> of the
# time directory $3 after the first step, and checks S.<species> in every
# cell holding material and agitated (T > 0) against the laws written out
# in Python (fMat 2, xWmMin 2e-8: Wmin of the order of the cells' Wmean):
#   omega = C sqrt(T/3)/d phi g0^b (1 + alpha x), Wmean = K (T/3) phi^c,
#   S = fMat d omega Wmean exp(-(xWmMin/d)/Wmean)
check_breakage_rates()
{
    python3 - "$1" "$2" "$3" <<'PY'
import math, re, sys
coeffs, startDir, timeDir = sys.argv[1], sys.argv[2], sys.argv[3]
text = open(coeffs).read()
def value(entry):
    # from the file itself: foamDictionary -value prints 6 digits only
    block, key = entry.split("/")
    body = re.search(r"\n%s\n\{(.*?)\n\}" % re.escape(block), text, re.S).group(1)
    return re.search(r"\n\s*%s\s+(\S+);" % key, body).group(1)
def field(name, where=None):
    text = open((where or timeDir) + "/" + name).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(([^)]*)\)", text)
    if m:
        return [float(v) for v in m.group(2).split()]
    m = re.search(r"internalField\s+uniform\s+(\S+);", text)
    return [float(m.group(1))]
species = {"fine": 1e-3, "coarse": 2e-3}
fMat, xWmMin, phiMin = 2.0, 2e-8, 0.05
nf, nc, T = field("n.fine", startDir), field("n.coarse", startDir), field("T")
cells = max(len(nf), len(nc), len(T))
get = lambda f, i: f[i] if len(f) > 1 else f[0]
worst, agitated = 0.0, 0
for s, d in species.items():
    C, b, alpha = (float(value("omega.%s/%s" % (s, p))) for p in ("C", "b", "alpha"))
    K, c = (float(value("Wmean.%s/%s" % (s, p))) for p in ("K", "c"))
    S = field("S." + s)
    for i in range(cells):
        phi = get(nf, i) + get(nc, i)
        t = get(T, i)
        if phi < phiMin:
            continue
        if t <= 0:
            if get(S, i) != 0:
                print("S.%s = %g in cell %d with T = 0" % (s, get(S, i), i)); sys.exit(1)
            continue
        agitated += 1
        x = get(nc, i)/phi
        g0 = (1 - phi/2)/(1 - phi)**3
        omega = C*math.sqrt(t/3)/d*phi*g0**b*(1 + alpha*x)
        W = K*(t/3)*phi**c
        expected = fMat*d*omega*W*math.exp(-(xWmMin/d)/W)
        if expected < 1e-200:
            # threshold far above the impacts (exp underflows): S = 0
            if abs(get(S, i)) > 1e-200:
                print("S.%s = %g in cell %d, expected 0" % (s, get(S, i), i)); sys.exit(1)
            continue
        worst = max(worst, abs(get(S, i) - expected)/expected)
if agitated == 0:
    print("no agitated cell holding material: nothing checked"); sys.exit(1)
print("S.fine, S.coarse in %d agitated cells: max %.3g, max relative deviation from the laws %.2e"
      % (agitated, max(max(field("S.fine")), max(field("S.coarse"))), worst))
sys.exit(0 if worst < 1e-9 else 1)
PY
}

# A small calibration with breakage (the tutorial's 8 conditions, sampling
# 0.01 s): omega.<s> and Wmean.<s> of both species written with errors and
# selection next to D; -fromCase adds breakage exactly when the breakage
# model is calibrated; segregationDegradationFoam runs one step of the
# closed box (tests/solver/closedBox) with Savage-Jeffrey T and the
# calibrated breakage on the fitted laws, S matches the laws cell by cell;
# bad input to the model (missing law, negative fMat) names the entry
test_calibration_breakage()
{
    local dir="$workRoot/calibrationBreakage" solver="$workRoot/calibrationBreakageSolver"
    local fromCase="$workRoot/calibrationBreakageFromCase"
    copy_calibration_case "$dir"
    local d="$dir/system/calibrationDict"
    foamDictionary -entry coefficients -set "(D breakage)" "$d" > /dev/null
    foamDictionary -entry samplingTime -set 0.01 "$d" > /dev/null
    foamDictionary -entry plot -set false "$d" > /dev/null
    local start=$SECONDS
    calibrateGranularMixture -case "$dir" > "$dir/log.calibrateGranularMixture" 2>&1 \
        || { tail -30 "$dir/log.calibrateGranularMixture"; return 1; }
    echo "calibration of 8 conditions with breakage: $((SECONDS - start)) s"
    local coeffs="$dir/constant/granularCoefficients" s
    foamDictionary -entry D/law -value "$coeffs" > /dev/null || { echo "no D law"; return 1; }
    for s in fine coarse
    do
        [ "$(foamDictionary -entry "omega.$s/law" -value "$coeffs")" = collisionFrequencyGroups ] \
            || { echo "omega.$s/law missing or wrong"; return 1; }
        [ "$(foamDictionary -entry "Wmean.$s/law" -value "$coeffs")" = impactEnergyGroups ] \
            || { echo "Wmean.$s/law missing or wrong"; return 1; }
        foamDictionary -entry "omega.$s/errors/C" -value "$coeffs" > /dev/null || { echo "omega.$s has no errors"; return 1; }
        foamDictionary -entry "Wmean.$s/selection/impactEnergyGroups" -value "$coeffs" > /dev/null \
            || { echo "Wmean.$s has no selection"; return 1; }
        python3 - "$s" \
            "$(foamDictionary -entry "omega.$s/C" -value "$coeffs")" \
            "$(foamDictionary -entry "omega.$s/b" -value "$coeffs")" \
            "$(foamDictionary -entry "omega.$s/alpha" -value "$coeffs")" \
            "$(foamDictionary -entry "omega.$s/R2" -value "$coeffs")" \
            "$(foamDictionary -entry "Wmean.$s/K" -value "$coeffs")" \
            "$(foamDictionary -entry "Wmean.$s/c" -value "$coeffs")" \
            "$(foamDictionary -entry "Wmean.$s/R2" -value "$coeffs")" <<'PY' || return 1
import math, sys
s = sys.argv[1]
C, b, alpha, R2o, K, c, R2W = map(float, sys.argv[2:])
print("%s: omega C %.4g b %.4g alpha %.4g (R2 %.3f); Wmean K %.4g c %.4g (R2 %.3f)"
      % (s, C, b, alpha, R2o, K, c, R2W))
ok = all(math.isfinite(v) for v in (C, b, alpha, K, c)) and C > 0 and K > 0 \
    and 1 + alpha > 0 and R2o > 0.5 and R2W > 0.5
sys.exit(0 if ok else 1)
PY
    done
    grep -A6 "^Exponential-spectrum check" "$dir/log.calibrateGranularMixture"

    # -fromCase: breakage only when the breakage model is calibrated
    local model expect
    for model in none vogelPeukert calibrated
    do
        rm -rf "$fromCase"; cp -r "$projectDir/tests/calibration/fromCase" "$fromCase"
        echo "breakage { model $model; }" >> "$fromCase/constant/granularProperties"
        case "$model" in calibrated) expect="coefficients (D breakage)" ;; *) expect="coefficients (D)" ;; esac
        calibrateGranularMixture -case "$fromCase" -fromCase -dryRun > "$fromCase/log.$model" 2>&1 \
            || { tail -20 "$fromCase/log.$model"; return 1; }
        grep -qF "breakage $model in constant/granularProperties -> $expect" "$fromCase/log.$model" \
            || { echo "breakage $model: not '$expect'"; grep "^-fromCase:" "$fromCase/log.$model"; return 1; }
    done
    foamDictionary -entry diffusivity/model -set none "$fromCase/constant/granularProperties" > /dev/null
    calibrateGranularMixture -case "$fromCase" -fromCase -dryRun > "$fromCase/log.breakageOnly" 2>&1 \
        || { tail -20 "$fromCase/log.breakageOnly"; return 1; }
    grep -qF -- "-> coefficients (breakage)" "$fromCase/log.breakageOnly" \
        || { echo "breakage alone not calibrated"; grep "^-fromCase:" "$fromCase/log.breakageOnly"; return 1; }
    echo "-fromCase: breakage none/vogelPeukert -> (D), calibrated -> (D breakage), diffusivity none -> (breakage)"

    # The solver, one step on the fitted laws
    rm -rf "$solver"; cp -r "$projectDir/tests/solver/closedBox" "$solver"
    cp "$coeffs" "$solver/constant/"
    local props="$solver/constant/granularProperties" ctrl="$solver/system/controlDict"
    foamDictionary -entry writeFields -set "(nTotal T S)" "$props" > /dev/null
    foamDictionary -entry granularTemperature -set "{ model savageJeffrey; savageJeffreyCoeffs { R 1; } }" "$props" > /dev/null
    foamDictionary -entry breakage -remove "$props" > /dev/null
    cat >> "$props" <<'DICT'
breakage
{
    model       calibrated;
    calibratedCoeffs { fMat 2; xWmMin 2e-8; outsideEnvelope extrapolate; }
    daughterSizeDistribution { model uniformBinary; }
    fines       finestClass;
}
DICT
    foamDictionary -entry libs -set '("libcalibratedModels.so")' "$ctrl" > /dev/null
    foamDictionary -entry endTime -set 1e-3 "$ctrl" > /dev/null
    foamDictionary -entry adjustTimeStep -set no "$ctrl" > /dev/null
    foamDictionary -entry writeControl -set timeStep "$ctrl" > /dev/null
    foamDictionary -entry writeInterval -set 1 "$ctrl" > /dev/null
    blockMesh -case "$solver" > "$solver/log.blockMesh" 2>&1 || { cat "$solver/log.blockMesh"; return 1; }
    cp -r "$solver/0.orig" "$solver/0"
    setFields -case "$solver" > "$solver/log.setFields" 2>&1 || { cat "$solver/log.setFields"; return 1; }
    start=$SECONDS
    segregationDegradationFoam -case "$solver" > "$solver/log.solver" 2>&1 || { tail -30 "$solver/log.solver"; return 1; }
    echo "solver, one step with the calibrated breakage: $((SECONDS - start)) s"
    grep -q "Selecting breakage model calibrated" "$solver/log.solver" || { echo "calibrated breakage not selected"; return 1; }
    grep "calibrated omega.fine\|calibrated Wmean.coarse" "$solver/log.solver"
    [ -f "$solver/0.001/S.coarse" ] || { echo "no S.coarse at 0.001"; ls "$solver"; return 1; }
    check_breakage_rates "$coeffs" "$solver/0" "$solver/0.001" || return 1

    # Bad input names the entry: a law missing, a negative material constant
    local kind
    for kind in missingLaw negativeFMat
    do
        rm -rf "$solver/0.001"
        cp "$coeffs" "$solver/constant/granularCoefficients"
        case "$kind" in
            missingLaw) # (foamDictionary -remove reads the dot as a scope)
                python3 -c 'import re, sys; p = sys.argv[1]; t = open(p).read(); open(p, "w").write(re.sub(r"\nWmean\.coarse\n\{.*?\n\}\n", "\n", t, flags=re.S))' \
                    "$solver/constant/granularCoefficients"
                ! grep -q "^Wmean.coarse" "$solver/constant/granularCoefficients" || { echo "Wmean.coarse not removed"; return 1; }
                expect="Wmean.coarse" ;;
            negativeFMat) foamDictionary -entry breakage/calibratedCoeffs/fMat -set -2 "$props" > /dev/null; expect="fMat -2" ;;
        esac
        if segregationDegradationFoam -case "$solver" > "$solver/log.$kind" 2>&1
        then
            echo "$kind accepted"; return 1
        fi
        echo "$kind: $(grep -A2 "FOAM FATAL" "$solver/log.$kind" | sed -n 2p)"
        grep -q "FOAM FATAL IO ERROR" "$solver/log.$kind" || { echo "no FatalIOError"; tail -5 "$solver/log.$kind"; return 1; }
        grep -qF -- "$expect" "$solver/log.$kind" || { echo "message lacks $expect"; return 1; }
    done
}
