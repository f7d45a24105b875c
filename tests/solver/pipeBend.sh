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
