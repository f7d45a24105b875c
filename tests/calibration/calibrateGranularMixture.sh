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

# small_store DIR: the tutorial case in DIR with a store made now, of one
# condition (phi 0.2, x 0.2, T 0.005, the tutorial's DEM settings), no fit:
# the refusals of an existing store (truncated, stored with other DEM
# settings or another driving) start from it, never from a store an earlier
# test or an older run left behind
small_store()
{
    copy_calibration_case "$1"
    local d="$1/system/calibrationDict"
    foamDictionary -entry phi -set "(0.2)" "$d" > /dev/null
    foamDictionary -entry x -set "(0.2)" "$d" > /dev/null
    foamDictionary -entry T -set "(0.005)" "$d" > /dev/null
    calibrateGranularMixture -case "$1" -noFit > "$1/log.store" 2>&1 \
        || { tail -20 "$1/log.store"; echo "small store: the calibration failed"; return 1; }
    local n
    n=$(h5ls "$1/constant/calibration.h5/conditions" 2> /dev/null | wc -l)
    [ "$n" -eq 1 ] || { echo "small store: $n conditions stored, expected 1"; return 1; }
}

# Attributes of a species of the conditions of a store whose names match a grep
# pattern, one line "condition a b ..." per condition (full precision):
# condition_attributes store pattern species attribute...
condition_attributes()
{
    local store=$1 pattern=$2 species=$3 g a
    shift 3
    for g in $(h5ls "$store/conditions" | awk '{print $1}' | grep -- "$pattern")
    do
        local args=()
        for a in "$@"; do args+=(-a "/conditions/$g/species/$species/$a"); done
        echo "$g $(h5dump "${args[@]}" -m "%.17g" "$store" | awk '/\(0\):/ { printf "%s ", $2 }')"
    done
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
    # the time step is reported, at timeStep 0 half the largest accepted (t_c/100 of t_c/50)
    grep "^DEM time step" "$dir/log.calibrateGranularMixture" | python3 -c '
import re, sys
line = sys.stdin.read()
m = re.match(r"DEM time step (\S+) s \(timeStep 0: t_c/100; the largest accepted, t_c/50: (\S+) s\)", line)
if not m:
    sys.exit("no DEM time step line: %r" % line)
step, largest = float(m.group(1)), float(m.group(2))
print("DEM time step %g s, largest %g s" % (step, largest))
sys.exit(0 if step > 0 and abs(largest/step - 2) < 1e-4 else "step %g is not half of %g" % (step, largest))' \
        || return 1
    # an ETA after every condition, never negative, 0 after the last
    python3 - "$dir/log.calibrateGranularMixture" <<'PYEOF' || return 1
import re, sys
etas = [float(x) for x in re.findall(r" done in \S+ s, ETA (\S+) s", open(sys.argv[1]).read())]
print("ETAs [s]: " + " ".join("%.2f" % e for e in etas))
if len(etas) != 8 or min(etas) < 0 or etas[-1] != 0:
    sys.exit("ETAs: 8 expected, >= 0, the last 0")
PYEOF
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
    # plot true: the PNG is part of the output (gnuplot-nox is installed by etc/bootstrap;
    # without it the check fails rather than being skipped)
    command -v gnuplot > /dev/null || { echo "gnuplot not found: the D(T) plot cannot be checked"; return 1; }
    [ -s "$dir/postProcessing/calibration/D_x0.2.png" ] || { echo "no D(T) plot"; return 1; }
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
# no granularCoefficients, a foreign calibration.h5 left untouched. The
# refusals of an existing store (truncated, other DEM settings, another
# driving) each run on a store made for it (small_store)
test_calibration_bad_input()
{
    local dir="$workRoot/calibrationBad" kind
    local kinds="unknownCoefficient unknownLaw emptyPhi invertedT jammedPhi negativeT xOutside textStore foreignHdf5 truncatedStore settingsChanged drivingChanged finiteSizeAndParticles finiteSizeOneSize finiteSizeOrder badAttribution badDiffusivityEstimate nveMode shearedWithT shearedNoGammaDot drivenWithGammaDot strainWithTime drivenWithStrain shearedGammaDotZero pairUnknownSpecies pairSetsNothing pairRestitution rheologyIZero rheologyIAboveOne rheologyPressureZero rheologyPressureNegative rheologyNoPressure rheologyNoEntry rheologyNotCalibrated"
    for kind in $kinds
    do
        # the kinds that need an existing store make their own, now
        local store="$workRoot/calibrationBadStore-$kind"
        case "$kind" in
            truncatedStore|settingsChanged|drivingChanged) small_store "$store" || return 1 ;;
        esac
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
            settingsChanged) cp "$store/constant/calibration.h5" "$dir/constant/"
                foamDictionary -entry phi -set "(0.2 0.35 0.5)" "$d" > /dev/null
                foamDictionary -entry particles -set 300 "$d" > /dev/null; expect="other DEM settings" ;;
            finiteSizeAndParticles) foamDictionary -entry finiteSize -set "{ particles (100 200); }" "$d" > /dev/null; expect="'particles' and 'finiteSize' both given" ;;
            finiteSizeOneSize) foamDictionary -entry particles -remove "$d" > /dev/null
                foamDictionary -entry finiteSize -set "{ particles (200); }" "$d" > /dev/null; expect="at least two cell sizes" ;;
            finiteSizeOrder) foamDictionary -entry particles -remove "$d" > /dev/null
                foamDictionary -entry finiteSize -set "{ particles (200 100); }" "$d" > /dev/null; expect="from the smallest to the largest" ;;
            badAttribution) foamDictionary -entry sievingAttribution -set paper "$d" > /dev/null; expect="valid: seed" ;;
            badDiffusivityEstimate) foamDictionary -entry diffusivityEstimate -add einstein "$d" > /dev/null
                expect="Entry 'diffusivityEstimate' einstein: valid: greenKubo" ;;
            nveMode) foamDictionary -entry mode -set nve "$d" > /dev/null; expect="valid: thermostatted" ;;
            shearedWithT) foamDictionary -entry mode -set leesEdwards "$d" > /dev/null; expect="Entry 'T' does not apply with mode leesEdwards" ;;
            shearedNoGammaDot) foamDictionary -entry mode -set leesEdwards "$d" > /dev/null
                foamDictionary -entry T -remove "$d" > /dev/null; expect="'gammaDot'" ;;
            drivenWithGammaDot) foamDictionary -entry gammaDot -set "(10 20)" "$d" > /dev/null; expect="Entry 'gammaDot' does not apply with mode thermostatted" ;;
            strainWithTime) foamDictionary -entry mode -set leesEdwards "$d" > /dev/null
                foamDictionary -entry T -remove "$d" > /dev/null
                foamDictionary -entry gammaDot -set "(10 20)" "$d" > /dev/null
                foamDictionary -entry samplingStrain -set 10 "$d" > /dev/null; expect="Entry 'equilibrationTime' given with run lengths in strain" ;;
            drivenWithStrain) foamDictionary -entry samplingStrain -set 10 "$d" > /dev/null; expect="run lengths of sheared cells" ;;
            shearedGammaDotZero) foamDictionary -entry mode -set leesEdwards "$d" > /dev/null
                foamDictionary -entry T -remove "$d" > /dev/null
                foamDictionary -entry gammaDot -set "(0 20)" "$d" > /dev/null; expect="'gammaDot' (shear rate" ;;
            pairUnknownSpecies) foamDictionary -entry contact/pairs -set "{ glassSand { species (fine sand); restitution 0.7; } }" "$d" > /dev/null
                expect="unknown species 'sand'; valid: fine coarse" ;;
            pairSetsNothing) foamDictionary -entry contact/pairs -set "{ fineCoarse { species (fine coarse); } }" "$d" > /dev/null
                expect="contact/pairs/fineCoarse' sets nothing" ;;
            pairRestitution) foamDictionary -entry contact/pairs -set "{ fineCoarse { species (fine coarse); restitution 1.4; } }" "$d" > /dev/null
                expect="pair fine/coarse: restitution e = 1.4" ;;
            rheologyIZero) foamDictionary -entry coefficients -set "(rheology)" "$d" > /dev/null
                foamDictionary -entry rheology -set "{ inertialNumber (0 0.1); pressure 1000; }" "$d" > /dev/null
                expect="Entry 'inertialNumber': value 0 is outside (0, 1]" ;;
            rheologyIAboveOne) foamDictionary -entry coefficients -set "(D rheology)" "$d" > /dev/null
                foamDictionary -entry rheology -set "{ inertialNumber (0.1 1.5); pressure 1000; }" "$d" > /dev/null
                expect="Entry 'inertialNumber': value 1.5 is outside (0, 1]" ;;
            rheologyPressureZero) foamDictionary -entry coefficients -set "(rheology)" "$d" > /dev/null
                foamDictionary -entry rheology -set "{ inertialNumber (0.01 0.1); pressure 0; }" "$d" > /dev/null
                expect="Entry 'pressure 0' must be a pressure > 0 Pa" ;;
            rheologyPressureNegative) foamDictionary -entry coefficients -set "(rheology)" "$d" > /dev/null
                foamDictionary -entry rheology -set "{ inertialNumber (0.01 0.1); pressure -500; }" "$d" > /dev/null
                expect="Entry 'pressure -500' must be a pressure > 0 Pa" ;;
            rheologyNoPressure) foamDictionary -entry coefficients -set "(rheology)" "$d" > /dev/null
                foamDictionary -entry rheology -set "{ inertialNumber (0.01 0.1); }" "$d" > /dev/null
                expect="Missing entry 'pressure' \[Pa\]" ;;
            rheologyNoEntry) foamDictionary -entry coefficients -set "(rheology)" "$d" > /dev/null
                expect="the sub-dictionary 'rheology' is missing" ;;
            rheologyNotCalibrated) foamDictionary -entry rheology -set "{ inertialNumber (0.01 0.1); pressure 1000; }" "$d" > /dev/null
                expect="Entry 'rheology' given, but 'coefficients'" ;;
            drivingChanged) cp "$store/constant/calibration.h5" "$dir/constant/"
                foamDictionary -entry phi -set "(0.2 0.35 0.5)" "$d" > /dev/null
                foamDictionary -entry mode -set stochastic "$d" > /dev/null; expect="other DEM settings" ;;
            truncatedStore) # its first half
                head -c $(($(stat -c %s "$store/constant/calibration.h5")/2)) "$store/constant/calibration.h5" \
                    > "$dir/constant/calibration.h5"; expect="calibration.h5" ;;
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

# A sheared calibration (mode leesEdwards, 4 small Lees-Edwards cells at
# phi 0.5, run lengths in strain): the store holds gammaDot and R per
# condition, granularCoefficients the T-law of D with its gammaDotRange and
# the shearScaling dictionary; C = D/(gammaDot dMean^2) and R recomputed here
# from the store agree with what the utility wrote, and lie within a factor
# of 3 of Fan et al.'s 0.042 and within (1, 3) (the seed assumed R = 1)
test_calibration_sheared()
{
    local dir="$workRoot/calibrationSheared"
    copy_calibration_case "$dir"
    local d="$dir/system/calibrationDict"
    foamDictionary -entry mode -set leesEdwards "$d" > /dev/null
    foamDictionary -entry T -remove "$d" > /dev/null
    foamDictionary -entry gammaDot -set "(20 40)" "$d" > /dev/null
    foamDictionary -entry phi -set "(0.5)" "$d" > /dev/null
    foamDictionary -entry laws -set "(kineticTheoryGroups)" "$d" > /dev/null   # 2 parameters for 4 rows
    for e in equilibrationTime maxEquilibrationTime samplingTime
    do
        foamDictionary -entry "$e" -remove "$d" > /dev/null
    done
    foamDictionary -entry equilibrationStrain -set 1 "$d" > /dev/null
    foamDictionary -entry samplingStrain -set 8 "$d" > /dev/null
    local start=$SECONDS
    calibrateGranularMixture -case "$dir" > "$dir/log" 2>&1 || { tail -30 "$dir/log"; return 1; }
    echo "sheared calibration of 4 conditions: $((SECONDS - start)) s"
    grep -E "^  C = |^  R = " "$dir/log"
    local h5="$dir/constant/calibration.h5" coeffs="$dir/constant/granularCoefficients"
    h5ls "$h5/conditions" | grep -q "^phi0.5_x0.4_gammaDot40_seed1 " || { echo "sheared condition not stored by name"; h5ls "$h5/conditions"; return 1; }
    foamDictionary -entry D/gammaDotRange -value "$coeffs" | grep -q "( *20 40 *)" || { echo "no gammaDotRange in D"; return 1; }
    local C R
    C=$(foamDictionary -entry shearScaling/C -value "$coeffs") || return 1
    R=$(foamDictionary -entry shearScaling/R -value "$coeffs") || return 1
    # recompute from the store: per condition D of the fines, T, gammaDot, x
    local rows
    rows=$(for g in $(h5ls "$h5/conditions" | awk '{print $1}')
    do
        h5dump -a "/conditions/$g/gammaDot" -a "/conditions/$g/x" -a "/conditions/$g/T" \
            -a "/conditions/$g/species/fine/D" -a "/conditions/$g/species/fine/DError" -m "%.17g" "$h5" \
            | awk '/\(0\):/ { printf "%s ", $2 } END { print "" }'
    done)
    echo "store rows (gammaDot x T D DError):"; echo "$rows"
    python3 - "$C" "$R" "$dir/postProcessing/calibration/shearScaling.dat" <<PY || return 1
import sys, math
C, R = float(sys.argv[1]), float(sys.argv[2])
store = sorted(tuple(map(float, l.split())) for l in """$rows""".strip().splitlines())
dat = sorted(tuple(map(float, l.split())) for l in open(sys.argv[3]) if not l.startswith("#"))
assert len(store) == 4 and len(dat) == 4, (store, dat)
sw = swc = 0.0; Rs = []
for (g, x, T, D, DE), (phi, xd, gd, Td, Dd, DEd, c, ce, r, notDiffusive) in zip(sorted(store, key=lambda s: (s[1], s[0])), sorted(dat, key=lambda d: (d[1], d[2]))):
    dm = (1 - x)*1e-3 + x*2e-3
    # the file's rows are the store's values (its error raised where the
    # diffusive-regime check failed)
    assert (gd, xd) == (g, x) and abs(Dd - D) <= 1e-7*D and abs(Td - T) <= 1e-7*T, (g, x, D, Dd)
    assert abs(c - D/(gd*dm*dm)) <= 1e-6*c and abs(ce - DEd/(gd*dm*dm)) <= 1e-6*ce
    assert DEd >= DE*(1 - 1e-7) and (notDiffusive or abs(DEd - DE) <= 1e-7*DE)
    sw += 1/ce**2; swc += c/ce**2
    Rs.append(dm*g*math.sqrt(3/T))
Cs, Rm = swc/sw, sum(Rs)/len(Rs)
print("recomputed from the store: C = %.6g (written %.6g), R = %.6g (written %.6g)" % (Cs, C, Rm, R))
ok = abs(Cs - C) <= 1e-6*C and abs(Rm - R) <= 1e-6*R and 0.042/3 < C < 3*0.042 and 1 < R < 3
sys.exit(0 if ok else 1)
PY
    [ "$(grep -vc '^#' "$dir/postProcessing/calibration/shearScaling.dat")" -eq 4 ] || { echo "shearScaling.dat lacks rows"; return 1; }
}

# A finite-size calibration (finiteSize { particles (100 200); }), the larger
# cells run first (longest expected first): every
# condition runs at both sizes (store groups <name>_N100, _N200), D of the
# fines is extrapolated to the infinite cell, D(N) = D_inf - a N^(-1/3): the
# two-point formula recomputed here from the store gives finiteSize.dat's
# D_inf, and the fit's data (D_x0.2.dat) are those D_inf
test_calibration_finite_size()
{
    local dir="$workRoot/calibrationFiniteSize"
    copy_calibration_case "$dir"
    local d="$dir/system/calibrationDict"
    foamDictionary -entry particles -remove "$d" > /dev/null
    foamDictionary -entry finiteSize -set "{ particles (100 200); }" "$d" > /dev/null
    # two workers: the order check below does not then depend on timing
    foamDictionary -entry concurrentConditions -set 2 "$d" > /dev/null
    calibrateGranularMixture -case "$dir" > "$dir/log" 2>&1 || { tail -30 "$dir/log"; return 1; }
    grep -A3 "^Finite size" "$dir/log"
    # longest expected first: every N 200 cell starts before any N 100 one, so with two
    # workers the first seven to finish are N 200 cells
    local firstDone
    firstDone=$(grep "done in" "$dir/log" | head -7 | grep -c " N 200)")
    [ "$firstDone" -eq 7 ] || { echo "the first 7 cells done: $firstDone of N 200 (longest first)"; grep "done in" "$dir/log"; return 1; }
    local h5="$dir/constant/calibration.h5"
    [ "$(h5ls "$h5/conditions" | grep -c "_N100 ")" -eq 8 ] && [ "$(h5ls "$h5/conditions" | grep -c "_N200 ")" -eq 8 ] \
        || { echo "not 8 conditions per size"; h5ls "$h5/conditions"; return 1; }
    local rows
    rows=$(for g in $(h5ls "$h5/conditions" | awk '{print $1}')
    do
        printf "%s " "$g"
        h5dump -a "/conditions/$g/particles" -a "/conditions/$g/species/fine/D" -a "/conditions/$g/species/fine/DError" \
            -m "%.17g" "$h5" | awk '/\(0\):/ { printf "%s ", $2 } END { print "" }'
    done)
    python3 - "$dir/postProcessing/calibration/finiteSize.dat" "$dir/postProcessing/calibration/D_x0.2.dat" <<PY || return 1
import sys, math
cells = {}
for l in """$rows""".strip().splitlines():
    name, n, D, DE = l.split()
    cells.setdefault(name.rsplit("_N", 1)[0], {})[int(n)] = (float(D), float(DE))
fs = {l.split()[0]: list(map(float, l.split()[1:])) for l in open(sys.argv[1]) if not l.startswith("#")}
assert len(fs) == 8, fs
u1, u2 = 100**(-1/3), 200**(-1/3)
for point, v in fs.items():
    (n1, D1, e1, n2, D2, e2, Dinf, err) = v[:8]
    assert (n1, n2) == (100, 200), v
    # the file's cells are the store's (errors raised where the check failed)
    assert abs(D1 - cells[point][100][0]) <= 1e-7*D1 and abs(D2 - cells[point][200][0]) <= 1e-7*D2
    assert e1 >= cells[point][100][1]*(1 - 1e-7) and e2 >= cells[point][200][1]*(1 - 1e-7)
    want = (D2*u1 - D1*u2)/(u1 - u2)
    wantErr = math.sqrt(u1**2*e2**2 + u2**2*e1**2)/(u1 - u2)
    assert abs(Dinf - want) <= 1e-6*abs(want) and abs(err - wantErr) <= 1e-6*wantErr, (point, Dinf, want, err, wantErr)
# the plot's (and the fit's) data are the extrapolated values
plotted = sorted(float(l.split()[1]) for l in open(sys.argv[2]) if l.strip() and not l.startswith("#"))
expected = sorted(v[6] for p, v in fs.items() if "_x0.2_" in p)
assert len(plotted) == 4 and all(abs(a - b) <= 1e-7*abs(b) for a, b in zip(plotted, expected)), (plotted, expected)
print("D_inf of 8 points: two-point formula reproduced, plotted and fitted")
PY
}

# A fit that does not converge is reported naming the law, and
# granularCoefficients is not written. The eta data of the small tutorial
# run: (1 + beta x) cannot follow their x dependence, so beta runs off.
# Runs its own conditions (a store left by another test or an older run
# could hold other results).
test_calibration_fit_failure()
{
    local dir="$workRoot/calibrationFitFailure"
    copy_calibration_case "$dir"
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
# the tutorial's conditions (run here) and the dictionary holds the chosen eta law
test_calibration_eta()
{
    local dir="$workRoot/calibrationEta"
    copy_calibration_case "$dir"
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

    # sievingAttribution crossTerms: the same stored cells, eta with the stress
    # ACF's cross terms kept; per condition eta(crossTerms)/eta(seed) is the
    # store's etaWithCrossTerms/eta (the conversion to m2/s cancels)
    cp "$dir/postProcessing/calibration/eta_x0.2.dat" "$dir/eta_seed.dat"
    foamDictionary -entry sievingAttribution -set crossTerms "$dir/system/calibrationDict" > /dev/null
    calibrateGranularMixture -case "$dir" > "$dir/log.crossTerms" 2>&1 || { tail -20 "$dir/log.crossTerms"; return 1; }
    grep -q "^DEM: 0 conditions run" "$dir/log.crossTerms" || { echo "the attribution reran the DEM"; return 1; }
    local ratios
    ratios=$(condition_attributes "$dir/constant/calibration.h5" _x0.2_ coarse eta etaWithCrossTerms)
    python3 - "$dir/eta_seed.dat" "$dir/postProcessing/calibration/eta_x0.2.dat" <<PY || return 1
import sys
rows = lambda f: [tuple(map(float, l.split()[:2])) for l in open(f) if l.strip() and not l.startswith("#")]
seed, kept = rows(sys.argv[1]), rows(sys.argv[2])
store = sorted(kept_ / eta for eta, kept_ in (map(float, l.split()[1:]) for l in """$ratios""".strip().splitlines()))
ratios = sorted(k[1] / s[1] for s, k in zip(seed, kept))
assert len(ratios) == len(store) == 4, (ratios, store)
assert all(abs(a - b) <= 1e-6 * abs(b) for a, b in zip(ratios, store)), (ratios, store)
assert any(abs(r - 1) > 1e-3 for r in ratios), "the cross terms changed nothing"
print("eta with cross terms kept / seed's rule:", " ".join("%.3f" % r for r in ratios))
PY
}

# diffusivityEstimate meanSquareDisplacement: the same stored cells (no DEM rerun),
# the fit's D rows are the store's DMsd of the fines; greenKubo (default) its D
test_calibration_diffusivity_estimate()
{
    local dir="$workRoot/calibrationMsd"
    copy_calibration_case "$dir"   # its own cells, run by the first calibration below
    calibrateGranularMixture -case "$dir" > "$dir/log.greenKubo" 2>&1 || { tail -20 "$dir/log.greenKubo"; return 1; }
    grep -q "diffusivityEstimate greenKubo" "$dir/log.greenKubo" || { echo "the fit does not name its D"; return 1; }
    cp "$dir/postProcessing/calibration/D_x0.2.dat" "$dir/D_greenKubo.dat"
    foamDictionary -entry diffusivityEstimate -add meanSquareDisplacement "$dir/system/calibrationDict" > /dev/null
    calibrateGranularMixture -case "$dir" > "$dir/log.msd" 2>&1 || { tail -20 "$dir/log.msd"; return 1; }
    grep -q "^DEM: 0 conditions run" "$dir/log.msd" || { echo "the estimate reran the DEM"; return 1; }
    grep -q "diffusivityEstimate meanSquareDisplacement" "$dir/log.msd" || { echo "the fit does not name its D"; return 1; }
    local recorded
    recorded=$(foamDictionary -entry D/diffusivityEstimate -value "$dir/constant/granularCoefficients") || return 1
    [ "$recorded" = meanSquareDisplacement ] || { echo "granularCoefficients records D/diffusivityEstimate '$recorded'"; return 1; }
    grep -q "set title 'DEM (MSD" "$dir/postProcessing/calibration/D_x0.2.gp" || { echo "the plot does not name the MSD"; return 1; }
    local stored
    stored=$(condition_attributes "$dir/constant/calibration.h5" _x0.2_ fine D DMsd)
    python3 - "$dir/D_greenKubo.dat" "$dir/postProcessing/calibration/D_x0.2.dat" <<PY || return 1
import sys
rows = lambda f: sorted(float(l.split()[1]) for l in open(f) if l.strip() and not l.startswith("#"))
gk, msd = rows(sys.argv[1]), rows(sys.argv[2])
pairs = [tuple(map(float, l.split()[1:])) for l in """$stored""".strip().splitlines()]
storedGk, storedMsd = sorted(p[0] for p in pairs), sorted(p[1] for p in pairs)
assert len(gk) == len(msd) == len(pairs) == 4, (gk, msd, pairs)
assert all(abs(a - b) <= 1e-8 * b for a, b in zip(gk, storedGk)), (gk, storedGk)
assert all(abs(a - b) <= 1e-8 * b for a, b in zip(msd, storedMsd)), (msd, storedMsd)
assert any(abs(a / b - 1) > 1e-4 for a, b in zip(gk, msd)), "the two estimates are the same numbers"
print("D of the fines, x 0.2: MSD / Green-Kubo =", " ".join("%.3f" % (b / a) for a, b in zip(gk, msd)))
PY
    # cells outside the diffusive regime: the error raised is the MSD's own, by at
    # least |D_GK - D_MSD| (the disagreement counted as a systematic error)
    local raised
    raised=$(condition_attributes "$dir/constant/calibration.h5" . fine D DMsd DMsdError)
    python3 - "$dir/log.msd" <<PY || return 1
import re, sys
stored = {l.split()[0]: tuple(map(float, l.split()[1:])) for l in """$raised""".strip().splitlines()}
lines = re.findall(r"condition (\S+): D of the fines not in the diffusive regime .*raised from (\S+) to (\S+) m2/s",
                   open(sys.argv[1]).read())
assert lines, "no condition outside the diffusive regime to check"
for name, before, after in lines:
    D, msd, msdError = stored[name]
    assert abs(float(before) - msdError) <= 1e-5 * msdError, (name, before, msdError)
    assert float(after) >= max(msdError, abs(D - msd)) * (1 - 1e-5), (name, after, D, msd)
print("%d cells outside the diffusive regime: errors raised from the MSD's" % len(lines))
PY
}
