# shellcheck shell=bash
# The solver's extremes matrix (sourced by tests/run; tests solver/extremes/*): the
# closed box of tests/solver/closedBox (cyclic in x, walls at the base and the lid,
# 16 x 24 cells, shear flow, diffusion, kinetic sieving and percolation on) pushed to one
# extreme at a time. Every case runs and is
#   bounded       0 <= n_i, sum_j n_j <= P (fieldStats) at every written time (tolerance 1e-8), no
#                 non-finite value in any written field (sdfoam.fieldStats bounds),
#   conservative  the closed box's solids volume (each species' without breakage) equal
#                 to its initial value to 1e-10 relative over every step (the solver's
#                 "Solids:" lines, 15 digits),
# (closed_box_run and closed_box_check of tests/solver/closedBox.sh) and, where an
# exact or reference value exists, meets it (per case below). The
# matrix with the observed values is the extremes table of docs/validation.md; the
# DEM's extremes are calibration/tests/test_extremes.cpp.

# extreme_case DIR FINE COARSE: a fresh closed box in DIR whose mixed layer (0 < z <
# 0.8) holds n.fine = FINE and n.coarse = COARSE (the shear flow's faster upper half
# as in closedBox), end time 0.5 s
extreme_case()
{
    local dir="$1" fine="$2" coarse="$3"
    rm -rf "$dir"; cp -r tests/solver/closedBox "$dir"
    foamDictionary -entry endTime -set 0.5 "$dir/system/controlDict" > /dev/null
    foamDictionary -entry writeInterval -set 0.25 "$dir/system/controlDict" > /dev/null
    cat > "$dir/system/setFieldsDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setFieldsDict; }
defaultFieldValues ( volScalarFieldValue n.fine 0 volScalarFieldValue n.coarse 0 volVectorFieldValue U (0.5 0 0) );
regions
(
    boxToCell { box (-1 -1 0) (2 2 0.8); fieldValues ( volScalarFieldValue n.fine $fine volScalarFieldValue n.coarse $coarse ); }
    boxToCell { box (-1 -1 0.5) (2 2 2); fieldValues ( volVectorFieldValue U (1 0 0) ); }
);
DICT
}

# add_species DIR NAME D VALUE: one more species of diameter D, VALUE in the mixed layer
add_species()
{
    local dir="$1" name="$2" d="$3" value="$4"
    sed "s/object n.fine;/object n.$name;/" "$dir/0.orig/n.fine" > "$dir/0.orig/n.$name"
    foamDictionary -entry "species/$name" -set "{ d $d; rho 2500; }" \
        "$dir/constant/granularProperties" > /dev/null
    sed -i "s|volScalarFieldValue n.fine 0 |&volScalarFieldValue n.$name 0 |; \
            s|fieldValues ( volScalarFieldValue n.fine \([^ ]*\) |&volScalarFieldValue n.$name $value |" \
        "$dir/system/setFieldsDict"
}

# fixed_step DIR DT: adjustTimeStep off at deltaT DT
fixed_step()
{
    foamDictionary -entry adjustTimeStep -set no "$1/system/controlDict" > /dev/null
    foamDictionary -entry deltaT -set "$2" "$1/system/controlDict" > /dev/null
}

# no_diffusion_case DIR CO: the closed box without diffusion at a fixed step of Courant
# number CO of the fastest cell (deltaT = CO/16 s), 25 s, written at 12.5 and 25 s
no_diffusion_case()
{
    local dir="$1" co="$2"
    extreme_case "$dir" 0.3 0.3
    foamDictionary -entry diffusivity -set "{ model none; }" "$dir/constant/granularProperties" > /dev/null
    fixed_step "$dir" "$(python3 -c "print($2/16)")"
    foamDictionary -entry endTime -set 25 "$dir/system/controlDict" > /dev/null
    foamDictionary -entry writeInterval -set 12.5 "$dir/system/controlDict" > /dev/null
}

# no_diffusion_segregated: the closed box's check (closed_box_check's PYTHON) that the
# layer ended fully segregated: the fines' centre of mass within 1e-3 m of 0.1985 m
no_diffusion_segregated()
{
    cat <<'PY'
from sdfoam import foamcase
t = foamcase.latestTime(case)
fine = foamcase.readScalarField(case, t, "n.fine")
z = [(k // 16 + 0.5) / 24 for k in range(len(fine))]   # blockMesh order: x fastest
layerRows = 19                                           # cell centres below z = 0.8
exact = (0.6 * sum(j + 0.5 for j in range(9)) + 0.3 * 9.5) / (0.6 * layerRows / 2) / 24
zc = sum(f * h for f, h in zip(fine, z)) / sum(fine)
print("fines centre of mass at t = %s: %.4f m, fully segregated %.4f m (tolerance 1e-3 m)" % (t, zc, exact))
ok &= abs(zc - exact) <= 1e-3
PY
}

# test_extreme KIND: one row of the matrix
test_extreme()
{
    local kind="$1" dir="$workRoot/extremes-$1"
    local gp="$dir/constant/granularProperties" conserved=perSpecies own="" bounds=1e-8
    case "$kind" in
        noDiffusionCo1|noDiffusionCo5)
            # Pe -> infinity: no diffusion, a fixed step at Courant number 1 or 5 of the
            # fastest cell (|U| = 1 m/s, dx = 1/16 m; the segregation fluxes then run at
            # up to that Courant number too), 25 s: long past the layer's segregation
            # time. Exact end state without diffusion: fully segregated, the fines' 9.5
            # rows (of the layer's 19 at n = 0.6) at the base, their centre of mass at
            # z = 0.1985 m, within 1e-3 m
            local co="${kind#noDiffusionCo}"
            no_diffusion_case "$dir" "$co"
            own="$(no_diffusion_segregated)"
            ;;
        noDiffusionCo50)
            # Courant 50, where the explicit segregation exchange cannot follow: its
            # positivity limiter cuts a cell's outflow to its content, so a composition
            # front moves at most one cell per step. Adjustable step (maxCo 50): the
            # segregation Courant number sets the step (maxSegregationCo 0.5 on every
            # step, the bulk Courant number below 50) and the layer ends fully
            # segregated as at Courant 1 (0.1985 m within 1e-3 m). Fixed step at
            # Courant 50 (segregation Courant number 46), 8 steps: the solver warns
            # once, naming maxSegregationCo, adjustTimeStep and deltaT, and lags by
            # exactly one row per step: after s steps the s lowest rows are pure fines
            # (0.6), the s highest of the layer pure coarse, the 19 - 2 s between
            # still mixed 0.3/0.3 (s = 8: centre of mass 0.2029 m; full segregation
            # needs s = 9): every cell of n.fine within 1e-10 of that
            no_diffusion_case "$dir-adaptive" 50
            foamDictionary -entry adjustTimeStep -set yes "$dir-adaptive/system/controlDict" > /dev/null
            foamDictionary -entry maxCo -set 50 "$dir-adaptive/system/controlDict" > /dev/null
            closed_box_run "$dir-adaptive" || return 1
            closed_box_check "$dir-adaptive" perSpecies "$(no_diffusion_segregated)"'
import re
# Each step prints its Courant numbers at the previous step (the first: the
# controlDict deltaT, 3.125 s), then the step it sets: those of the step taken
# are the printed ones times new/previous step
log = open(case + "/log.solver").read()
printed = [tuple(map(float, m)) for m in re.findall(r"Courant Number max: (\S+)  segregation Courant Number max: (\S+)", log)]
dt = [float(v) for v in re.findall(r"^deltaT = (\S+)", log, re.M)]
co = [(c * new / old, s * new / old) for (c, s), new, old in zip(printed, dt, [3.125] + dt)]
print("adjustable step, maxCo 50: %d steps, largest bulk Courant number %.4g, largest segregation Courant number %.12g (maxSegregationCo 0.5)"
      % (len(co), max(c for c, s in co), max(s for c, s in co)))
ok &= len(co) == len(dt) == len(rows) - 1 and max(s for c, s in co) <= 0.5 * (1 + 1e-9) and max(c for c, s in co) <= 50' || return 1
            no_diffusion_case "$dir" 50
            own='
import re
from sdfoam import foamcase
log = open(case + "/log.solver").read()
warnings = re.findall(r"segregation Courant number \S+ exceeds maxSegregationCo 0.5 with adjustTimeStep off \(deltaT 3.125 in \S*controlDict\"?\)", log)
print("fixed step at Courant 50: the warning %d time(s): %s" % (len(warnings), warnings[:1]))
ok &= len(warnings) == 1 and log.count("said once") == 1
steps = len(rows) - 1                                    # rows: the Initial line, then every step
fine = foamcase.readScalarField(case, foamcase.latestTime(case), "n.fine")
def lagged(row):
    if row >= 19:
        return 0.0
    return 0.6 if row < steps else 0.0 if row >= 19 - steps else 0.3
worst = max(abs(f - lagged(k // 16)) for k, f in enumerate(fine))
z = [(k // 16 + 0.5) / 24 for k in range(len(fine))]
print("after %d steps: n.fine against one row per step from each end: max difference %.2e; centre of mass %.5f m"
      % (steps, worst, sum(f * h for f, h in zip(fine, z)) / sum(fine)))
ok &= steps == 8 and worst <= 1e-10'
            ;;
        dilute)
            # phi -> 0: 1e-12 solids in the layer. The diffusivity vanishes with the
            # presence min(1, phi/phiMin); the drift velocities (grayThornton,
            # velocityGradient) do not depend on phi, so the equations are linear in n:
            # reference, the dense layer (0.3 + 0.3) without diffusion, scaled by
            # 5e-13/0.3, within 1e-8 of the dense values
            extreme_case "$dir" 5e-13 5e-13
            bounds=5e-21
            extreme_case "$dir-reference" 0.3 0.3
            foamDictionary -entry diffusivity -set "{ model none; }" \
                "$dir-reference/constant/granularProperties" > /dev/null
            closed_box_run "$dir-reference" || return 1
            own='
from sdfoam import foamcase
t = foamcase.latestTime(case)
worst = 0.0
for name in ("n.fine", "n.coarse"):
    a = foamcase.readScalarField(case, t, name)
    b = foamcase.readScalarField(case + "-reference", t, name)
    worst = max(worst, max(abs(x / 5e-13 - y / 0.3) for x, y in zip(a, b)))
print("dilute / 5e-13 against dense without diffusion / 0.3 at t = %s: max difference %.2e" % (t, worst))
ok &= worst <= 1e-8'
            ;;
        packed|overPacked)
            # phi at random close packing (0.64) and above it (0.70)
            local half=0.32; [ "$kind" = overPacked ] && half=0.35
            extreme_case "$dir" "$half" "$half" ;;
        fewFines|fewCoarse)
            # x -> 0 and x -> 1: one species at 1e-9 of the other
            if [ "$kind" = fewFines ]
            then
                extreme_case "$dir" 6e-10 0.6
            else
                extreme_case "$dir" 0.6 6e-10
            fi
            bounds=6e-18 ;;
        absentSpecies)
            # a species absent everywhere: it stays exactly 0, the other is conserved
            extreme_case "$dir" 0.6 0
            own='
c = [r["n.coarse"] for r in rows]
print("absent n.coarse: largest volume over the run %g" % max(c))
ok &= max(c) == 0.0' ;;
        sizeRatio4|sizeRatio10)
            # coarse 4 and 10 times the fines, with the size-dependent percolation of
            # Schlick et al. (2015), S = C_s d_s ln(d_l/d_s), alone (no sieving, no
            # diffusion; it acts where the flow shears, about z = 0.5), 0.05 s. Reference:
            # the same case at ratio 2; early, the fines' centre of mass moves by
            # S dt times the same sum, so the shifts are in the ratio ln(r)/ln(2), within 2 %
            local ratio="${kind#sizeRatio}" d
            for d in "$dir" "$dir-reference"
            do
                extreme_case "$d" 0.3 0.3
                fixed_step "$d" 1e-3
                foamDictionary -entry endTime -set 0.05 "$d/system/controlDict" > /dev/null
                foamDictionary -entry writeInterval -set 0.025 "$d/system/controlDict" > /dev/null
                foamDictionary -entry diffusivity -set "{ model none; }" "$d/constant/granularProperties" > /dev/null
                foamDictionary -entry kineticSieving -set "{ model none; }" "$d/constant/granularProperties" > /dev/null
                foamDictionary -entry percolation -set "{ model shearRate; shearRateCoeffs { C_s 0.26; } }" \
                    "$d/constant/granularProperties" > /dev/null
            done
            foamDictionary -entry species/coarse/d -set "${ratio}e-3" "$gp" > /dev/null
            closed_box_run "$dir-reference" || return 1
            own='
import math
from sdfoam import foamcase
def shift(c):
    t = foamcase.latestTime(c)
    a0, a = (foamcase.readScalarField(c, s, "n.fine") for s in ("0", t))
    z = [(k // 16 + 0.5) / 24 for k in range(len(a))]
    return sum(x * h for x, h in zip(a0, z)) / sum(a0) - sum(x * h for x, h in zip(a, z)) / sum(a)
r = shift(case) / shift(case + "-reference")
expected = math.log('"$ratio"') / math.log(2)
print("fines centre of mass moved %.4e m, at ratio 2 %.4e m: ratio %.4f, ln(r)/ln(2) = %.4f" % (shift(case), shift(case + "-reference"), r, expected))
ok &= abs(r / expected - 1) <= 0.02'
            ;;
        threeSpecies|fourSpecies)
            extreme_case "$dir" 0.2 0.2
            add_species "$dir" medium 1.5e-3 0.2
            if [ "$kind" = fourSpecies ]
            then
                add_species "$dir" large 3e-3 0.1
            fi ;;
        breakageStiff)
            # breakage rate x dt = 1e6: the coarse species breaks into fines within the
            # first step; implicit in the sink, coarse falls by 1/(1 + S dt) per step
            # (plus what transport moves), the solids' total is kept
            extreme_case "$dir" 0.3 0.3
            fixed_step "$dir" 1e-3
            foamDictionary -entry endTime -set 0.02 "$dir/system/controlDict" > /dev/null
            foamDictionary -entry writeInterval -set 0.01 "$dir/system/controlDict" > /dev/null
            foamDictionary -entry breakage -remove "$gp" > /dev/null
            echo "breakage { model constant; constantCoeffs { S { coarse 1e9; } } daughterSizeDistribution { model table; tableCoeffs { coarse { fine 1; } } } }" >> "$gp"
            conserved=totalOnly
            own='
c0, c1 = rows[0]["n.coarse"], rows[1]["n.coarse"]
print("breakage S dt = 1e6: coarse after the first step %.3e of its initial volume (1/(1 + S dt) = %.3e)" % (c1 / c0, 1 / (1 + 1e6)))
ok &= c1 / c0 <= 1.5e-6 and abs(rows[-1]["n.fine"] - rows[0]["total"]) <= 1e-10 * rows[0]["total"]' ;;
        *)
            echo "test_extreme: unknown kind $kind"; return 1 ;;
    esac
    closed_box_run "$dir" || return 1
    closed_box_check "$dir" "$conserved" "$own" "$bounds"
}
