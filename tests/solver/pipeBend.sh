# shellcheck shell=bash
# The pipe bend (sourced by tests/run; tests solver/pipeBend/*): the
# particle pass of OpenFOAM's kinematic cloud with the particlePass cloud
# function object, on a short snappyHexMesh bend of tutorials/pipeBend.

# mesh_short_bend DIR RD: the tutorial's bend (R/D = RD) with legs of 1 D
# upstream and 2 D downstream, background cubes D/10, wall refined once
mesh_short_bend()
{
    local dir="$1" RD="$2"
    mkdir -p "$dir/constant/triSurface"
    cp "$projectDir/tutorials/pipeBend/system/"{blockMeshDict,snappyHexMeshDict,surfaceFeatureExtractDict,meshParameters} "$dir/system/"
    (cd "$dir" && python3 "$projectDir/tutorials/pipeBend/writeBendSTL" -RD "$RD" -upstream 1 -downstream 2 > log.writeBendSTL) || return 1
    blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || return 1
    surfaceFeatureExtract -case "$dir" > "$dir/log.surfaceFeatureExtract" 2>&1 || return 1
    snappyHexMesh -case "$dir" -overwrite > "$dir/log.snappyHexMesh" 2>&1 || { tail -20 "$dir/log.snappyHexMesh"; return 1; }
    checkMesh -case "$dir" > "$dir/log.checkMesh" 2>&1 || { tail -20 "$dir/log.checkMesh"; return 1; }
    grep -q "Mesh OK" "$dir/log.checkMesh" || { tail -20 "$dir/log.checkMesh"; return 1; }
}

# Ballistic limit: no gas, no gravity, drag negligible; 1800 parcels fired
# along the axis from equal-area rings of the inlet section half a diameter
# upstream of the bend. Their first impacts on the snapped R/D = 3 wall
# against the straight-line geometry (sdfoam.bendBallistic): mean impact
# angle 23.2 +- 1 deg, mean normal/total speed 0.387 +- 0.01, the
# centreline parcel at bend angle 31.0 deg, none beyond 44.4 deg; every
# parcel hits the outer wall once before the first impact list closes
test_pipe_bend_ballistic()
{
    local dir="$workRoot/pipeBendBallistic"
    rm -rf "$dir"
    cp -r "$projectDir/tests/solver/pipeBend/ballistic" "$dir"
    mesh_short_bend "$dir" 3 || return 1
    python3 - "$dir" <<'PY'
import sys
from sdfoam.bendBallistic import diskPoints
D = 0.05
with open(sys.argv[1] + "/constant/kinematicCloudPositions", "w") as f:
    f.write("FoamFile { version 2.0; format ascii; class vectorField; object kinematicCloudPositions; }\n(\n")
    # (y0, z0) of the section; the centreline parcel first (origId 0)
    for y, z in [(0.0, 0.0)] + diskPoints(30, 60, D):
        f.write("(%.9g %.9g %.9g)\n" % (-0.5 * D, y, z))
    f.write(")\n")
PY
    icoUncoupledKinematicParcelFoam -case "$dir" > "$dir/log.pass" 2>&1 || { tail -30 "$dir/log.pass"; return 1; }
    python3 - "$dir" <<'PY'
import glob, math, sys
from sdfoam.bendBallistic import diskPoints, statistics
case = sys.argv[1]
D, RD = 0.05, 3.0
R = RD * D
path = glob.glob(case + "/postProcessing/lagrangian/kinematicCloud/particlePass/*/firstImpacts.d1mm")[0]
rows = [list(map(float, l.split())) for l in open(path) if not l.startswith("#")]
points = diskPoints(30, 60, D)
byId = {int(r[6]): r for r in rows}
angles, ratios, bends = [], [], []
for r in rows:
    x, y, z, un, ut = r[:5]
    angles.append(math.degrees(math.atan2(un, ut)))
    ratios.append(un / math.hypot(un, ut))
    bends.append(math.degrees(math.atan2(x, R - y)))
mean = sum(angles[1:]) / len(angles[1:]) if 0 in byId else None
# the disk sample without the centreline parcel (origId 0)
disk = [r for i, r in byId.items() if i != 0]
meanAngle = sum(math.degrees(math.atan2(r[3], r[4])) for r in disk) / len(disk)
meanRatio = sum(r[3] / math.hypot(r[3], r[4]) for r in disk) / len(disk)
maxBend = max(math.degrees(math.atan2(r[0], R - r[1])) for r in disk)
c = byId[0]
centreBend = math.degrees(math.atan2(c[0], R - c[1]))
exact = statistics(RD, points, D)
print("first impacts %d of %d parcels; mean angle %.3f deg (exact %.3f, continuum 23.224);"
      " mean Un/U %.4f (exact %.4f); max bend angle %.2f deg (exact %.2f);"
      " centreline at %.2f deg (exact 31.00)"
      % (len(rows), len(points) + 1, meanAngle, exact[0], meanRatio, exact[1],
         maxBend, exact[2], centreBend))
ok = len(disk) == len(points)
ok = ok and abs(meanAngle - 23.2) <= 1 and abs(meanRatio - 0.387) <= 0.01
ok = ok and abs(centreBend - 31.0) <= 0.5 and maxBend <= 44.4 + 0.5
sys.exit(0 if ok else 1)
PY
}

# The chain on the short bend, no gas solve (the pass in still air: parcels
# fired at 20 m/s, gravity on), the classes carried with their own fluxes
# and broken at the wall (impactEnergy total): solids in = out + held up +
# dust to 1e-9 of the inflow (the 10 digits of outlet.dat), every class non-negative, the finer classes
# and dust gained what the parent lost, 2 MPI ranks = serial
test_pipe_bend_mass_balance()
{
    local dir="$workRoot/pipeBendMassBalance" tut="$projectDir/tutorials/pipeBend"
    rm -rf "$dir"
    mkdir -p "$dir/pass" "$dir/case"
    cp -r "$tut/system" "$tut/constant" "$tut/0.orig" "$dir/case/"
    mesh_short_bend "$dir/case" 3 || return 1
    echo "impactEnergy total;" > "$dir/case/constant/bendParameters"
    # The pass: the tutorial's stage with the ballistic test's still air
    cp -r "$tut/particlePass/system" "$tut/particlePass/constant" "$dir/pass/"
    cp -r "$dir/case/constant/polyMesh" "$dir/case/constant/granularProperties" \
        "$dir/case/constant/bendParameters" "$dir/pass/constant/"
    mkdir -p "$dir/pass/0"
    cp "$projectDir/tests/solver/pipeBend/ballistic/0/U" "$dir/pass/0/U"
    : > "$dir/pass/constant/injectionModels"
    for c in d2mm:2e-3 d1mm:1e-3 d500um:5e-4 d250um:2.5e-4
    do
        cat >> "$dir/pass/constant/injectionModels" <<INJ
${c%%:*} { type patchInjection; patch inlet; SOI 0; duration 1; parcelsPerSecond \$parcelsPerSecond;
  U0 (\$Uin 0 0); flowRateProfile constant 1; massTotal 0; parcelBasisType fixed; nParticle 1;
  sizeDistribution { type fixedValue; fixedValueDistribution { value ${c#*:}; } } }
INJ
    done
    foamDictionary -entry endTime -set 0.03 "$dir/pass/system/controlDict" > /dev/null
    foamDictionary -entry writeInterval -set 0.03 "$dir/pass/system/controlDict" > /dev/null
    foamDictionary -entry recordFrom -set 0.01 "$dir/pass/constant/passParameters" > /dev/null
    foamDictionary -entry parcelsPerSecond -set 20000 "$dir/pass/constant/passParameters" > /dev/null
    icoUncoupledKinematicParcelFoam -case "$dir/pass" > "$dir/log.pass" 2>&1 || { tail -30 "$dir/log.pass"; return 1; }
    # The solver's case
    cp -r "$dir/case/0.orig" "$dir/case/0"
    cp "$dir/pass/0.03"/alphaPass.* "$dir/pass/0.03"/UPass.* "$dir/pass/0.03"/phiPass.* "$dir/case/0/"
    mkdir -p "$dir/case/constant/particlePass"
    cp "$dir/pass/postProcessing/lagrangian/kinematicCloud/particlePass/0.03"/impacts.* "$dir/case/constant/particlePass/"
    foamDictionary -entry endTime -set 0.04 "$dir/case/system/controlDict" > /dev/null
    foamDictionary -entry writeInterval -set 0.02 "$dir/case/system/controlDict" > /dev/null
    cp -r "$dir/case" "$dir/parallel"
    segregationDegradationFoam -case "$dir/case" > "$dir/log.solver" 2>&1 || { tail -30 "$dir/log.solver"; return 1; }
    printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmethod simple;\nsimpleCoeffs { n (2 1 1); delta 0.001; }\n' > "$dir/parallel/system/decomposeParDict"
    decomposePar -case "$dir/parallel" > "$dir/log.decomposePar" 2>&1 || { tail -20 "$dir/log.decomposePar"; return 1; }
    mpirun -np 2 segregationDegradationFoam -parallel -case "$dir/parallel" > "$dir/log.parallel" 2>&1 || { tail -30 "$dir/log.parallel"; return 1; }
    python3 -m sdfoam.fieldStats "$dir/case" bounds --tol 1e-12 || return 1
    python3 - "$dir" <<'PY'
import re, sys
d = sys.argv[1]
def balance(log, base):
    text = open(log).read()
    initial = float(re.search(r"Initial solids: total volume (\S+)", text).group(1))
    last = re.findall(r"^Solids: total volume (\S+)\s+dust volume (\S+)(.*)$", text, re.M)[-1]
    total, dust = float(last[0]), float(last[1])
    vols = dict(re.findall(r"n\.(\S+) volume (\S+)", last[2]))
    def cum(patch):
        rows = [l for l in open(base + patch + ".dat") if not l.startswith("#")]
        hdr = [l for l in open(base + patch + ".dat") if l.startswith("# time")][0][1:].split()
        row = dict(zip(hdr, map(float, rows[-1].split())))
        return sum(v for k, v in row.items() if k.startswith("cumulativeMass.")) / 1590.0
    inflow, outflow = -cum("inlet"), cum("outlet")
    return initial, total, dust, vols, inflow, outflow
i, t, dust, vols, qin, qout = balance(d + "/log.solver", d + "/case/postProcessing/outletComposition/0/")
err = abs(i + qin - qout - t - dust) / qin
fines = sum(float(v) for k, v in vols.items() if k != "d2mm")
p = re.findall(r"^Solids: total volume (\S+)\s+dust volume (\S+)(.*)$", open(d + "/log.parallel").read(), re.M)[-1]
parDiff = max(abs(float(p[0]) - t) / t, abs(float(p[1]) - dust) / max(dust, 1e-300))
print("in %.6e out %.6e held %.6e dust %.6e: balance %.2e of the inflow; finer classes held %.3e (%.3e of the held solids); 2 ranks vs serial: %.2e"
      % (qin, qout, t, dust, err, fines, fines / t, parDiff))
# 1e-9: the cumulative masses are read from outlet.dat, written with 10
# significant digits (measured 1.6e-10)
sys.exit(0 if err < 1e-9 and fines > 0 and dust >= 0 and parDiff < 1e-8 else 1)
PY
}
