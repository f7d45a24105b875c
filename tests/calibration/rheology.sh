# shellcheck shell=bash
# calibrateGranularMixture's rheology (coefficients (rheology)): the bulk's
# mu(I) and phi(I) from pressure-controlled sheared cells of the tutorial's
# material, and the muI bulk flow that takes them (`rheology calibrated`).
# Sourced by tests/run; tests calibration/rheology/*.

# rheology_case DIR "I list" STRAINS: the tutorial case calibrating only the
# rheology, 150 grains per cell at sigma_yy 1333 Pa (kn/(p d) 1000)
rheology_case()
{
    copy_calibration_case "$1"
    local d="$1/system/calibrationDict"
    foamDictionary -entry coefficients -set "(rheology)" "$d" > /dev/null
    foamDictionary -entry particles -set 150 "$d" > /dev/null
    foamDictionary -entry timeStep -set 1e-6 "$d" > /dev/null
    foamDictionary -entry rheology -set "{ inertialNumber ($2); pressure 1333; $3 }" "$d" > /dev/null
}

# The calibration of 5 cells (I 0.12-0.3, about 30 s): every cell stored with
# its rheology group; the written mu_s, mu_d, I_0 minimise the weighted chi2
# of Jop's law over the stored cells (each moved by 1e-3 of itself, chi2 does
# not drop), packedFraction is the weighted linear fit's phi_c (closed form,
# recomputed here); a rerun runs nothing and writes the same coefficients; a
# transport calibration (D) afterwards keeps the rheology and adds D; the
# inclined plane with `rheology calibrated` gives bitwise the velocity of the
# same values given in muICoeffs.
test_calibration_rheology()
{
    local dir="$workRoot/calibrationRheology"
    rheology_case "$dir" "0.12 0.16 0.2 0.25 0.3" "equilibrationStrain 6; samplingStrain 8;"
    local start=$SECONDS
    calibrateGranularMixture -case "$dir" > "$dir/log.1" 2>&1 || { tail -30 "$dir/log.1"; return 1; }
    echo "rheology calibration of 5 cells: $((SECONDS - start)) s"
    grep -E "^  (muI|phiILinear) =|model choice" "$dir/log.1"
    local h5="$dir/constant/calibration.h5" coeffs="$dir/constant/granularCoefficients"
    local groups
    groups=$(h5ls "$h5/conditions" | awk '{print $1}')
    [ "$(echo "$groups" | grep -c '^rheology_I')" -eq 5 ] || { echo "5 rheology cells expected in the store:"; echo "$groups"; return 1; }
    echo "$groups" | grep -q "^rheology_I0.2_p1333_x0.5_seed1$" || { echo "cell not stored by its name"; return 1; }
    local rows g
    rows=$(for g in $groups
    do
        h5dump -a "/conditions/$g/rheology/inertialNumber" -a "/conditions/$g/rheology/stressRatio" \
            -a "/conditions/$g/rheology/stressRatioError" -a "/conditions/$g/rheology/solidsFraction" \
            -a "/conditions/$g/rheology/solidsFractionError" -a "/conditions/$g/rheology/regime" -m "%.17g" "$h5" \
            | awk '/\(0\):/ { $1 = ""; printf "%s ", $0 } END { print "" }'
    done)
    echo "store rows (I mu muErr phi phiErr regime):"; echo "$rows"
    local values=()
    for e in mu_s mu_d I_0 packedFraction cells
    do
        values+=("$(foamDictionary -entry "rheology/$e" -value "$coeffs")") || return 1
    done
    echo "written: mu_s ${values[0]} mu_d ${values[1]} I_0 ${values[2]} packedFraction ${values[3]} cells ${values[4]}"
    python3 - "${values[@]}" <<PY || return 1
import sys
mus, mud, I0, phic, cells = (float(v) for v in sys.argv[1:])
rows = []
for line in """$rows""".strip().splitlines():
    f = line.split()
    assert f[5].strip('"') == "dense", line   # "dense flow"
    rows.append(tuple(float(v) for v in f[:5]))
assert len(rows) == 5 and cells == 5, rows
def chi2(p):
    s, d, i0 = p
    return sum(((mu - (s + (d - s)/(i0/I + 1)))/e)**2 for I, mu, e, phi, pe in rows)
best = chi2((mus, mud, I0))
worst = 0.0
for k in range(3):
    for sign in (-1, 1):
        p = [mus, mud, I0]
        p[k] *= 1 + sign*1e-3
        worst = min(worst, chi2(p) - best)
print("chi2 at the written mu(I) %.6g; largest drop when moved by 1e-3: %.3g" % (best, -worst))
# the written values carry 6 digits: a drop below 1e-6 of chi2 is their rounding
assert worst > -1e-6*max(best, 1), "mu(I) is not the weighted least-squares fit of the stored cells"
w = [1/pe**2 for I, mu, e, phi, pe in rows]
sw = sum(w); sx = sum(wi*r[0] for wi, r in zip(w, rows)); sy = sum(wi*r[3] for wi, r in zip(w, rows))
sxx = sum(wi*r[0]**2 for wi, r in zip(w, rows)); sxy = sum(wi*r[0]*r[3] for wi, r in zip(w, rows))
slope = (sw*sxy - sx*sy)/(sw*sxx - sx*sx)
phi0 = (sy - slope*sx)/sw
print("phi_c recomputed %.6g, written %.6g" % (phi0, phic))
assert abs(phi0 - phic) <= 2e-6, "packedFraction is not the weighted linear fit's phi_c"
PY
    [ -s "$dir/postProcessing/calibration/rheology.dat" ] || { echo "no rheology.dat"; return 1; }
    [ -s "$dir/postProcessing/calibration/rheology.png" ] || { echo "no rheology.png"; return 1; }

    # Resume: everything stored, nothing runs, the same coefficients
    cp "$coeffs" "$dir/granularCoefficients.1"
    calibrateGranularMixture -case "$dir" > "$dir/log.2" 2>&1 || { tail -20 "$dir/log.2"; return 1; }
    grep -q "^DEM: 0 conditions run and stored, 5 taken from" "$dir/log.2" || { grep "^DEM" "$dir/log.2"; echo "the rerun ran cells"; return 1; }
    diff -q "$coeffs" "$dir/granularCoefficients.1" > /dev/null || { diff "$coeffs" "$dir/granularCoefficients.1"; echo "the rerun changed the coefficients"; return 1; }

    # D added to the same calibration: its conditions run beside the stored
    # rheology cells, which are reused (the transport cells' run controls
    # are not part of the rheology cells' settings)
    local d="$dir/system/calibrationDict"
    foamDictionary -entry coefficients -set "(D rheology)" "$d" > /dev/null
    calibrateGranularMixture -case "$dir" > "$dir/log.3" 2>&1 || { tail -20 "$dir/log.3"; return 1; }
    grep -q "^DEM: 8 conditions run and stored, 5 taken from" "$dir/log.3" \
        || { grep "^DEM" "$dir/log.3"; echo "the rheology cells were not reused beside D's 8 conditions"; return 1; }
    # and a transport calibration alone afterwards keeps the rheology
    foamDictionary -entry coefficients -set "(D)" "$d" > /dev/null
    foamDictionary -entry rheology -remove "$d" > /dev/null
    calibrateGranularMixture -case "$dir" > "$dir/log.4" 2>&1 || { tail -20 "$dir/log.4"; return 1; }
    foamDictionary -entry D/law -value "$coeffs" > /dev/null || { echo "no D after the transport calibration"; return 1; }
    [ "$(foamDictionary -entry rheology/mu_s -value "$coeffs")" = "${values[0]}" ] \
        || { echo "the transport calibration lost the rheology"; cat "$coeffs"; return 1; }
    echo "D calibrated afterwards: D/law $(foamDictionary -entry D/law -value "$coeffs"), rheology/mu_s still ${values[0]}"

    # The muI bulk flow takes them: the inclined plane (28 deg, 1 s of flow)
    # with `rheology calibrated` and with the same numbers given
    local kind
    for kind in calibrated given
    do
        mui_bad_case "$dir/$kind" || return 1
        local case="$dir/$kind/inclinedPlaneMuI" props="$dir/$kind/inclinedPlaneMuI/constant/granularProperties"
        # (sed: foamDictionary would write the file without its #includeIfPresent)
        sed -i -E '/^ *(mu_s|mu_d|I_0|packedFraction) /d' "$props"
        echo "endTime 1; writeInterval 1;" > "$case/system/caseParameters"
        if [ "$kind" = calibrated ]
        then
            cp "$coeffs" "$case/constant/"
            echo "rheology calibrated;" > "$case/constant/muIOverrides"
        else
            for e in mu_s mu_d I_0 packedFraction d rhoS
            do
                echo "$e $(foamDictionary -entry "rheology/$e" -value "$coeffs");"
            done > "$case/constant/muIOverrides"
        fi
        # the 10 mm layer, at the calibrated packed fraction
        sed -i "s/volScalarFieldValue n.grain 0.6/volScalarFieldValue n.grain ${values[3]}/" "$case/system/setFieldsDict"
        setFields -case "$case" > "$case/log.setFields" 2>&1 || { tail -20 "$case/log.setFields"; return 1; }
        segregationDegradationFoam -case "$case" > "$case/log.solver" 2>&1 || { tail -20 "$case/log.solver"; return 1; }
        [ -f "$case/1/U" ] || { echo "$kind: no U at 1 s"; return 1; }
    done
    grep "muI: rheology calibrated" "$dir/calibrated/inclinedPlaneMuI/log.solver" || { echo "no report of the calibrated rheology"; return 1; }
    # the same numbers, so the same flow: bitwise
    diff -q "$dir/calibrated/inclinedPlaneMuI/1/U" "$dir/given/inclinedPlaneMuI/1/U" > /dev/null \
        || { echo "U differs between rheology calibrated and the same values given"; return 1; }
    # the bulk flows, and by the calibrated law: its largest speed in the
    # layer (alpha > 0.5) lies between no motion and free sliding g sin(28) t
    local ubulk
    ubulk=$(python3 -c '
import re, sys
def internal(path):
    t = open(path).read().split("internalField")[1].split("boundaryField")[0]
    return [float(v) for v in re.findall(r"[-0-9.eE+]+", t.split("(", 1)[1])]
u = internal(sys.argv[1]); a = internal(sys.argv[2])
ux = u[0::3]
print(max(abs(x) for x, al in zip(ux, a) if al > 0.5))' \
        "$dir/calibrated/inclinedPlaneMuI/1/U" "$dir/calibrated/inclinedPlaneMuI/1/alpha.granular")
    echo "inclined plane with the calibrated rheology: U bitwise that of the values given, bulk speed $ubulk m/s after 1 s"
    python3 -c "import math, sys; sys.exit(0 if 1e-3 < float('$ubulk') < 0.9*9.81*math.sin(math.radians(28)) else 1)" \
        || { echo "the bulk does not flow, or slides freely"; return 1; }
}

# Cells that are not steady dense flows are reported and not stored: at I
# 0.6-1 the cells are gases (Z < 1 or a sigma_yy <= 0 block), each reported
# with the figures that decided; the fit needs 4 steady dense cells, so the
# run stops naming the count, nothing stored, no granularCoefficients
test_calibration_rheology_gas()
{
    local dir="$workRoot/calibrationRheologyGas"
    rheology_case "$dir" "0.6 0.7 0.85 1" "equilibrationStrain 2; samplingStrain 4;"
    if calibrateGranularMixture -case "$dir" > "$dir/log" 2>&1
    then
        echo "a calibration of gas cells was accepted"; return 1
    fi
    grep "left out of the rheology fit" "$dir/log" | cut -c1-220
    [ "$(grep -c "left out of the rheology fit, not stored (.*regime gas" "$dir/log")" -eq 4 ] \
        || { echo "4 cells reported as gases expected"; tail -20 "$dir/log"; return 1; }
    grep -q "The rheology fit needs at least 4 steady dense cells (three parameters of mu(I)); 0 of 4 cells" "$dir/log" \
        || { sed -n '/FOAM FATAL/,$p' "$dir/log"; echo "no refusal naming the count"; return 1; }
    [ ! -e "$dir/constant/granularCoefficients" ] || { echo "granularCoefficients written"; return 1; }
    if [ -e "$dir/constant/calibration.h5" ]
    then
        local n
        n=$(h5ls "$dir/constant/calibration.h5/conditions" 2> /dev/null | wc -l)
        [ "$n" -eq 0 ] || { echo "$n gas cells stored"; return 1; }
    fi
    echo "4 gas cells reported, none stored, the fit refused"
}

# Spread over 2 MPI ranks (-parallel) the rheology cells are dealt 2 + 2 and
# the master merges the processor stores: the stored cells are those of a
# serial run, bitwise (timing groups aside). -noFit: 4 cells over I 0.16-0.3
# do not identify mu_d and I_0 (the fit says so); the fit is
# calibrateAndUse's
test_calibration_rheology_parallel()
{
    local ref="$workRoot/calibrationRheologySerial" dir="$workRoot/calibrationRheologyParallel" d
    for d in "$ref" "$dir"
    do
        rheology_case "$d" "0.16 0.2 0.25 0.3" "equilibrationStrain 6; samplingStrain 8;"
        # one cell at a time in the serial run: its conditions must not
        # depend on how many run at once either
        foamDictionary -entry concurrentConditions -set 1 "$d/system/calibrationDict" > /dev/null
    done
    calibrateGranularMixture -case "$ref" -noFit > "$ref/log" 2>&1 || { tail -20 "$ref/log"; return 1; }
    mpirun --allow-run-as-root --oversubscribe -np 2 calibrateGranularMixture -parallel -case "$dir" -noFit > "$dir/log" 2>&1 \
        || { tail -20 "$dir/log"; return 1; }
    local r0 r1
    r0=$(grep -c "^\[0\] condition .* done in" "$dir/log")
    r1=$(grep -c "^\[1\] condition .* done in" "$dir/log")
    echo "rank 0 ran $r0, rank 1 ran $r1 rheology cells"
    [ "$r0" -eq 2 ] && [ "$r1" -eq 2 ] || { echo "cells not spread 2 + 2 over the ranks"; return 1; }
    grep -q "Merged 4 conditions of 2 processor stores" "$dir/log" || { grep -i merged "$dir/log"; echo "no merge of 4 conditions"; return 1; }
    dump_conditions "$ref/constant/calibration.h5" > "$ref/conditions.txt"
    dump_conditions "$dir/constant/calibration.h5" > "$dir/conditions.txt"
    [ "$(grep -c 'GROUP "rheology"' "$ref/conditions.txt")" -eq 4 ] || { echo "the serial store lacks its 4 rheology groups"; return 1; }
    diff -q "$ref/conditions.txt" "$dir/conditions.txt" > /dev/null \
        || { echo "cells differ from the serial run:"; diff "$ref/conditions.txt" "$dir/conditions.txt" | head -20; return 1; }
    echo "4 cells on 2 ranks: the store ($(wc -l < "$dir/conditions.txt") dump lines) identical to the serial run's"
}
