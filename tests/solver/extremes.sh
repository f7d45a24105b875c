# shellcheck shell=bash
# The solver's extremes matrix (sourced by tests/run; tests solver/extremes/*): the
# closed box of tests/solver/closedBox (cyclic in x, walls at the base and the lid,
# 16 x 24 cells, shear flow, diffusion, kinetic sieving and percolation on) pushed to one
# extreme at a time. Every case runs and is
#   bounded       0 <= n_i <= sum_j n_j at every written time (tolerance 1e-8), no
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

# test_extreme KIND: one row of the matrix
test_extreme()
{
    local kind="$1" dir="$workRoot/extremes-$1"
    local gp="$dir/constant/granularProperties" conserved=perSpecies own="" bounds=1e-8
    case "$kind" in
        noDiffusionCo1|noDiffusionCo5|noDiffusionCo50)
            # Pe -> infinity: no diffusion, a fixed step at Courant number 1, 5, 50 of the
            # fastest cell (|U| = 1 m/s, dx = 1/16 m; the segregation fluxes then run at
            # up to that Courant number too), 25 s: long past the layer's segregation
            # time. Exact end state without diffusion: fully segregated, the fines' 9.5
            # rows (of the layer's 19 at n = 0.6) at the base, their centre of mass at
            # z = 0.1985 m: within 1e-3 m at Courant 1 and 5. At 50 the explicit, limited
            # exchange stalls with three rows mixed 0.3/0.3 at the interface (0.2029 m):
            # held to that, within 5e-3 m, so that a worse stall fails
            local co="${kind#noDiffusionCo}" tolerance=1e-3
            [ "$co" = 50 ] && tolerance=5e-3
            extreme_case "$dir" 0.3 0.3
            foamDictionary -entry diffusivity -set "{ model none; }" "$gp" > /dev/null
            fixed_step "$dir" "$(python3 -c "print($co/16)")"
            foamDictionary -entry endTime -set 25 "$dir/system/controlDict" > /dev/null
            foamDictionary -entry writeInterval -set 12.5 "$dir/system/controlDict" > /dev/null
            own='
from sdfoam import foamcase
t = foamcase.latestTime(case)
fine = foamcase.readScalarField(case, t, "n.fine")
z = [(k // 16 + 0.5) / 24 for k in range(len(fine))]   # blockMesh order: x fastest
layerRows = 19                                           # cell centres below z = 0.8
exact = (0.6 * sum(j + 0.5 for j in range(9)) + 0.3 * 9.5) / (0.6 * layerRows / 2) / 24
zc = sum(f * h for f, h in zip(fine, z)) / sum(fine)
print("fines centre of mass at t = %s: %.4f m, fully segregated %.4f m (tolerance %g m)"
      % (t, zc, exact, '"$tolerance"'))
ok &= abs(zc - exact) <= '"$tolerance"''
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
