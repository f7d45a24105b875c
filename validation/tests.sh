# shellcheck shell=bash
# Tests of the validation cases (sourced by tests/run; tests validation/*):
# the case scripts and checks themselves live in the case folders.

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

# The kinematic bulk flow above a slot in a planar bin against the exact
# Nedderman-Tuzun field (validation/neddermanTuzunSlot/check) on 2, 4 and 8
# cells across the slot: with the default marchingScheme (linearUpwind)
# the finest pair's observed order of U_z is at least 1.8 in L1 and in the
# max norm and the finest L1 error below 6e-5 of the slot's speed.
# Measured: L1 7.9e-4, 1.8e-4, 3.8e-5 (orders 2.17, 2.19), max orders 2.13,
# 2.26; "Gauss upwind" gives L1 orders 1.44, 1.25 and 2.3e-4 at N = 8
test_nedderman_tuzun_slot()
{
    local dir="$workRoot/neddermanTuzunSlot" n
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/neddermanTuzunSlot" "$dir/"
    local case="$dir/neddermanTuzunSlot"
    : > "$dir/errors"
    for n in 2 4 8
    do
        "$case/Allrun" -n "$n" > "$dir/log.$n" 2>&1 || { tail -20 "$dir/log.$n"; return 1; }
        grep '^errors:' "$dir/log.$n" >> "$dir/errors"
    done
    cat "$dir/errors"
    python3 - "$dir/errors" <<'PY'
import sys
from sdfoam.foamcase import observedOrder
rows = [dict(zip(l.split()[1::2], map(float, l.split()[2::2]))) for l in open(sys.argv[1])]
ok = True
for norm, floor in (("L1", 1.8), ("max", 1.8)):
    orders = [observedOrder(a["h"], a[norm], b["h"], b[norm]) for a, b in zip(rows, rows[1:])]
    print("%s orders %s (finest pair >= %g)" % (norm, " ".join("%.2f" % p for p in orders), floor))
    ok = ok and orders[-1] >= floor
print("finest L1 %.3e (< 6e-5)" % rows[-1]["L1"])
ok = ok and rows[-1]["L1"] < 6e-5
sys.exit(0 if ok else 1)
PY
}

# A layer of uniform shear with the shear-rate closures (percolation and
# diffusivity shearRate): the exact steady profile to 4e-3 on 50 cells and
# 1e-3 on 100 (second order), the fines and the solids kept to 1e-10, and
# the same profile at four times the shear rate (to 1e-10): the closures'
# shear rate cancels (validation/uniformShearColumn/check)
test_uniform_shear_column()
{
    local dir="$workRoot/uniformShearColumn"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/uniformShearColumn" "$dir/"
    local case="$dir/uniformShearColumn"
    "$case/Allrun" -n 50 -gammaDot 100 -tol 4e-3 || return 1
    cp "$case/results/profile.dat" "$dir/profile100.dat"
    "$case/Allrun" -n 50 -gammaDot 400 -tol 4e-3 || return 1
    "$case/check" --same-as "$dir/profile100.dat" --tol-same 1e-10 || return 1
    "$case/Allrun" -n 100 -gammaDot 100 -tol 1e-3
}

# The same layer with `percolation calibrated` (libcalibratedModels.so), the law read
# from constant/granularCoefficients' segregationVelocity: fanSchlick with C_s 0.26 gives
# the shearRate model's profile (to 1e-10: the same law); trewhela (B 0.2, C 1) under the
# prescribed flow's lithostatic pressure (p* 0 at the top, 3.5 at the bottom) gives the
# exact pressure-dependent profile (./pressureProfile) to 1e-3 on 50 cells (measured
# 3.1e-4; the shearRate profile is 0.22 from it), with the fines and the solids kept to
# 1e-10 and n >= 0. Refused by name: no granularCoefficients, no segregationVelocity in
# it, an unknown law, a law's missing parameter, a pressure law with C <= 0
test_uniform_shear_column_calibrated()
{
    local dir="$workRoot/uniformShearColumnCalibrated"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/uniformShearColumn" "$dir/"
    local case="$dir/uniformShearColumn"
    "$case/Allrun" -n 50 -tol 4e-3 > "$dir/log.shearRate" 2>&1 || { tail -20 "$dir/log.shearRate"; return 1; }
    cp "$case/results/profile.dat" "$dir/profile.shearRate.dat"
    sed -i '/^percolation/,/^}/s/model       shearRate;/model       calibrated;/' "$case/constant/granularProperties"
    grep -A2 '^percolation' "$case/constant/granularProperties" | grep -q 'model       calibrated;' \
        || { echo "the percolation model was not switched"; return 1; }
    echo 'libs ("libcalibratedModels.so");' >> "$case/system/controlDict"
    coefficients()   # coefficients 'law entries'
    {
        printf 'FoamFile { version 2.0; format ascii; class dictionary; object granularCoefficients; }\n%s\n' \
            "segregationVelocity { $1 pStarRange (0 1e6); sizeRatioRange (1 10); xRange (0 1); }" \
            > "$case/constant/granularCoefficients"
    }
    coefficients "law fanSchlick; C_s 0.26;"
    "$case/Allrun" -n 50 -tol 4e-3 > "$dir/log.fanSchlick" 2>&1 || { tail -20 "$dir/log.fanSchlick"; return 1; }
    local out
    out=$(cd "$case" && ./check --same-as "$dir/profile.shearRate.dat" --tol-same 1e-10) \
        || { echo "$out"; return 1; }
    tail -n 2 <<< "$out"
    coefficients "law trewhela; B 0.2; C 1;"
    "$case/Allrun" -n 50 > "$dir/log.trewhela" 2>&1 || { tail -20 "$dir/log.trewhela"; return 1; }
    grep -q "percolation calibrated: S = B\*dMean\*(R - 1)/(C + pStar).*the pressure: lithostatic" \
        "$case/log.segregationDegradationFoam" || { echo "the model's log line is missing"; return 1; }
    out=$(cd "$case" && ./check --bounds-only) || { echo "$out"; return 1; }
    tail -n 4 <<< "$out"
    (cd "$case" && ./pressureProfile --tol 1e-3) || return 1
    # bad input: each refused with its message, no time written
    local bad
    for bad in "none|not found: there is no calibration of the segregation velocity" \
               "other { law trewhela; }|has no segregationVelocity sub-dictionary" \
               "segregationVelocity { law muI; }|unknown segregation law 'muI' (valid: fanSchlick, trewhela, trewhelaAsymmetric)" \
               "segregationVelocity { law trewhela; B 0.2; pStarRange (0 1); sizeRatioRange (1 3); xRange (0 1); }|law trewhela needs the parameter 'C', not found" \
               "segregationVelocity { law trewhela; B 0.2; C -1; pStarRange (0 1); sizeRatioRange (1 3); xRange (0 1); }|C must be > 0"
    do
        local body="${bad%%|*}" message="${bad#*|}"
        rm -f "$case/constant/granularCoefficients"
        [ "$body" = none ] || printf 'FoamFile { version 2.0; format ascii; class dictionary; object granularCoefficients; }\n%s\n' \
            "$body" > "$case/constant/granularCoefficients"
        if "$case/Allrun" -n 10 > "$dir/log.bad" 2>&1
        then
            echo "accepted: $body"; return 1
        fi
        grep -qF "$message" "$case/log.segregationDegradationFoam" \
            || { echo "refused without '$message':"; grep -A6 FATAL "$case/log.segregationDegradationFoam"; return 1; }
        echo "refused as it should: $message"
    done
}

# fresh_validation_case WORK CASE: a fresh copy of validation/CASE in
# $workRoot/WORK; prints the copy's path
fresh_validation_case()
{
    local dir="$workRoot/$1"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/$2" "$dir/" && echo "$dir/$2"
}

# The fill of a planar bin through a central inlet (validation/planarSiloFill,
# 10 mm cells, 2 s at 0.5 m/s): per species, the solids in the bin = what
# entered - what left (to 1e-8 of the fill), what entered = the feed (to
# 1e-8), less than 1e-6 of it out of the open top, 0 <= n, sum n <= 0.6
# alpha + 1e-8 (the check's assertions); without segregation and with the
# shear-rate closures, the second then discharged for 0.5 s (every written
# time within 0 <= n_i, sum n_i <= 0.6 + 1e-8)
test_planar_silo_fill()
{
    local dir="$workRoot/planarSiloFill"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/planarSiloFill" "$dir/"
    local case="$dir/planarSiloFill"
    "$case/Allrun" || return 1
    "$case/Allrun" -closures shearRate -discharge 0.5 || return 1
    local record="$case/postProcessing/outletComposition/2/outlet.dat"
    [ -s "$record" ] || { echo "no discharge record $record"; return 1; }
    # Material left through the slot in the discharge
    awk '!/^#/ { m = $8 + $9 } END { print "discharged " m " kg"; exit !(m > 0.01) }' "$record" || return 1
    # Nothing through the closed inlet in the discharge (the flux read at
    # the restart carries the inlet's new noSlip, not the fill's feed)
    awk '!/^#/ { m = $8 + $9 } END { print "through the closed inlet " m " kg"; exit !(m == 0) }' \
        "$case/postProcessing/outletComposition/2/inlet.dat" || return 1
    # Every written time of both stages: 0 <= n_i, their sum at most 0.6
    # (a discharge restarted with the flux rebuilt from U lifted alpha, and
    # so the species' sum, 1.4e-4 above packing)
    python3 -m sdfoam.fieldStats "$case" bounds --tol 1e-8 --packed 0.6
}

# A pour deposited where it lands (Allrun -deposition: the same feed, 1 s,
# glass beads, 10 mm cells; serial and on 2 ranks with the spout's column
# on the processor boundary): the check's balance (species 1e-8, solids
# 1e-10 of the fill; what was deposited against the pour to 1e-3, a step's
# worth), bounds, the species' sum packedFraction alpha.granular (1e-8);
# and a heap where the jet digs a crater: the highest
# column under the inlet, every column outward no higher than the one
# inside it (1 mm), the centre more than two cells above the walls
test_planar_silo_fill_deposition()
{
    local case
    case=$(fresh_validation_case planarSiloFillDeposition planarSiloFill) || return 1
    local opts
    for opts in "" -parallel
    do
        "$case/Allrun" -deposition -fill 1 $opts > "$case/../log.Allrun" 2>&1 \
            || { tail -20 "$case/../log.Allrun"; return 1; }
        echo "Allrun -deposition -fill 1 $opts:"
        grep "balance\|entered - fed\|slope beside" "$case/../log.Allrun"
        python3 -m sdfoam.fieldStats "$case" inBulk --packed 0.6 --tol 1e-8 || return 1
        python3 - "$case/results/fill.dat" <<'PY'
import sys
rows = [list(map(float, l.split())) for l in open(sys.argv[1]) if not l.startswith("#")]
h = [r[1] for r in rows]
n = len(h)
half = h[n // 2:]            # from the centre line out to the right wall
left = h[:n // 2][::-1]      # and to the left
print("surface heights from the centre out [m]:", " ".join("%.4f" % v for v in half))
ok = max(h) in (h[n // 2 - 1], h[n // 2])
for side in (half, left):
    ok = ok and all(b <= a + 1e-3 for a, b in zip(side, side[1:]))
    ok = ok and side[0] - side[-1] > 0.02
print("a heap with its apex under the inlet" if ok else "FAIL: not a heap under the inlet")
sys.exit(0 if ok else 1)
PY
        [ $? -eq 0 ] || return 1
    done
}

# The bounded heap's limits (Fan et al. 2014; Schlick et al. 2015), half
# fines and half coarse fed: with a segregation far stronger than the
# diffusion (the shear-rate closures, C_s 26 for 0.26) the deposit that rose
# with the heap is pure fines out to c W/2 from the centre line of the planar
# bin and out to sqrt(c) W/2 from the axis of the cylinder (--segregated:
# the fines share falls through 0.5 within one cell of the limit, >= 0.95
# inside, <= 0.05 in the outer ring; measured 0.0445 m for 0.05 m and
# 0.0684 m for 0.0707 m, 10 mm cells); without segregation each cell holds the feed's
# composition to 1e-9 (--mixed; 0 measured). Each run's balance as the
# check asserts it, the species' to 1e-7 (8.5e-9 and 1.9e-8 measured with
# the strong segregation)
test_planar_silo_fill_heap_limits()
{
    local case geometry
    case=$(fresh_validation_case planarSiloFillHeap planarSiloFill) || return 1
    for geometry in planar axisymmetric
    do
        local opts="-coarse 0.5 -fill 3" t=3
        [ "$geometry" = axisymmetric ] && { opts="-axisymmetric -b 0.04 -coarse 0.5 -fill 6"; t=6; }
        # shellcheck disable=SC2086
        "$case/Allrun" $opts -closures shearRate -Cs 26 -tol 1e-7 || return 1
        "$case/check" --time "$t" --feed 0.5 --coarse 0.5 --fill "$t" --tol 1e-7 --segregated || return 1
        # shellcheck disable=SC2086
        "$case/Allrun" $opts || return 1
        "$case/check" --time "$t" --feed 0.5 --coarse 0.5 --fill "$t" --mixed || return 1
    done
}

# The strong segregation's fill of the planar bin (as in the bounded-heap
# test) decomposed on 2 ranks: the species are solved again around
# compositions below 0 on both ranks (the log says so at least once: the
# cells marked on either side of the processor boundary), and the run
# passes the same assertions as the serial one (each species' balance to
# 1e-7, bounds, the complete-segregation limit)
test_planar_silo_fill_resolve_parallel()
{
    local case
    case=$(fresh_validation_case planarSiloFillResolveParallel planarSiloFill) || return 1
    "$case/Allrun" -coarse 0.5 -fill 3 -closures shearRate -Cs 26 -tol 1e-7 -parallel || return 1
    "$case/check" --time 3 --feed 0.5 --coarse 0.5 --fill 3 --tol 1e-7 --segregated || return 1
    local n
    n=$(grep -c "solved again" "$case/log.segregationDegradationFoam.fill")
    echo "solves again on 2 ranks: $n steps"
    [ "$n" -gt 0 ] || { echo "no solve again on 2 ranks: the parallel path untested"; return 1; }
}

# The fill decomposed on 2 ranks side by side (the inlet on the processor
# boundary), shear-rate closures, 0.2 s: the balance of each run (the
# check's assertions), the fields of the two runs within 1e-6
# (alpha.granular, n.fine, n.coarse; 3.9e-9 measured) and each species'
# total within 1e-8 (relative; 1.1e-10). Later the runs part pointwise as
# the serial run parts from its own mirror image: the falling stream's
# splash amplifies round-off (the serial run's left-right asymmetry 7.8e-3
# at 0.25 s, 0.41 at 1 s; 2 ranks against serial 1.8e-3, 0.27)
test_planar_silo_fill_parallel()
{
    local dir="$workRoot/planarSiloFillParallel" mode
    rm -rf "$dir"; mkdir -p "$dir"
    for mode in serial parallel
    do
        local opt=; [ "$mode" = parallel ] && opt=-parallel
        mkdir -p "$dir/$mode"
        cp -r "$validationDir/planarSiloFill/." "$dir/$mode/"
        # shellcheck disable=SC2086
        "$dir/$mode/Allrun" -closures shearRate -fill 0.2 $opt || return 1
    done
    python3 - "$dir" <<'PY'
import sys
from sdfoam import foamcase
work = sys.argv[1]
ok = True
for name in ("alpha.granular", "n.fine", "n.coarse"):
    a = foamcase.readScalarField(work + "/serial", "0.2", name)
    b = foamcase.readScalarField(work + "/parallel", "0.2", name)
    diff = max(abs(x - y) for x, y in zip(a, b))
    print("2 ranks vs serial at 0.2 s: max |difference| of %s %.3e" % (name, diff))
    ok = ok and diff < 1e-6
for name in ("n.fine", "n.coarse"):
    a = sum(foamcase.readScalarField(work + "/serial", "0.2", name))
    b = sum(foamcase.readScalarField(work + "/parallel", "0.2", name))
    rel = abs(b / a - 1)
    print("2 ranks vs serial at 0.2 s: total of %s %.3e (relative)" % (name, rel))
    ok = ok and rel < 1e-8
sys.exit(0 if ok else 1)
PY
}

# Starting the discharge from a settled map (Allrun -start, ./mapComposition):
# a synthetic map, flat surface at 0.105 m (half a 10 mm cell), coarse left
# of x = 0.1 m and fine right of it: the mapped bulk is W h to 1e-12, its
# coarse share 0.5 to 1e-12, the cells either side hold one species alone;
# then 0.3 s of discharge: material leaves through the slot
test_planar_silo_fill_from_map()
{
    local dir="$workRoot/planarSiloFillMap"
    rm -rf "$dir"; mkdir -p "$dir/map"
    cp -r "$validationDir/planarSiloFill" "$dir/"
    local case="$dir/planarSiloFill"
    python3 - "$dir/map" <<'PY' || return 1
import sys
d = sys.argv[1]
with open(d + "/composition.dat", "w") as f:
    f.write("# x z solidsFraction coarseShare\n")
    for i in range(20):
        for k in range(30):
            x, z = (i + 0.5) * 0.01, (k + 0.5) * 0.01
            f.write("%g %g %g %s\n" % (x, z, 0.6 if z < 0.105 else 0,
                                         ("1" if x < 0.1 else "0") if z < 0.105 else "nan"))
        f.write("\n")
with open(d + "/surface.dat", "w") as f:
    for i in range(20):
        f.write("%g 0.105\n" % ((i + 0.5) * 0.01))
PY
    "$case/Allrun" -start "$dir/map/composition.dat" -discharge 0.3 || return 1
    python3 - "$case" <<'PY'
import sys
from sdfoam import foamcase
case = sys.argv[1]
C = foamcase.cellCentres(case)
a = foamcase.readScalarField(case, "0", "alpha.granular")
nf = foamcase.readScalarField(case, "0", "n.fine")
nc = foamcase.readScalarField(case, "0", "n.coarse")
V = 0.2 * 0.3 * 0.01 / len(C)
bulk = sum(a) * V / 0.01
share = sum(nc) / (sum(nf) + sum(nc))
mixed = max(min(f, c) for f, c in zip(nf, nc))
print("mapped: bulk %.12g m2 (expected 0.021), coarse share %.12g, largest min(n.fine, n.coarse) %.3e"
      % (bulk, share, mixed))
ok = abs(bulk / 0.021 - 1) < 1e-12 and abs(share - 0.5) < 1e-12 and mixed == 0
rows = [l.split() for l in open(case + "/postProcessing/outletComposition/0/outlet.dat") if not l.startswith("#")]
out = float(rows[-1][7]) + float(rows[-1][8])
print("discharged in 0.3 s: %.4g kg (per 10 mm of depth)" % out)
sys.exit(0 if ok and out > 0 else 1)
PY
}

# The fill with a calibrated rheology (Allrun -granularCoefficients FILE,
# the shipped calibration of tutorials/resources/calibratedRheology: packed
# fraction 0.612214): muI takes it (rheology calibrated), the feed enters at
# that packing (the inlet's n.fine + n.coarse), ./check's balance holds with
# it and every cell's species sum to at most that packing times alpha; a
# FILE that is
# missing or has no rheology is refused naming it, before anything runs
test_planar_silo_fill_calibrated_rheology()
{
    local dir="$workRoot/planarSiloFillCalibrated" shipped="$projectDir/tutorials/resources/calibratedRheology/granularCoefficients.shipped"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/planarSiloFill" "$dir/"
    local case="$dir/planarSiloFill" out
    out=$("$case/Allrun" -granularCoefficients "$dir/none" 2>&1) && { echo "a missing file was accepted"; return 1; }
    echo "$out" | grep -F -- "-granularCoefficients: no file $dir/none" || { echo "$out"; return 1; }
    printf 'FoamFile { version 2.0; format ascii; class dictionary; object granularCoefficients; }\nD { law powerLaw; }\n' > "$dir/noRheology"
    out=$("$case/Allrun" -granularCoefficients "$dir/noRheology" 2>&1) && { echo "a file without rheology was accepted"; return 1; }
    echo "$out" | grep -F -- "no rheology.packedFraction" || { echo "$out"; return 1; }
    "$case/Allrun" -fill 1 -discharge 0.2 -granularCoefficients "$shipped" > "$dir/log.Allrun" 2>&1 \
        || { tail -20 "$dir/log.Allrun"; return 1; }
    grep "muI: rheology calibrated" "$case/log.segregationDegradationFoam.fill" || return 1
    local packed
    packed=$(foamDictionary -entry rheology.packedFraction -value "$shipped") || return 1
    python3 -m sdfoam.fieldStats "$case" inBulk --packed "$packed" --tol 1e-8 || return 1
    python3 - "$case" "$packed" <<'PY'
import re, sys
case, packed = sys.argv[1], float(sys.argv[2])
def inlet(name):
    text = open(case + "/0/" + name).read()
    block = text[text.index("inlet"):]
    return float(re.search(r"value\s+uniform\s+([0-9.eE+-]+)", block).group(1))
feed = inlet("n.fine") + inlet("n.coarse")
print("the feed's solids fraction %.10g (the calibration's packed fraction %.10g)" % (feed, packed))
sys.exit(0 if abs(feed - packed) < 1e-9 else 1)
PY
}

# The fill with the calibrated closures (Allrun -closures calibrated: the
# segregation velocity and the shear-rate diffusivity's C of a
# calibrateGranularMixture segregationVelocity file, here silo2D's, the same
# 1 and 2 mm grains as this bin; with the calibrated rheology): the file
# missing or given without the closures refused by name; the solver selects
# percolation calibrated, the file's C and -outsideEnvelope extrapolate (an
# unknown policy, and the case's own copy, which Allclean would remove,
# refused); the check's balance (1e-8), the
# bounds over every written time; and the fill segregates: the largest
# |coarse share - feed's| of a cell above 0.05 where the same fill without
# closures keeps it below 1e-6
test_planar_silo_fill_calibrated_closures()
{
    local dir="$workRoot/planarSiloFillClosures" file="$projectDir/tutorials/silo2D/constant/segregationVelocity"
    local shipped="$projectDir/tutorials/resources/calibratedRheology/granularCoefficients.shipped"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/planarSiloFill" "$dir/"
    local case="$dir/planarSiloFill" out mode C spread
    out=$("$case/Allrun" -closures calibrated 2>&1) && { echo "no file was accepted"; return 1; }
    echo "$out" | grep -F -- "-closures calibrated needs -segregationVelocity FILE" || { echo "$out"; return 1; }
    out=$("$case/Allrun" -closures calibrated -segregationVelocity "$dir/none" 2>&1) \
        && { echo "a missing file was accepted"; return 1; }
    echo "$out" | grep -F -- "given: '$dir/none'" || { echo "$out"; return 1; }
    out=$("$case/Allrun" -closures calibrated -segregationVelocity "$file" -outsideEnvelope bogus 2>&1) \
        && { echo "an unknown -outsideEnvelope was accepted"; return 1; }
    echo "$out" | grep -F -- "-outsideEnvelope: 'bogus' is not one of: clamp extrapolate error" || { echo "$out"; return 1; }
    mkdir -p "$case/constant"; cp "$file" "$case/constant/segregationVelocity"
    out=$("$case/Allrun" -closures calibrated -segregationVelocity "$case/constant/segregationVelocity" 2>&1) \
        && { echo "the case's own copy was accepted (Allclean removes it)"; return 1; }
    echo "$out" | grep -F -- "give a file outside the case's constant/" || { echo "$out"; return 1; }
    [ -f "$case/constant/segregationVelocity" ] || { echo "the given file was removed"; return 1; }
    out=$("$case/Allrun" -segregationVelocity "$file" 2>&1) && { echo "a file without the closures was accepted"; return 1; }
    echo "$out" | grep -F -- "-segregationVelocity and -outsideEnvelope need -closures calibrated" || { echo "$out"; return 1; }
    C=$(foamDictionary -entry shearRateDiffusivity/C -value "$file") || return 1
    for mode in none calibrated
    do
        "$case/Allclean" > /dev/null
        if [ "$mode" = calibrated ]
        then
            "$case/Allrun" -fill 1 -granularCoefficients "$shipped" -closures calibrated \
                -segregationVelocity "$file" -outsideEnvelope extrapolate > "$dir/log.$mode" 2>&1 \
                || { tail -20 "$dir/log.$mode"; return 1; }
            grep "Selecting percolation model calibrated" "$case/log.segregationDegradationFoam.fill" || return 1
            grep "percolation calibrated: .*outside: extrapolate" "$case/log.segregationDegradationFoam.fill" || return 1
            grep -F "C $C;" "$case/constant/mechanismOverrides" || { echo "C $C not given to the diffusivity"; return 1; }
            python3 -m sdfoam.fieldStats "$case" bounds --tol 1e-8 --packed "$(foamDictionary -entry rheology.packedFraction -value "$shipped")" || return 1
        else
            "$case/Allrun" -fill 1 -granularCoefficients "$shipped" > "$dir/log.$mode" 2>&1 \
                || { tail -20 "$dir/log.$mode"; return 1; }
        fi
        spread=$(sed -n "s/.*largest |coarse share - feed's| of a cell //p" "$dir/log.$mode")
        echo "$mode: largest |coarse share - feed's| of a cell $spread"
        [ -n "$spread" ] || { echo "no spread in the check's output"; return 1; }
        if [ "$mode" = calibrated ]
        then
            awk -v s="$spread" 'BEGIN { exit !(s > 0.05) }' || { echo "the calibrated closures did not segregate"; return 1; }
        else
            awk -v s="$spread" 'BEGIN { exit !(s < 1e-6) }' || { echo "the fill without closures segregated"; return 1; }
        fi
    done
}

# The fill's extremes: a single-species feed (no coarse appears anywhere); a
# feed of pure coarse onto a bed of fines (each species' balance to 5e-8:
# 1.25e-9 measured; the solids' to 1e-10, as every run's check); no feed
# (nothing enters, nothing moves: exactly 0 solids); a fill that overflows
# the bin (a FatalError naming the open top and the inlet, no field with a
# NaN written)
test_planar_silo_fill_extremes()
{
    local dir="$workRoot/planarSiloFillExtremes"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/planarSiloFill" "$dir/"
    local case="$dir/planarSiloFill" log
    "$case/Allrun" -coarse 0 -fill 1 || return 1
    python3 -c "
import sys
from sdfoam import foamcase
nc = foamcase.readScalarField('$case', '1', 'n.coarse')
print('single-species feed: max n.coarse %.3e' % max(map(abs, nc)))
sys.exit(0 if max(map(abs, nc)) == 0 else 1)" || return 1
    "$case/Allrun" -bed 0.1 -coarse 1 -fill 1 -tol 5e-8 || return 1
    "$case/Allrun" -feed 0 -fill 0.5 || return 1
    python3 -c "
import sys
from sdfoam import foamcase
a = foamcase.readScalarField('$case', '0.5', 'alpha.granular')
print('no feed: bulk in the bin %.3e' % sum(a))
sys.exit(0 if sum(a) == 0 else 1)" || return 1
    if "$case/Allrun" -feed 1 -fill 4 > "$dir/overflow.out" 2>&1
    then
        echo "the overflowing fill ran to its end"; return 1
    fi
    log="$case/log.segregationDegradationFoam.fill"
    grep -q "The fill overflows the bin" "$log" \
        && grep -q "(atmosphere)" "$log" && grep -q "(inlet)" "$log" \
        || { echo "no overflow message in $log"; tail -n 20 "$log"; return 1; }
    grep -A2 "FATAL ERROR" "$log"
    if grep -l -i nan "$case"/[0-9]*/n.* "$case"/[0-9]*/alpha.granular 2> /dev/null
    then
        echo "NaN written"; return 1
    fi
}

# The planar hopper (planarSiloFill -hopper 20, walls at 19.9 deg with
# Coulomb friction 16.7 deg, 5 mm cells, 100 mm wide, 24 mm slot): half
# fines fed for 1 s with the shear-rate closures (the fill's balance as the
# check asserts it), then 0.3 s of discharge: each species in the hopper at
# the end plus what left (slot, inlet, top) equals the fill's to 1e-8 of it;
# bounds at every written time; mass flow: in every row of the lower three
# quarters of the hopper the wall cell moves at >= 0.3 of the centre cell's
# speed at the last two writes (0.63-0.88 measured), where the flat bin of
# the same width (20 mm slot) leaves its floor's corner stagnant (< 0.05 in
# the two lowest rows; below 1e-3 measured). Refused: a half-angle outside (0,
# 90) and -hopper with -axisymmetric
test_planar_silo_fill_hopper()
{
    local case
    case=$(fresh_validation_case planarSiloFillHopper planarSiloFill) || return 1
    local geometry="-W 0.1 -H 0.2 -dx 5e-3 -coarse 0.5 -fill 1 -feed 0.5 -closures shearRate -wallFriction 16.7"
    local refused
    for refused in "-hopper 95" "-hopper 20 -axisymmetric"
    do
        # shellcheck disable=SC2086
        if "$case/Allrun" $refused > "$case/refused.out" 2>&1
        then
            echo "Allrun $refused ran"; return 1
        fi
        grep -- "-hopper" "$case/refused.out" || { cat "$case/refused.out"; return 1; }
    done
    local pattern
    for pattern in flat hopper
    do
        local opts="-b 0.02"
        [ "$pattern" = hopper ] && opts="-b 0.024 -hopper 20"
        # shellcheck disable=SC2086
        "$case/Allrun" $geometry $opts -discharge 0.3 || return 1
        python3 -m sdfoam.fieldStats "$case" bounds --tol 1e-8 --packed 0.6 || return 1
        python3 - "$case" "$pattern" <<'PY' || return 1
import math, os, re, sys
from sdfoam import foamcase
case, pattern = sys.argv[1], sys.argv[2]
params = open(os.path.join(case, "system", "caseParameters")).read()
zc = float(re.search(r"\bzc\s+([^;]+);", params).group(1)) if pattern == "hopper" else 0.0
V = foamcase.readScalarField(case, "0", "V")
ok = True
# The discharge's balance per species (kg per m of depth x depth)
out = [0.0, 0.0]
for patch in ("outlet", "inlet", "atmosphere"):
    rows = foamcase.readColumns(os.path.join(case, "postProcessing", "outletComposition", "1", patch + ".dat"))
    out[0] += rows[-1][7] / 2500
    out[1] += rows[-1][8] / 2500
for k, sp in enumerate(("fine", "coarse")):
    start = sum(n * v for n, v in zip(foamcase.readScalarField(case, "1", "n." + sp), V))
    end = sum(n * v for n, v in zip(foamcase.readScalarField(case, "1.3", "n." + sp), V))
    err = (end + out[k] - start) / start
    print("%s: %s at the fill's end %.10e m3, discharged %.10e, left %.10e: balance %.3e"
          % (pattern, sp, start, out[k], end, err))
    ok = ok and abs(err) <= 1e-8 and out[k] > 0.2 * start
# Wall against centre speeds, rows of the lower three quarters of the
# hopper (the flat bin: its two lowest rows)
C = foamcase.cellCentres(case)
rows = {}
for i, c in enumerate(C):
    rows.setdefault(round(c[2], 7), []).append(i)
zs = sorted(rows)
zs = [z for z in zs if z < 0.75 * zc] if pattern == "hopper" else zs[:2]
worst, best = float("inf"), 0.0
for t in ("1.225", "1.3"):
    U = foamcase.readVectorField(case, t, "U")
    for z in zs:
        ids = sorted(rows[z], key=lambda i: C[i][0])
        centre = min(ids, key=lambda i: abs(C[i][0] - 0.05))
        for wall in (ids[0], ids[-1]):
            r = math.sqrt(sum(u * u for u in U[wall])) / math.sqrt(sum(u * u for u in U[centre]))
            worst, best = min(worst, r), max(best, r)
print("%s: wall/centre speed over %d rows: min %.3g max %.3g" % (pattern, len(zs), worst, best))
ok = ok and (worst >= 0.3 if pattern == "hopper" else best < 0.05)
sys.exit(0 if ok else 1)
PY
    done
}

# validation/convergenceStudy: every case on its meshes held to the study's
# targets (column and Gaussian: order >= 1.8; chute, upwind and the three
# TVD variants: meeting point within 2 %, L1 order >= 0.8, bounds and
# n.fine + n.coarse = 1 to 1e-8 on every mesh), every error figure equal to
# the published results file's (1e-4 relative), and docs/validation.md's
# generated part the one that file gives
test_convergence_study()
{
    local dir="$workRoot/validation"
    "$validationDir/convergenceStudy" --check-docs || return 1
    "$validationDir/convergenceStudy" --work "$dir" --results "$dir/convergenceStudy-results.json" \
        --compare "$validationDir/convergenceStudy-results.json"
}

# Breakage on one closed cell (validation/breakageSingleCell): the class-edge
# volumes of S = v^2 with uniform binary fragments, exact to 1e-12 (the
# check's assertion)
test_breakage_edge_volumes()
{
    local dir="$workRoot/breakageEdge"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/breakageSingleCell" "$dir/"
    "$dir/breakageSingleCell/Allrun" edge
}

# One implicit Euler step at S_max dt = 1e-3 .. 1e6 against a dense solve
# (1e-8 per class), positive, solids + dust kept to 1e-12; solids + dust
# kept with backward in time as well; then 100 and 200 steps against Reid's
# exact solution in time: first order in dt
test_breakage_implicit_step()
{
    local dir="$workRoot/breakageImplicit" sdt
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/breakageSingleCell" "$dir/"
    for sdt in 1e-3 1 1e3 1e6
    do
        "$dir/breakageSingleCell/Allrun" implicit --sdt "$sdt" || return 1
    done
    local e1 e2
    e1=$("$dir/breakageSingleCell/Allrun" implicit --dt 0.01 --steps 100 -- --reid | sed -n 's/^reidResult //p' | awk '{print $2}')
    e2=$("$dir/breakageSingleCell/Allrun" implicit --dt 0.005 --steps 200 -- --reid | sed -n 's/^reidResult //p' | awk '{print $2}')
    [ -n "$e1" ] && [ -n "$e2" ] || { echo "no Reid comparison"; return 1; }
    # The dust field follows the species' time scheme: the balance holds with
    # backward (BDF2) too
    "$dir/breakageSingleCell/Allrun" implicit --dt 0.2 --steps 30 --ddt backward -- --balance-only || return 1
    python3 -c "
import math, sys
e1, e2 = $e1, $e2
p = math.log(e1/e2)/math.log(2)
print('Reid: error %.3e (dt 0.01), %.3e (dt 0.005): order %.3f in dt' % (e1, e2, p))
sys.exit(0 if 0.9 < p < 1.1 and e1 < 1e-3 else 1)"
}

# Ziff & McGrady (1985) on geometric grids of ratio 2, 2^(1/2), 2^(1/4):
# volume kept to 1e-12 on each, class numbers and moments converging at an
# order in ln r between 1.7 and 2.3; and the peer's grid (29 classes of
# ratio 1.5): L1 error of the class numbers under 2 %
test_breakage_ziff_mcgrady()
{
    local dir="$workRoot/breakageZiff"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/breakageSingleCell" "$dir/"
    local case="$dir/breakageSingleCell"
    "$case/Allrun" ziff --ratio 1.5 --classes 29 -- --tol-l1 0.02 || return 1
    "$case/Allrun" study > "$dir/log.study" || { cat "$dir/log.study"; return 1; }
    grep "study:\|ziff: L1" "$dir/log.study"
    python3 - "$case/results/ziffConvergence.dat" <<'PY'
import math, sys
rows = [list(map(float, l.split())) for l in open(sys.argv[1]) if not l.startswith("#")]
ok = len(rows) == 3
for a, b in zip(rows, rows[1:]):
    for col in (1, 2, 3, 5):
        p = math.log(abs(a[col]) / abs(b[col])) / math.log(math.log(a[0]) / math.log(b[0]))
        ok = ok and 1.7 < p < 2.3
for r in rows:
    ok = ok and r[4] <= 1e-12
ok = ok and rows[-1][1] < 0.02 and rows[-1][5] < 0.02
sys.exit(0 if ok else 1)
PY
}

# Side by side with OpenFOAM v1912's population balance (Debian's
# reactingMultiphaseEulerFoam) on the Foundation's single-cell breakup case:
# both against Ziff & McGrady class by class (the compare's assertions: our
# L1 error of the class numbers under 2 %, our volume kept to 1e-12; the
# peer's figures printed)
test_breakage_peer()
{
    local dir="$workRoot/breakagePeer"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/breakageSingleCell" "$validationDir/breakagePeer" "$dir/"
    rm -rf "$dir/breakagePeer/run" "$dir/breakagePeer/peer/run"
    "$dir/breakagePeer/Allrun"
}

# mu(I) flow down an inclined plane from rest to steady (validation/
# inclinedPlaneMuI): Bagnold's profile to 1 % of the surface speed at 24 and
# 28 degrees with the standard law, and at 28 degrees with the partially
# regularised law against its own I_theta; steady to 1 % over the last 2 s
# (the check's assertions)
test_inclined_plane_mui()
{
    local dir="$workRoot/inclinedPlaneMuI" run
    for run in "-angle 24" "-angle 28" "-angle 28 -regularised"
    do
        rm -rf "$dir"; mkdir -p "$dir"
        cp -r "$validationDir/inclinedPlaneMuI" "$dir/"
        # shellcheck disable=SC2086
        "$dir/inclinedPlaneMuI/Allrun" $run -tol 0.01 > "$dir/log.Allrun" 2>&1 \
            || { tail -20 "$dir/log.Allrun"; return 1; }
        echo "Allrun $run:"; grep -E "theta|max \|u" "$dir/log.Allrun"
    done
}

# mui_bad_case DIR: a fresh copy of validation/inclinedPlaneMuI in DIR,
# meshed, with 0/ and gravity tilted to 28 degrees
mui_bad_case()
{
    rm -rf "$1"; mkdir -p "$1"
    cp -r "$validationDir/inclinedPlaneMuI" "$1/"
    local case="$1/inclinedPlaneMuI"
    echo "FoamFile { version 2.0; format ascii; class uniformDimensionedVectorField; location \"constant\"; object g; } dimensions [0 1 -2 0 0 0 0]; value (4.6 0 -8.66);" > "$case/constant/g"
    blockMesh -case "$case" > "$case/log.blockMesh" 2>&1 || return 1
    cp -r "$case/0.orig" "$case/0"
}

# mui_expect_refusal CASE LABEL EXPECT [io]: the solver stops with EXPECT in
# its fatal error (a FatalIOError with `io`), does not crash and writes no
# time directory (check_refusal)
mui_expect_refusal()
{
    local case="$1" label="$2" expect=("$3")
    [ "${4:-}" != io ] || expect+=("FOAM FATAL IO ERROR")
    check_refusal "$case" segregationDegradationFoam "${expect[@]}" > "$case/log.refusal" \
        || { echo "$label:"; cat "$case/log.refusal"; return 1; }
    echo "$label: refused: $3"
}

# muI's bad input: mu_s >= mu_d, a negative I_0, a negative d, an unknown
# forces, etaMax, pMin, rhoAir, muAir not > 0, packedFraction above 1, a
# negative settlingVelocity, Beverloo's k not > 0, emptyAnnulus without
# outletPatches, a deposition (a pour deposited where it lands) with a rate
# or radius not > 0, an unknown entry, a composition that names an unknown
# species, leaves one out or does not sum to 1, an end not after its start or
# a spout over no cell, an unknown or out-of-range wall condition, the open top's alphaMin outside
# (0, 1), species whose sum is not
# packedFraction alpha.granular, a species ddt scheme other than Euler, a
# div(phi,n) with explicit correction: each a fatal error naming the entry
# or file, nothing written
test_mui_bad_input()
{
    local dir="$workRoot/muIBadInput" case="$workRoot/muIBadInput/inclinedPlaneMuI" entry value expect
    for entry in "mu_s 0.7:'mu_d 0.643' must be > mu_s" "I_0 -0.1:'I_0 -0.1' must be > 0" "d -1e-3:'d -0.001' must be > 0" "forces cellCentred:Unknown 'forces cellCentred'; valid: (faceFlux cellGradient)" "etaMax -1:'etaMax -1' must be > 0" "pMin 0:'pMin 0' must be > 0" "rhoAir -1.2:'rhoAir -1.2' must be > 0" "muAir 0:'muAir 0' must be > 0" "packedFraction 1.2:'packedFraction 1.2' must lie in (0, 1]" "settlingVelocity -1:'settlingVelocity -1' must be >= 0" "k 0:'k 0' must be > 0" "emptyAnnulus yes:'emptyAnnulus yes' needs 'outletPatches'" \
        "deposition { rate 0; centre (0 0 0); radius 1e3; composition { grain 1; } }:'rate 0' must be > 0" \
        "deposition { rate 1e-4; centre (0 0 0); radius -1; composition { grain 1; } }:'radius -1' must be > 0" \
        "deposition { rate 1e-4; centre (0 0 0); radius 1e3; composition { grain 1; } speed 2; }:Unknown entry 'speed'" \
        "deposition { rate 1e-4; centre (0 0 0); radius 1e3; composition { sand 1; } }:Unknown entry 'sand'" \
        "deposition { rate 1e-4; centre (0 0 0); radius 1e3; composition { } }:No entry for species 'grain'" \
        "deposition { rate 1e-4; centre (0 0 0); radius 1e3; composition { grain 0.5; } }:sum to 0.5, not 1" \
        "deposition { rate 1e-4; centre (0 0 0); radius 1e3; composition { grain 1; } start 1; end 1; }:'end 1' must be after 'start 1'" \
        "deposition { rate 1e-4; centre (1e3 1e3 0); radius 1e-6; composition { grain 1; } }:No cell centre lies within 'radius 1e-06'" \
        "deposition yes:'deposition' must be a dictionary"
    do
        value="${entry%%:*}"; expect="${entry#*:}"
        mui_bad_case "$dir" || return 1
        echo "${value};" > "$case/constant/muIOverrides"
        mui_expect_refusal "$case" "$value" "$expect" || return 1
    done
    # rheology calibrated: an unknown source, a calibrated entry also given,
    # no granularCoefficients in the case, one without the rheology
    local props="$case/constant/granularProperties"
    for entry in "unknown:Unknown 'rheology measured'; valid: (given calibrated)" "both:Entry 'mu_s' given with 'rheology calibrated'" "noFile:'rheology calibrated': there is no calibration in the case" "noRheology:has no sub-dictionary rheology (the rheology was not calibrated)"
    do
        value="${entry%%:*}"; expect="${entry#*:}"
        mui_bad_case "$dir" || return 1
        echo "rheology calibrated;" > "$case/constant/muIOverrides"
        if [ "$value" != both ]
        then
            # (sed: foamDictionary would write the file without its #includeIfPresent)
            sed -i -E '/^ *(mu_s|mu_d|I_0|packedFraction) /d' "$props"
        fi
        case "$value" in
            unknown) echo "rheology measured;" > "$case/constant/muIOverrides" ;;
            noRheology) printf 'FoamFile { version 2.0; format ascii; class dictionary; object granularCoefficients; }\nD { law powerLaw; }\n' > "$case/constant/granularCoefficients" ;;
        esac
        mui_expect_refusal "$case" "rheology $value" "$expect" io || return 1
    done
    # The wall condition: an unknown model (OpenFOAM's selection lists the
    # valid types) and a wall friction angle outside [0, 90)
    for entry in "coulombFriction; wallFrictionAngle 20:Unknown patchField type coulombFriction" "coulombWallFriction; wallFrictionAngle 95:'wallFrictionAngle 95' on patch bed of U must lie in [0, 90)" "coulombWallFriction:Entry 'wallFrictionAngle' not found"
    do
        value="${entry%%:*}"; expect="${entry#*:}"
        mui_bad_case "$dir" || return 1
        foamDictionary -case "$case" -entry boundaryField.bed -set "{ type ${value}; value uniform (0 0 0); }" "$case/0/U" > /dev/null || return 1
        mui_expect_refusal "$case" "bed U $value" "$expect" io || return 1
    done
    # The open top's bulk threshold alphaMin must lie in (0, 1)
    for value in 0 1
    do
        mui_bad_case "$dir" || return 1
        foamDictionary -case "$case" -entry boundaryField.atmosphere -set "{ type prghBulkRetainingTotalPressure; p0 uniform 0; alphaMin ${value}; value uniform 0; }" "$case/0/p_rgh" > /dev/null || return 1
        mui_expect_refusal "$case" "atmosphere p_rgh alphaMin $value" "'alphaMin ${value}' on patch atmosphere of p_rgh must lie in (0, 1)" io || return 1
    done
    # The species live in the bulk: their sum must be packedFraction alpha
    # at the start, their ddt scheme Euler (as MULES), their div(phi,n)
    # scheme one without explicit correction
    for entry in "sum:differs from packedFraction 0.6 x alpha.granular" "ddt:ddtSchemes: 'ddt(n.grain)' is CrankNicolson" "div:divSchemes: 'div(phi,n)' is Gauss linearUpwind"
    do
        value="${entry%%:*}"; expect="${entry#*:}"
        mui_bad_case "$dir" || return 1
        case "$value" in
            sum) sed -i 's/^internalField .*/internalField   uniform 0.3;/' "$case/0/n.grain" ;;
            ddt) sed -i 's/^\( *default *\)Euler;/\1Euler;\n    ddt(n.grain) CrankNicolson 0.9;/' "$case/system/fvSchemes" ;;
            div) sed -i 's/div(phi,n) *Gauss vanLeer01;/div(phi,n) Gauss linearUpwind grad(n);/' "$case/system/fvSchemes" ;;
        esac
        mui_expect_refusal "$case" "species $value" "$expect" io || return 1
    done
}

# Coulomb wall friction (coulombWallFriction on U) under the inclined layer
# (validation/inclinedPlaneMuI -wallFriction): from rest, the layer's
# mass-weighted mean velocity follows a t, a = g (sin theta - tan delta_w
# cos theta), to 1 % of a t_end over 1 s when the bed slides (20 degrees on
# a 12-degree wall: a plug, the bulk below yield; 28 degrees on a 20-degree
# wall: sliding and shearing), and the layer stays at rest (bulk speed
# below 1e-3 of the frictionless a t_end) when tan delta_w > tan theta
test_mui_coulomb_wall()
{
    local dir="$workRoot/muICoulombWall" run
    for run in "-angle 20 -wallFriction 12 -tol 0.01" "-angle 20 -wallFriction 25 -tol 1e-3" "-angle 28 -wallFriction 20 -tol 0.01"
    do
        rm -rf "$dir"; mkdir -p "$dir"
        cp -r "$validationDir/inclinedPlaneMuI" "$dir/"
        # shellcheck disable=SC2086
        "$dir/inclinedPlaneMuI/Allrun" $run > "$dir/log.Allrun" 2>&1 \
            || { tail -20 "$dir/log.Allrun"; return 1; }
        echo "Allrun $run:"; grep -E "slides|sticks" "$dir/log.Allrun"
    done
}

# A bed below yield (I -> 0 in the whole layer): 20 degrees < atan(mu_s)
# on a no-slip bed, 1 s from rest. The bulk's viscosity sits at the cap
# etaMax (1e3 Pa s) and the layer creeps at the Newtonian rate of that cap,
# u_s = rho g sin(theta) h^2 / (2 etaMax) = 2.52e-4 m/s (to 10 %); the
# pressure at the bed is hydrostatic to 1 %; no field holds a non-finite
# value (eta, capped by construction, is printed)
test_mui_stagnant_bed()
{
    local dir="$workRoot/muIStagnantBed"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/inclinedPlaneMuI" "$dir/"
    local case="$dir/inclinedPlaneMuI"
    "$case/Allrun" -angle 20 -wallFriction noSlip -tol 1e-3 > "$dir/log.Allrun" 2>&1 \
        || { tail -20 "$dir/log.Allrun"; return 1; }
    grep -E "sticks" "$dir/log.Allrun"
    python3 - "$case" <<'PY' || return 1
import math, sys
from sdfoam import foamcase
case = sys.argv[1]
t = foamcase.latestTime(case)
U = foamcase.readVectorField(case, t, "U")
p = foamcase.readScalarField(case, t, "p")
eta = [max(foamcase.readScalarField(case, s, "eta")) for s in foamcase.timeDirs(case)]
alpha = foamcase.readScalarField(case, t, "alpha.granular")
bulk = [i for i, a in enumerate(alpha) if a >= 0.99]
theta, rho, h, dz = math.radians(20), 1500.0, 0.01, 0.015 / 75
uCreep = rho * 9.81 * math.sin(theta) * h * h / (2 * 1e3)
uTop = max(U[i][0] for i in bulk)
pBed = rho * 9.81 * math.cos(theta) * (h - 0.5 * dz)
print("creep at the surface %.4e m/s against %.4e (Newtonian at etaMax); bed cell p %.2f Pa against %.2f hydrostatic; max eta over %d times %.6g Pa s"
      % (uTop, uCreep, p[0], pBed, len(eta), max(eta)))
ok = abs(uTop / uCreep - 1) < 0.1 and abs(p[0] / pBed - 1) < 0.01
sys.exit(0 if ok else 1)
PY
    python3 -m sdfoam.fieldStats "$case" bounds --tol 1e-8
}

# The inclined-plane mu(I) flow at 28 degrees on 2 ranks gives the serial
# steady layer: U in the bulk (alpha.granular >= 0.99) within 1e-4 of the
# surface speed, alpha.granular and n.grain within 1e-3 of 1 and 0.6 (the
# cell at the interface differs by 1e-4, with MULES's 3e-5 overshoot of 1
# above it); the air above
# is not steady and the start from rest passes through the ill-posed low-I
# range (rounding differences grow there), so the comparison is of the
# steady state
test_inclined_plane_mui_parallel()
{
    local dir="$workRoot/inclinedPlaneMuIParallel" d
    rm -rf "$dir"; mkdir -p "$dir"
    for d in serial parallel
    do
        cp -r "$validationDir/inclinedPlaneMuI" "$dir/$d"
    done
    "$dir/serial/Allrun" -angle 28 > "$dir/log.serial" 2>&1 || { tail -20 "$dir/log.serial"; return 1; }
    "$dir/parallel/Allrun" -angle 28 -parallel > "$dir/log.parallel" 2>&1 || { tail -20 "$dir/log.parallel"; return 1; }
    python3 - "$dir/serial" "$dir/parallel" <<'PY'
import sys
from sdfoam import foamcase
s, p = sys.argv[1:]
t = foamcase.latestTime(s)
if foamcase.latestTime(p) != t:
    print("latest times differ"); sys.exit(1)
alpha = foamcase.readScalarField(s, t, "alpha.granular")
bulk = [i for i, a in enumerate(alpha) if a >= 0.99]
Us, Up = foamcase.readVectorField(s, t, "U"), foamcase.readVectorField(p, t, "U")
uMax = max(abs(Us[i][0]) for i in bulk)
dU = max(max(abs(a - b) for a, b in zip(Us[i], Up[i])) for i in bulk) / uMax
worst = {"U (of the surface speed)": dU}
for f, scale in (("alpha.granular", 1.0), ("n.grain", 0.6)):
    a, b = foamcase.readScalarField(s, t, f), foamcase.readScalarField(p, t, f)
    worst[f] = max(abs(a[i] - b[i]) for i in bulk) / scale
print("serial vs 2 ranks at t = %s s over %d bulk cells: %s" % (t, len(bulk), ", ".join("%s %.2e" % kv for kv in worst.items())))
sys.exit(0 if dU < 1e-4 and worst["alpha.granular"] < 1e-3 and worst["n.grain"] < 1e-3 else 1)
PY
}

# run_case_copy CASE DIR NAME [ARGS...]: a fresh copy of validation/CASE as
# DIR/NAME, run by its Allrun with ARGS; the log is DIR/log.NAME, its tail
# printed when the Allrun fails
run_case_copy()
{
    local case="$1" dir="$2" name="$3"; shift 3
    rm -rf "${dir:?}/$name"
    cp -r "$validationDir/$case" "$dir/$name"
    "$dir/$name/Allrun" "$@" > "$dir/log.$name" 2>&1 || { tail -20 "$dir/log.$name"; return 1; }
}

# Beverloo from the rheology, small (validation/planarSiloMuI on 5 mm
# cells, bin 0.16 m wide; benchmarks/muIBeverloo has the fit on 2.5 mm
# cells): the mass flow through a 20 mm slot is constant within 2 % over
# 0.3-0.8 s (0.1 s means) at fill heights 0.34 and 0.42 m (h/W 2.1 and
# 2.6) and the same at both within 2 %; a 40 mm slot gives (b - k d)^1.5
# times as much within 5 % (k = 1.5, d = 1.2 mm; +3.9 % measured on these
# 5 mm cells; the benchmark's 2.5 mm cells meet the law's 30/20 mm ratio
# to -0.6 %)
test_mui_beverloo()
{
    local dir="$workRoot/muIBeverloo" run
    rm -rf "$dir"; mkdir -p "$dir"
    for run in "b20_h34 -b 0.02 -hFill 0.34" "b20_h42 -b 0.02 -hFill 0.42" "b40_h34 -b 0.04 -hFill 0.34"
    do
        # shellcheck disable=SC2086
        set -- $run
        local name="$1"; shift
        run_case_copy planarSiloMuI "$dir" "$name" -W 0.16 -H 0.46 -dx 5e-3 -endTime 0.8 "$@" || return 1
    done
    python3 - "$dir" <<'PY'
import math, sys
from sdfoam.beverloo import maxWindowDeviation, timeMean
work = sys.argv[1]
def rate(name):
    rows = [l.split() for l in open(work + "/" + name + "/postProcessing/outletComposition/0/outlet.dat") if not l.startswith("#")]
    ts = [(float(r[0]), float(r[2]) / 5e-3) for r in rows]
    return timeMean(ts, 0.3, 0.8), maxWindowDeviation(ts, 0.3, 0.8, 0.1)
W34, d34 = rate("b20_h34"); W42, d42 = rate("b20_h42"); W40, d40 = rate("b40_h34")
d = 1.2e-3
law = ((0.04 - 1.5 * d) / (0.02 - 1.5 * d)) ** 1.5
print("20 mm slot: W %.4f kg/s/m (fill 0.34 m, 0.1 s means within %.2e), %.4f (fill 0.42 m, within %.2e): ratio %.4f" % (W34, d34, W42, d42, W42 / W34))
print("40 mm slot: W %.4f kg/s/m (within %.2e); W40/W20 %.4f against ((b - 1.5 d) ratio)^1.5 = %.4f: %+.2e" % (W40, d40, W40 / W34, law, W40 / W34 / law - 1))
ok = max(d34, d42, d40) < 0.02 and abs(W42 / W34 - 1) < 0.02 and abs(W40 / W34 / law - 1) < 0.05
sys.exit(0 if ok else 1)
PY
}

# The orifice's empty annulus (muICoeffs emptyAnnulus yes, the outlet's
# p_rgh prghOrificeTotalPressure; validation/planarSiloMuI -emptyAnnulus on
# 5 mm cells, 0.8 s). With d = 6.667 mm the band k d/2 is 5 mm, one whole
# face at each rim: a 30 mm slot with the annulus is a 20 mm slot with
# walls beside it, so
#   - the log's open fraction of the outlet is 20/30 (to 1e-9),
#   - the two closed faces carry no flux at any written time (exactly 0),
#   - its rate (0.3-0.8 s) is the plain 20 mm slot's within 3 % (the
#     closed faces' velocity is the cells' where the floor's is zero),
#   - the solids the bin lost left through the slot (to 1e-6) and the
#     fields stay within their bounds,
#   - on 2 ranks cut at a rim (the rim edge on the processor boundary) the
#     open fraction is the same;
# and a 20 mm slot (d 1.2 mm: the band 0.9 mm inside its two rim faces)
# flows slower than without the annulus. Refused, each naming what it
# found: an open outlet condition that cannot close the rim
# (prghTotalPressure), an orifice that is a throat above the outlet
# patches, a rim on a hopper's sloping wall
test_mui_empty_annulus()
{
    local dir="$workRoot/muIEmptyAnnulus" run
    rm -rf "$dir"; mkdir -p "$dir"
    for run in "annulus30 -b 0.03 -d 6.6667e-3 -emptyAnnulus" "open20 -b 0.02 -d 6.6667e-3" "annulus20 -b 0.02 -emptyAnnulus" "plain20 -b 0.02"
    do
        # shellcheck disable=SC2086
        set -- $run
        local name="$1"; shift
        run_case_copy planarSiloMuI "$dir" "$name" -dx 5e-3 -endTime 0.8 "$@" || return 1
    done
    python3 -m sdfoam.fieldStats "$dir/annulus30" bounds --tol 1e-8 || return 1
    python3 - "$dir" <<'PY' || return 1
import re, sys
from sdfoam import foamcase
from sdfoam.beverloo import timeMean
work = sys.argv[1]
def rate(name):
    rows = [[float(v) for v in l.split()] for l in open(work + "/" + name + "/postProcessing/outletComposition/0/outlet.dat") if not l.startswith("#")]
    return timeMean([(r[0], r[2]) for r in rows], 0.3, 0.8), rows
case = work + "/annulus30"
log = open(case + "/log.segregationDegradationFoam").read()
opened = float(re.search(r"empty annulus: .* open (\S+) of the outlet", log).group(1))
# The outlet's faces on the written times: the first and last are the rims'
closedFlux = 0.0
for t in foamcase.timeDirs(case):
    text = open(case + "/" + t + "/phi").read()
    block = text[text.index("outlet"):]
    values = [float(v) for v in re.search(r"List<scalar>\s*\d+\s*\(([^)]*)\)", block).group(1).split()]
    closedFlux = max(closedFlux, abs(values[0]), abs(values[-1]))
    openFlux = min(values[1:-1])
W30, rows = rate("annulus30")
W20, _ = rate("open20")
Wa, _ = rate("annulus20")
Wp, _ = rate("plain20")
total = [float(x) for x in re.findall(r"Solids: total volume (\S+)", log)]
out = (rows[-1][-1] + rows[-1][-2]) / 2500.0
initial = total[0] + (rows[0][-1] + rows[0][-2]) / 2500.0
balance = abs((initial - total[-1]) - out) / out
print("30 mm slot with the annulus (d 6.667 mm): open %.10f of the outlet (20/30 = %.10f); closed faces' largest |phi| %.3g (the open faces' smallest %.3g)"
      % (opened, 2 / 3.0, closedFlux, openFlux))
print("rate %.6f kg/s against the 20 mm slot's %.6f: %+.2e; solids lost against out %.1e" % (W30, W20, W30 / W20 - 1, balance))
print("20 mm slot, d 1.2 mm: %.6f kg/s with the annulus, %.6f without (ratio %.4f)" % (Wa, Wp, Wa / Wp))
ok = abs(opened - 2 / 3.0) < 1e-9 and closedFlux == 0 and openFlux > 0 \
    and abs(W30 / W20 - 1) < 0.03 and balance < 1e-6 and Wa < Wp
sys.exit(0 if ok else 1)
PY
    # On 2 ranks cut at a rim (manual decomposition: the cells left of the
    # slot's left rim on rank 0), the rim edge lies on the processor
    # boundary and no wall face of rank 1 holds it: found across the ranks,
    # the open fraction is the serial run's 20/30
    run_case_copy planarSiloMuI "$dir" parallel30 -dx 5e-3 -b 0.03 -d 6.6667e-3 -emptyAnnulus -endTime 0.002 || return 1
    local par="$dir/parallel30"
    python3 - "$par" <<'PY' || return 1
import sys
from sdfoam import foamcase
case = sys.argv[1]
C = foamcase.cellCentres(case)
with open(case + "/constant/cellDecomposition", "w") as f:
    f.write('FoamFile { version 2.0; format ascii; class labelList; location "constant"; object cellDecomposition; }\n%d\n(\n' % len(C))
    f.write("".join("%d\n" % (0 if c[0] < 0.085 else 1) for c in C))
    f.write(")\n")
PY
    printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmethod manual;\ncoeffs { dataFile "cellDecomposition"; }\n' > "$par/system/decomposeParDict"
    decomposePar -case "$par" -force > "$par/log.decomposePar" 2>&1 || { tail -5 "$par/log.decomposePar"; return 1; }
    mpirun --allow-run-as-root --oversubscribe -np 2 segregationDegradationFoam -parallel -case "$par" > "$par/log.parallel" 2>&1 \
        || { tail -20 "$par/log.parallel"; return 1; }
    grep "empty annulus" "$par/log.parallel"
    grep -q "open 0.6666666667 of the outlet" "$par/log.parallel" || { echo "the open fraction on 2 ranks is not 20/30"; return 1; }

    # prghTotalPressure cannot close the rim: refused, naming the patch
    local case="$dir/annulus30"
    rm -rf "$case"/0.[0-9]* "$case"/[1-9]*
    foamDictionary -entry boundaryField.outlet.type -set prghTotalPressure "$case/0/p_rgh" > /dev/null || return 1
    mui_expect_refusal "$case" "emptyAnnulus with prghTotalPressure" "'emptyAnnulus yes': p_rgh on outlet patch outlet is prghTotalPressure, which cannot close the orifice's rim" io

    # An orifice that is a throat above the outlet patches (OpenFOAM's
    # hopper tutorial mesh: a 30 mm throat above a 300 mm skirt, one cell
    # thick, its inlet renamed the bin's open top, its front and back
    # empty): the rim the band would close is not on
    # the outlet patches, so the run is refused, naming the throat
    local tutorial="$projectDir/.cache/openfoam/tutorials/lagrangian/icoUncoupledKinematicParcelFoam/hopper/hopperEmptying"
    [ -f "$tutorial/system/blockMeshDict" ] || { echo "no OpenFOAM tutorial at $tutorial (run etc/bootstrap)"; return 1; }
    local throat="$dir/throat"
    rm -rf "$throat"; mkdir -p "$throat"
    cp -r "$case/system" "$case/constant" "$case/0.orig" "$throat/"
    rm -rf "$throat/constant/polyMesh"
    cp "$tutorial/constant/g" "$throat/constant/g"
    sed 's/\binlet\b/atmosphere/; /frontAndBack/,/faces/ s/type wall;/type empty;/' "$tutorial/system/blockMeshDict" > "$throat/system/blockMeshDict"
    blockMesh -case "$throat" > "$throat/log.blockMesh" 2>&1 || { tail -5 "$throat/log.blockMesh"; return 1; }
    cp -r "$throat/0.orig" "$throat/0"
    sed -i 's/^\( *outlet *{ *type *\)prghTotalPressure;/\1prghOrificeTotalPressure;/' "$throat/0/p_rgh"
    grep -q "outlet *{ *type *prghOrificeTotalPressure;" "$throat/0/p_rgh" || { echo "the throat case's outlet is not prghOrificeTotalPressure"; return 1; }
    mui_expect_refusal "$throat" "emptyAnnulus above a throat" "'emptyAnnulus yes': the orifice is a throat 0.03" io

    # A planar hopper's rim (validation/planarSiloFill -hopper 20: walls at
    # 70 degrees to the slot's plane): the band would be a ledge across the
    # walls' stream, so the band closure is refused, naming the wall's angle
    # (the empty annulus of a hopper is its slot meshed k d narrower;
    # benchmarks/siloFillDEM/compare --emptyAnnulus); a short fill, should
    # it run
    local hopper="$dir/hopper"
    rm -rf "$hopper"; cp -r "$projectDir/validation/planarSiloFill" "$hopper"
    if "$hopper/Allrun" -hopper 20 -emptyAnnulus -W 0.1 -H 0.22 -b 0.024 -dx 5e-3 -fill 0.01 > "$dir/log.hopper" 2>&1
    then
        echo "planarSiloFill -hopper 20 -emptyAnnulus ran"; return 1
    fi
    mui_expect_refusal "$hopper" "emptyAnnulus in a hopper" "'emptyAnnulus yes': the orifice's rim is on a wall at 70.1" io
}

# Beverloo from the rheology in the axisymmetric bin (validation/
# axisymmetricSiloMuI, 2.5 mm cells, 0.8 s): the rate constant within 2 %
# (0.1 s means over 0.3-0.8 s) for a 20 mm orifice filled to 0.17 and 0.22 m
# (h/D 2.1 and 2.75; rates within 2 %) and a 30 mm orifice; Q30/Q20 against
# ((D0 - 1.5 d) ratio)^2.5 within 5 % (+3.2 % at 1 s: benchmarks/
# muIBeverloo -axisymmetric); solids lost = solids out (orifice and top) to
# 1e-6; what leaves through the top printed (a known leak of the species
# across the interface, docs/validation.md)
test_mui_beverloo_axisymmetric()
{
    local dir="$workRoot/muIBeverlooAxisymmetric" run
    rm -rf "$dir"; mkdir -p "$dir"
    for run in "D20_h17 -D0 0.02 -H 0.3 -hFill 0.17" "D20_h22 -D0 0.02 -H 0.35 -hFill 0.22" "D30_h17 -D0 0.03 -H 0.3 -hFill 0.17"
    do
        # shellcheck disable=SC2086
        set -- $run
        local name="$1"; shift
        run_case_copy axisymmetricSiloMuI "$dir" "$name" -dx 2.5e-3 -endTime 0.8 "$@" || return 1
    done
    python3 - "$dir" <<'PY'
import math, re, sys
from sdfoam.beverloo import maxWindowDeviation, timeMean
work = sys.argv[1]
wedges = 72.0
def records(name, patch):
    return [[float(v) for v in l.split()] for l in
            open(work + "/" + name + "/postProcessing/outletComposition/0/" + patch + ".dat") if not l.startswith("#")]
ok = True
rates = {}
for name in ("D20_h17", "D20_h22", "D30_h17"):
    out, top = records(name, "outlet"), records(name, "atmosphere")
    ts = [(r[0], wedges * r[2]) for r in out]
    Q, dev = timeMean(ts, 0.3, 0.8), maxWindowDeviation(ts, 0.3, 0.8, 0.1)
    total = [float(v) for v in re.findall(r"Solids: total volume (\S+)", open(work + "/" + name + "/log.segregationDegradationFoam").read())]
    initial = total[0] + (out[0][-1] + top[0][-1]) / 2500.0
    lost, gone = initial - total[-1], (out[-1][-1] + top[-1][-1]) / 2500.0
    balance = abs(lost - gone) / lost
    rates[name] = Q
    print("%s: Q %.5f kg/s (full bin), 0.1 s means within %.2e; balance %.1e; out of the top %.1e of the orifice's"
          % (name, Q, dev, balance, top[-1][-1] / out[-1][-1]))
    ok = ok and dev < 0.02 and balance < 1e-6
law = ((0.03 - 1.5e-3) / (0.02 - 1.5e-3)) ** 2.5
ratio = rates["D30_h17"] / rates["D20_h17"]
height = rates["D20_h22"] / rates["D20_h17"]
print("fill 0.22 / 0.17 m: %.4f; Q30/Q20 %.4f against ((D0 - 1.5 d) ratio)^2.5 = %.4f: %+.2e (n at k = 1.5: %.3f)"
      % (height, ratio, law, ratio / law - 1, math.log(ratio) / math.log(28.5 / 18.5)))
ok = ok and abs(height - 1) < 0.02 and abs(ratio / law - 1) < 0.05
sys.exit(0 if ok else 1)
PY
}

# Mass flow or core flow from the rheology (validation/hopperFlowMuI, muI
# with forces cellGradient and Coulomb walls of 20 degrees, 0.5 s): a
# 20-degree cone discharges in mass flow (the wall cells move at more than
# 0.05 of the axis's speed all along the lower cone; 0.36 at 1 s in the
# study), a 50-degree one in core flow (0.0024); the fields bounded, no
# non-finite value
test_hopper_flow_pattern()
{
    local dir="$workRoot/hopperFlowPattern" theta
    rm -rf "$dir"; mkdir -p "$dir"
    for theta in 20 50
    do
        run_case_copy hopperFlowMuI "$dir" "theta$theta" -angle "$theta" -wallFriction 20 -endTime 0.5 || return 1
        grep "^hopper $theta deg" "$dir/log.theta$theta"
        python3 -m sdfoam.fieldStats "$dir/theta$theta" bounds --tol 1e-6 || return 1
    done
    grep -q "^hopper 20 deg: mass flow" "$dir/log.theta20" || { echo "20 degrees: not mass flow"; return 1; }
    grep -q "^hopper 50 deg: core flow" "$dir/log.theta50" || { echo "50 degrees: not core flow"; return 1; }
}

# The hopper (20 degrees, 0.5 s) on 2 ranks against serial: the transient
# from rest is chaotic (the adaptive steps part ways: 864 serial, 821 on 2
# ranks, and the free surface's cells differ by up to 0.2 in n), so the
# discharge is compared: the mean rate over 0.3-0.5 s within 1e-3 (5.5e-5
# measured), the discharged mass within 1e-3 (1.9e-4) and the flow
# pattern's wall/axis speed ratio within 1e-2 (5.4e-4); bounds on 2 ranks
test_hopper_parallel()
{
    local dir="$workRoot/hopperParallel" mode
    rm -rf "$dir"; mkdir -p "$dir"
    for mode in serial parallel
    do
        local opt=; [ "$mode" = parallel ] && opt=-parallel
        # shellcheck disable=SC2086
        run_case_copy hopperFlowMuI "$dir" "$mode" -angle 20 -wallFriction 20 -endTime 0.5 $opt || return 1
    done
    python3 -m sdfoam.fieldStats "$dir/parallel" bounds --tol 1e-6 || return 1
    python3 - "$dir" <<'PY'
import sys
from sdfoam.beverloo import timeMean
work = sys.argv[1]
res = {}
for mode in ("serial", "parallel"):
    rows = [[float(v) for v in l.split()] for l in
            open(work + "/" + mode + "/postProcessing/outletComposition/0/outlet.dat") if not l.startswith("#")]
    Q = timeMean([(r[0], 72 * r[2]) for r in rows], 0.3, 0.5)
    table = [l.split() for l in open(work + "/" + mode + "/results/flowPattern.dat") if not l.startswith("#")]
    ratio = min(float(r[4]) for r in table)
    res[mode] = (Q, 72 * rows[-1][-1], ratio, len(rows))
    print("%-8s Q(0.3-0.5 s) %.6f kg/s, discharged %.6e kg, wall/axis min %.4f, %d steps" % ((mode,) + res[mode]))
dQ, dM, dR = (abs(res["parallel"][k] / res["serial"][k] - 1) for k in range(3))
print("2 ranks vs serial: rate %.1e, discharged mass %.1e, wall/axis %.1e" % (dQ, dM, dR))
sys.exit(0 if dQ < 1e-3 and dM < 1e-3 and dR < 1e-2 else 1)
PY
}

# mu(I) silo extremes on the planar bin (5 mm cells, 0.5 s): an empty bin
# (nothing leaves, nothing non-finite); a bin filled to the brim (no air
# above it at the start) and the fines alone (n.coarse stays 0 exactly):
# species bounded and inside the bulk (sum = 0.6 alpha.granular, 1e-8;
# the fill's composition unchanged, 1e-6), the solids lost from the bin
# equal those through the slot and the top to 1e-9, through the top under
# 1e-5 of the slot's, from the brim too (the open top is
# prghBulkRetainingTotalPressure: closed to the bulk's outflow; with
# prghTotalPressure 5.8 % of the slot's left through the top); a slot not
# wider than k d
# (d 8 mm in I, 10 mm slot: refused naming outletPatches, nothing written)
test_mui_silo_extremes()
{
    local dir="$workRoot/muISiloExtremes" name run
    rm -rf "$dir"; mkdir -p "$dir"
    for run in "empty -hFill 0 -endTime 0.5" "brim -hFill 0.3 -endTime 0.5" "fines -coarse 0 -endTime 0.5"
    do
        # shellcheck disable=SC2086
        set -- $run
        name="$1"; shift
        run_case_copy planarSiloMuI "$dir" "$name" -dx 5e-3 "$@" || return 1
        python3 -m sdfoam.fieldStats "$dir/$name" bounds --tol 1e-8 || return 1
        if [ "$name" != empty ]
        then
            python3 -m sdfoam.fieldStats "$dir/$name" inBulk --packed 0.6 --tol 1e-8 \
                --uniform "$([ "$name" = fines ] && echo 0 || echo 0.2)" || return 1
        fi
    done
    python3 - "$dir" <<'PY' || return 1
import re, sys
from sdfoam import foamcase
work = sys.argv[1]
ok = True
def cumulative(case, patch):
    rows = [l.split() for l in open(case + "/postProcessing/outletComposition/0/" + patch + ".dat") if not l.startswith("#")]
    return [(float(r[0]), sum(float(x) for x in r[-2:]) / 2500) for r in rows]
for name in ("empty", "brim", "fines"):
    case = work + "/" + name
    log = open(case + "/log.segregationDegradationFoam").read()
    total = [float(x) for x in re.findall(r"Solids: total volume (\S+)", log)]
    out, top = cumulative(case, "outlet"), cumulative(case, "atmosphere")
    initial = total[0] + out[0][1] + top[0][1]
    lost = initial - total[-1]
    left = out[-1][1] + top[-1][1]
    coarse = max(max(foamcase.readScalarField(case, t, "n.coarse")) for t in foamcase.timeDirs(case))
    if name == "empty":
        good = total[-1] == 0 and left == 0
        print("empty bin: solids %.3e m3 at the end, %.3e m3 out" % (total[-1], left))
    else:
        imbalance = abs(lost - left) / left
        print("%s: solids lost from the bin %.6e m3 of %.4e; through the slot %.6e, through the top %.3e (%.2e of the slot's): imbalance %.2e; largest n.coarse %.3g"
              % (name, lost, initial, out[-1][1], top[-1][1], top[-1][1] / out[-1][1], imbalance, coarse))
        # Nothing may leave through the top, from the brim either
        good = out[-1][1] > 0.05 * initial and imbalance < 1e-9 and top[-1][1] < 1e-5 * out[-1][1]
        if name == "fines":
            good = good and coarse == 0
    ok = ok and good
sys.exit(0 if ok else 1)
PY
    retaining_top_worked "$dir/brim/log.segregationDegradationFoam" || return 1
    cp -r "$validationDir/planarSiloMuI" "$dir/narrow"
    if "$dir/narrow/Allrun" -dx 5e-3 -b 0.01 -W 0.16 -d 8e-3 -endTime 0.05 > "$dir/log.narrow" 2>&1
    then
        echo "a 10 mm slot with d = 8 mm was accepted"; return 1
    fi
    local expect="the orifice is 0.01 m wide (a slot), not more than k d = 1.5 x 0.008 m"
    grep -qF "$expect" "$dir/narrow/log.segregationDegradationFoam" || { echo "message lacks \"$expect\""; sed -n '/FOAM FATAL/,/FOAM exiting/p' "$dir/narrow/log.segregationDegradationFoam" | head; return 1; }
    grep -q "FOAM FATAL IO ERROR" "$dir/narrow/log.segregationDegradationFoam" || return 1
    [ -z "$(find "$dir/narrow" -mindepth 1 -maxdepth 1 -name '0.0*' | head -1)" ] || { echo "narrow: a time directory was written"; return 1; }
    echo "narrow slot refused: $(grep -m1 -oF "outletPatches 1(outlet): $expect" "$dir/narrow/log.segregationDegradationFoam")"
}

# A planar bin discharged through a slot with the mu(I) bulk flow (validation/
# planarSiloMuI, coarse mesh, 0.5 s): the solids that left the bin equal
# those through the outlet (1e-9 relative), every species within 0 <= n_i
# <= the packed fraction 0.6 (1e-8), the species' sum is 0.6 alpha.granular
# (1e-8: no species outside the bulk), the fill's composition stays uniform
# (1e-6: no segregation models), and material leaves
test_planar_silo_mui()
{
    local dir="$workRoot/planarSiloMuI"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/planarSiloMuI" "$dir/"
    local case="$dir/planarSiloMuI"
    "$case/Allrun" -dx 5e-3 -endTime 0.5 > "$dir/log.Allrun" 2>&1 || { tail -20 "$dir/log.Allrun"; return 1; }
    python3 - "$case" <<'PY' || return 1
import re, sys
case = sys.argv[1]
log = open(case + "/log.segregationDegradationFoam").read()
total = [float(x) for x in re.findall(r"Solids: total volume (\S+)", log)]
rows = [l.split() for l in open(case + "/postProcessing/outletComposition/0/outlet.dat") if not l.startswith("#")]
out = [sum(float(x) for x in r[-2:]) / 2500 for r in rows]
initial = total[0] + out[0]
lost = initial - total[-1]
print("solids lost from the bin %.6e m3, through the outlet %.6e m3: relative imbalance %.2e; mean mass flow %.4f kg/s over %s s"
      % (lost, out[-1], abs(lost - out[-1]) / out[-1], out[-1] * 2500 / float(rows[-1][0]), rows[-1][0]))
from sdfoam import foamcase
packed = max(sum(v) - 0.6 for t in foamcase.timeDirs(case, includeZero=True)
             for v in zip(foamcase.readScalarField(case, t, "n.fine"), foamcase.readScalarField(case, t, "n.coarse")))
print("largest n.fine + n.coarse - 0.6 at the written times: %.2e" % packed)
sys.exit(0 if lost > 0.1 * initial and abs(lost - out[-1]) / out[-1] < 1e-9 and packed < 1e-8 else 1)
PY
    python3 -m sdfoam.fieldStats "$case" bounds --tol 1e-8 || return 1
    python3 -m sdfoam.fieldStats "$case" inBulk --packed 0.6 --tol 1e-8 --uniform 0.2
}

# The planar bin with tutorials/silo2D's segregation mechanisms on the mu(I)
# bulk flow (Savage-Jeffrey T from its shear rate, powerLaw diffusion,
# velocityGradient kinetic sieving), coarse mesh, 0.5 s: the species stay in
# the bulk (sum = 0.6 alpha.granular, 1e-8) while they segregate (the
# coarse share of the bulk spreads by more than 0.1), nothing leaves through
# the open top, the solids that left equal those through the slot (1e-9),
# bounds (1e-8)
test_mui_silo_segregating()
{
    local dir="$workRoot/muISiloSegregating"
    rm -rf "$dir"; mkdir -p "$dir"
    run_case_copy planarSiloMuI "$dir" segregating -dx 5e-3 -endTime 0.5 -segregation || return 1
    local case="$dir/segregating"
    grep -q "Selecting kineticSieving model velocityGradient" "$case/log.segregationDegradationFoam" || { echo "kinetic sieving not selected"; return 1; }
    python3 - "$case" <<'PY' || return 1
import re, sys
from sdfoam import foamcase
case = sys.argv[1]
log = open(case + "/log.segregationDegradationFoam").read()
initial = float(re.search(r"Initial solids: total volume (\S+)", log).group(1))
total = [float(x) for x in re.findall(r"Solids: total volume (\S+)", log)]
def cumulative(patch):
    rows = [l.split() for l in open(case + "/postProcessing/outletComposition/0/" + patch + ".dat") if not l.startswith("#")]
    return sum(float(x) for x in rows[-1][-2:]) / 2500
out, top = cumulative("outlet"), cumulative("atmosphere")
imbalance = abs(initial - total[-1] - out - top) / out
t = foamcase.latestTime(case)
fine, coarse, alpha = (foamcase.readScalarField(case, t, f) for f in ("n.fine", "n.coarse", "alpha.granular"))
share = [c / (f + c) for f, c, a in zip(fine, coarse, alpha) if a > 0.5]
print("solids out through the slot %.6e m3, through the top %.3e m3; imbalance %.2e; coarse share of the bulk at %s s: %.4f to %.4f (0.2 at the start)"
      % (out, top, imbalance, t, min(share), max(share)))
sys.exit(0 if imbalance < 1e-9 and top < 1e-12 * out and max(share) - min(share) > 0.1 else 1)
PY
    python3 -m sdfoam.fieldStats "$case" bounds --tol 1e-8 || return 1
    python3 -m sdfoam.fieldStats "$case" inBulk --packed 0.6 --tol 1e-8
}

# The exact cases (the segregation-diffusion column, the Gaussian pulse) on
# 2-D distorted quadrilaterals (interior points moved by up to 20 % of the
# cell size, about 30 degrees non-orthogonal), on their polyDualMesh
# (polyhedra) and on a snappyHexMesh refinement (split hexahedra along
# staircase level transitions), with the species' gradient
# pointCellsLeastSquares, 20, 40 and 80 cells along
# (validation/unstructuredMeshes/study): second order in L1, the finest
# pair's observed order at least 1.8, and at least 1 in the max norm;
# every species within [0, the case's largest solids fraction] and their
# total below it (sdfoam.fieldStats bounds, 1e-8) at every written time
# and each species' volume kept (1e-10) on every mesh. Measured: L1
# 2.00-2.38 (1.97-2.08 between 20 and 40), max 1.26-2.12, volumes to
# 4.8e-11. 1.8 is 2 less 10 % (as validation/neddermanTuzunSlot): the
# orders scatter about 2 from pair to pair because the seeded distortion
# is not a smooth mapping of the mesh, while a first-order error, or the
# Gauss linear gradient whose non-orthogonal correction does not converge
# (the column's L1 orders -0.64, 0.49 and 1.72 on these meshes,
# docs/validation.md), falls below it. The max norm is
# held to first order only: on the distorted quadrilaterals the column's
# largest error sits in the cells at the bottom wall (max orders 1.26,
# then 1.05 between 80 and 160)
test_unstructured_meshes()
{
    local dir="$workRoot/unstructuredMeshes" case
    rm -rf "$dir"
    "$validationDir/unstructuredMeshes/study" --kinds distorted,polyDual,snappy --meshes 20,40,80 \
        --grad pointCellsLeastSquares --min-order-l1 1.8 --min-order-max 1 --work "$dir" || return 1
    for case in "$dir"/*-*-*/
    do
        python3 -m sdfoam.fieldStats "${case%/}" bounds --tol 1e-8 || return 1
    done
}
