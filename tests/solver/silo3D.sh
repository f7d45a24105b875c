# shellcheck shell=bash
# tutorials/silo3D (sourced by tests/run; tests solver/silo3D/*): the
# snappyHexMesh silo run end to end by its Allrun, serial and on 2 ranks.

# silo3D_run DIR ARGS...: a fresh copy of tutorials/silo3D run by its Allrun
silo3D_run()
{
    local dir="$1"; shift
    rm -rf "$dir"; mkdir -p "$dir"
    (cd "$projectDir/tutorials/silo3D" && cp -r 0.orig constant system Allrun Allclean \
        writeSiloSTL plotOutletComposition renderMidPlane.py muI "$dir/")
    (cd "$dir" && ./Allrun "$@" > "$dir.Allrun.log" 2>&1) || { tail -30 "$dir.Allrun.log"; return 1; }
}

# The tutorial on a coarse background mesh (h 20 mm), 4 s of discharge:
# checkMesh clean with polyhedra, the 3-D Beverloo rate by hand from the
# mesh's orifice, mass balance, bounds, pictures, and 2 ranks = serial
test_silo3D_tutorial()
{
    local parallel="$workRoot/silo3DParallel" serial="$workRoot/silo3DSerial"
    silo3D_run "$parallel" -h 0.02 -endTime 4 -writeInterval 2 || return 1
    silo3D_run "$serial" -h 0.02 -endTime 4 -writeInterval 2 -serial -noRender || return 1
    python3 "$projectDir/tests/solver/silo3D/checkTutorial.py" "$parallel" || return 1
    python3 -m sdfoam.fieldStats "$parallel" bounds --tol 1e-8 --packed 0.6 || return 1
    # 2 ranks against serial: the solves stop at 1e-12 (species, vKinematic)
    # and 1e-10 (pKinematic) each step. The species' shared TVD limiter
    # includes the total's where the total varies by more than 1e-8: that
    # switch turns the ranks' different round-off into different weights
    # on faces where the composition varies, and over 153 steps (550 at maxCo 0.5) the fields
    # differ by 5.9e-6 (measured at maxCo 2; 4.2e-6 at 0.5; 3e-8 with the species' limiters alone,
    # which let the total rise 1e-4 above packing), so 1e-5 (on n up to 0.6)
    python3 -m sdfoam.fieldStats "$parallel" compare "$serial" --tol 1e-5
}

# The tutorial on the coarse mesh (h 20 mm) for 20 s, serial: every species
# within [0, its total] and the total at most the packed fraction 0.6
# (1e-8) while the composition varies (kinetic sieving on, vanLeer01 on
# snapped cells). Measured: at most 0.6 + 6.1e-10; with limiters of the
# species alone and each species' own cell-limited gradient in the
# diffusion's correction the total reached 0.6 + 1.1e-4 by 20 s (2e-7 at
# 12 s)
test_silo3D_packing_bound()
{
    local dir="$workRoot/silo3DPackingBound"
    silo3D_run "$dir" -h 0.02 -endTime 20 -writeInterval 2 -serial -noRender || return 1
    python3 -m sdfoam.fieldStats "$dir" bounds --tol 1e-8 --packed 0.6
}

# The tutorial with the mu(I) bulk flow (Allrun -muI) on the coarse mesh
# (h 20 mm) filled to the brim, 0.1 s on 2 ranks: every species within
# [0, its total], the total at most 0.6 (1e-8) and equal to 0.6
# alpha.granular (1e-8); the solids lost from the silo equal those through
# the orifice and the top (1e-9 of the outflow), and through the top less
# than 1e-5 of the orifice's (the open top closed to the bulk's outflow:
# prghBulkRetainingTotalPressure)
test_silo3D_muI()
{
    local dir="$workRoot/silo3DMuI"
    silo3D_run "$dir" -muI -hFill 1 -h 0.02 -endTime 0.1 -writeInterval 0.05 -noRender || return 1
    python3 -m sdfoam.fieldStats "$dir" bounds --tol 1e-8 --packed 0.6 || return 1
    python3 -m sdfoam.fieldStats "$dir" inBulk --packed 0.6 --tol 1e-8 || return 1
    python3 - "$dir" <<'PY'
import re, sys
case = sys.argv[1]
total = [float(x) for x in re.findall(r"Solids: total volume (\S+)", open(case + "/log.segregationDegradationFoam").read())]
def cumulative(patch):
    rows = [l.split() for l in open(case + "/postProcessing/outletComposition/0/" + patch + ".dat") if not l.startswith("#")]
    return [sum(float(x) for x in r[-2:]) / 2500 for r in rows]
out, top = cumulative("outlet"), cumulative("top")
initial = total[0] + out[0] + top[0]
lost, left = initial - total[-1], out[-1] + top[-1]
imbalance = abs(lost - left) / left
print("silo3D muI from the brim, 2 ranks: solids lost %.6e m3 of %.4e; through the orifice %.6e, through the top %.3e (%.2e of the orifice's); imbalance %.2e"
      % (lost, initial, out[-1], top[-1], top[-1] / out[-1], imbalance))
sys.exit(0 if out[-1] > 1e-4 * initial and imbalance < 1e-9 and top[-1] < 1e-5 * out[-1] else 1)
PY
    retaining_top_worked "$dir/log.segregationDegradationFoam"
}


# The tutorial's fill stage on the coarse mesh (h 20 mm), 2 ranks (Allrun
# -fill 0.4 -endTime 0.2): the inlet carved from the snapped top, the fill
# and the discharge; per species the silo at the end = what entered - what
# left, over both stages (tests/solver/silo/checkFill.py: 1e-8 of the fed,
# the solids' 1e-10; 2.1e-12 and 1.3e-12 measured), nothing through the
# closed inlet, something discharged, bounds and the total 0.6
# alpha.granular (1e-8)
test_silo3D_fill()
{
    local tree="$workRoot/silo3DFill"
    rm -rf "$tree"; mkdir -p "$tree"
    cp -r "$projectDir/tutorials/silo3D" "$projectDir/tutorials/resources" "$tree/"
    local dir="$tree/silo3D"
    (cd "$dir" && ./Allrun -fill 0.4 -endTime 0.2 -writeInterval 0.1 -h 0.02 -noRender > ../log.Allrun 2>&1) \
        || { tail -30 "$dir/../log.Allrun"; return 1; }
    python3 "$projectDir/tests/solver/silo/checkFill.py" "$dir" || return 1
    python3 -m sdfoam.fieldStats "$dir" bounds --tol 1e-8 --packed 0.6 || return 1
    python3 -m sdfoam.fieldStats "$dir" inBulk --packed 0.6 --tol 1e-8
}

# The tutorial's fill deposited where it lands (Allrun -flat -fill 2 -feed
# 0.25 -deposition, the calibrated rheology shipped, 20 mm mesh, serial;
# the tutorial's own 2 ranks close the same balance):
# per species the silo at the end = what was deposited - what left, over
# both stages (checkFill.py, the deposition's record as what entered: 1e-8,
# the solids' 1e-10), bounds and the total at the packed fraction (1e-8),
# and the heap (./heapProfile): its apex in the ring under the inlet, its
# flank rising towards it within 3 degrees of both angles of a DEM heap of
# the grains the shipped rheology was calibrated for
# (benchmarks/angleOfRepose/results.txt: while its pour lasts, and 0.5 s
# after it); the jet's crater slopes the other way, and a flank at
# atan(mu_s) lies more than 3 degrees below the first
test_silo3D_fill_deposition()
{
    local tree="$workRoot/silo3DFillDeposition"
    rm -rf "$tree"; mkdir -p "$tree"
    cp -r "$projectDir/tutorials/silo3D" "$projectDir/tutorials/resources" "$tree/"
    local dir="$tree/silo3D" packed
    (cd "$dir" && ./Allrun -serial -flat -fill 2 -feed 0.25 -deposition -rheology shipped \
        -endTime 0.25 -writeInterval 0.25 -h 0.02 -noRender > ../log.Allrun 2>&1) \
        || { tail -30 "$dir/../log.Allrun"; return 1; }
    python3 "$projectDir/tests/solver/silo/checkFill.py" "$dir" || return 1
    packed=$(foamDictionary -entry rheology.packedFraction -value "$dir/constant/granularCoefficients") || return 1
    python3 -m sdfoam.fieldStats "$dir" bounds --tol 1e-8 --packed "$packed" || return 1
    python3 -m sdfoam.fieldStats "$dir" inBulk --packed "$packed" --tol 1e-8 || return 1
    cat "$dir/log.heapProfile"
    grep -q "(height [0-9.]* m); the inlet's radius 0.0400 m: under the inlet" "$dir/log.heapProfile" \
        || { echo "FAIL: the apex is not under the inlet"; return 1; }
    local results="$projectDir/benchmarks/angleOfRepose/results.txt" poured settled
    read -r poured settled < <(awk '/^# mean over / { for (i = 1; i < NF; ++i) {
            if ($i == "end:") p = $(i + 1); if ($i == "settled:") s = $(i + 1) } }
        END { print p, s }' "$results")
    [ -n "$poured" ] && [ -n "$settled" ] \
        || { echo "FAIL: no DEM heap angles in $results"; return 1; }
    awk -v p="$poured" -v s="$settled" '/flank angle/ { for (i = 1; i <= NF; ++i) if ($i == "angle") a = $(i + 1) }
         END { print "flank angle " a " deg; the DEM heap under its pour " p " deg (difference " a - p \
                     "), 0.5 s after it " s " deg (difference " a - s ")"
               exit !(a != "" && a - p >= -3 && a - p <= 3 && a - s >= -3 && a - s <= 3) }' "$dir/log.heapProfile" \
        || { echo "FAIL: the heap's flank is not within 3 degrees of the DEM heap's angles"; return 1; }
}
