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
    (cd "$dir" && "$projectDir/tutorials/pipeBend/meshBend" -RD "$RD" -upstream 1 -downstream 2) || return 1
}

# Ballistic limit: no gas, no gravity, drag negligible; 1800 parcels fired
# along the axis from equal-area rings of the inlet section half a diameter
# upstream of the bend. Their first impacts on the snapped R/D = 3 wall
# against the exact ones of the same points on the torus
# (sdfoam.bendBallistic): mean impact angle, mean normal/total speed, the
# centreline parcel's bend angle and the last first impact, each within
# what the snapped wall's facets allow (below); every parcel hits the
# outer wall once before the first impact list closes
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
# the disk sample without the centreline parcel (origId 0)
disk = [r for i, r in byId.items() if i != 0]
meanAngle = sum(math.degrees(math.atan2(r[3], r[4])) for r in disk) / len(disk)
meanRatio = sum(r[3] / math.hypot(r[3], r[4]) for r in disk) / len(disk)
maxBend = max(math.degrees(math.atan2(r[0], R - r[1])) for r in disk)
c = byId[0]
centreBend = math.degrees(math.atan2(c[0], R - c[1]))
exact = statistics(RD, points, D)
print("first impacts %d of %d parcels" % (len(rows), len(points) + 1))
# The tolerances come from the snapped wall. Its faces (edges h = 2.5 mm:
# background cubes D/10, the wall refined once) are chords between
# vertices on the STL, whose facets (128 around, 1 degree along the bend)
# are chords of the torus. So
# - the wall lies inside the torus by at most the chords' sag, h^2/(8a)
#   across the pipe and h^2/(8(R + a)) along the bend, plus the STL's own
#   sag: a parcel meets it early, and its bend angle is that of the
#   exact wall moved in by this gap g (the exact statistics computed for
#   the diameter D - 2g) within |that - exact|;
# - a face's normal is tilted from the torus normal where a parcel meets
#   it by up to delta = h/(2a) across and h/(2(R + a)) along, varying
#   linearly across the face. Over 1800 hits spread across the faces the
#   first-order part cancels in the mean; what stays is second order, at
#   most the mean square tilt delta^2/3 rad in the mean impact angle and
#   as much in the mean Un/U (d sin = cos d), plus the gap's shift.
a, h = D / 2, D / 20
g = (h * h / (8 * a) + h * h / (8 * (R + a))
     + a * (1 - math.cos(math.pi / 128)) + (R + a) * (1 - math.cos(math.radians(0.5))))
moved = statistics(R / (D - 2 * g), points, D - 2 * g)
tilt2 = ((h / (2 * a)) ** 2 + (h / (2 * (R + a))) ** 2) / 3
tolAngle = math.degrees(tilt2) + abs(moved[0] - exact[0])
tolRatio = tilt2 + abs(moved[1] - exact[1])
tolMax = abs(moved[2] - exact[2])
tolCentre = abs(moved[3] - exact[3])
checks = [("mean impact angle [deg]", meanAngle, exact[0], tolAngle),
          ("mean Un/U", meanRatio, exact[1], tolRatio),
          ("last first impact, bend angle [deg]", maxBend, exact[2], tolMax),
          ("centreline parcel, bend angle [deg]", centreBend, exact[3], tolCentre)]
print("gap g = %.2e m, mean square tilt %.2e rad^2" % (g, tilt2))
ok = len(disk) == len(points)
for name, got, want, tol in checks:
    print("%-38s measured %.5f exact %.5f difference %+.2e tolerance %.2e"
          % (name, got, want, got - want, tol))
    ok = ok and abs(got - want) <= tol
sys.exit(0 if ok else 1)
PY
}

# bend_chain_mesh CASE: the short R/D 3 bend's mesh in CASE/constant,
# built once per test run
bend_chain_mesh()
{
    local mesh="$workRoot/pipeBendShortMesh" tut="$projectDir/tutorials/pipeBend"
    # The marker holds the PID of this tests/run: a mesh from an earlier
    # run, or one whose meshing failed, is built again
    if [ "$(cat "$mesh/meshOK" 2>/dev/null)" != "$$" ]
    then
        rm -rf "$mesh"
        mkdir -p "$mesh"
        cp -r "$tut/system" "$tut/constant" "$mesh/"
        mesh_short_bend "$mesh" 3 || return 1
        echo "$$" > "$mesh/meshOK"
    fi
    mkdir -p "$1/constant"
    cp -r "$mesh/constant/polyMesh" "$1/constant/"
}

# bend_gas DIR: the gas of the short bend (the tutorial's simpleFoam stage,
# 20 m/s, at most 150 iterations; built once per test run) as the pass's
# DIR/pass/0/U, and its face flux as DIR/phiGas
bend_gas()
{
    local gas="$workRoot/pipeBendShortGas" tut="$projectDir/tutorials/pipeBend" gasTime
    if [ "$(cat "$gas/gasOK" 2>/dev/null)" != "$$" ]
    then
        rm -rf "$gas"
        mkdir -p "$gas"
        bend_chain_mesh "$gas" || return 1
        cp -r "$tut/gas/system" "$tut/gas/constant" "$gas/"
        cp -r "$tut/gas/0.orig" "$gas/0"
        printf 'Uin 20;\nkIn 1.5;\nomegaIn 1000;\n' > "$gas/system/gasInlet"
        foamDictionary -entry writeFormat -set ascii "$gas/system/controlDict" > /dev/null
        foamDictionary -entry endTime -set 150 "$gas/system/controlDict" > /dev/null
        foamDictionary -entry writeInterval -set 150 "$gas/system/controlDict" > /dev/null
        simpleFoam -case "$gas" > "$gas/log.simpleFoam" 2>&1 || { tail -20 "$gas/log.simpleFoam"; return 1; }
        echo "$$" > "$gas/gasOK"
    fi
    gasTime=$(foamListTimes -case "$gas" -latestTime | tail -n 1)
    mkdir -p "$1/pass/0"
    cp "$gas/$gasTime/U" "$1/pass/0/U"
    sed 's/^\( *object *\)phi;/\1phiGas;/' "$gas/$gasTime/phi" > "$1/phiGas"
}

# bend_chain DIR UIN E [CLASSES...]: the chain on the short R/D 3 bend in
# DIR: the case (the tutorial's, impactEnergy total) in DIR/case, the pass
# (the tutorial's stage, parcels fired at UIN m/s with wall restitution E,
# gravity on) in DIR/pass with the gas velocity DIR/pass/0/U if the caller
# wrote one (else still air), ready for the solver (bend_solve). The feed
# and the pass's product come from the tutorial's writeFeed: DIR/feed and
# DIR/granularProperties, if the caller wrote them, replace the tutorial's
# system/feed and constant/granularProperties; DIR/kinematicCloudProperties
# replaces the pass's. The pass injects the feed's classes (writeFeed's
# injectors, number rates in the feed's proportions) or, if CLASSES are
# given, those classes at one particle per parcel each (a controlled pass:
# equal number rates whatever the feed). The walls rebound
# (standardWallInteraction) unless the caller sets
# bendWall=breakingRebound (and bendFragments=sampled|expected).
# The mesh is built once per test run and copied.
bend_chain()
{
    local dir="$1" Uin="$2" e="$3" tut="$projectDir/tutorials/pipeBend" c d
    shift 3
    mkdir -p "$dir/pass" "$dir/case"
    cp -r "$tut/system" "$tut/constant" "$dir/case/"
    # A test's own species (and models) and feed instead of the tutorial's
    [ -f "$dir/granularProperties" ] && cp "$dir/granularProperties" "$dir/case/constant/"
    [ -f "$dir/feed" ] && cp "$dir/feed" "$dir/case/system/"
    # The wall's restitution (wallContact's e; edited as text, not with
    # foamDictionary -set, which would drop the #includeIfPresent of
    # bendParameters, absent yet)
    python3 - "$dir/case/constant/granularProperties" "$e" <<'PY'
import re, sys
path, e = sys.argv[1], sys.argv[2]
text = open(path).read()
open(path, "w").write(re.sub(r"(wallContact\s*\{[^}]*?\be\s+)[^;]*;", r"\g<1>%s;" % e, text, count=1))
PY
    [ "$(foamDictionary -entry wallContact/e -value "$dir/case/constant/granularProperties")" = "$e" ] \
        || { echo "bend_chain: wallContact/e not set to $e"; return 1; }
    bend_chain_mesh "$dir/case" || return 1
    echo "impactEnergy total;" > "$dir/case/constant/bendParameters"
    cp -r "$tut/particlePass/system" "$tut/particlePass/constant" "$dir/pass/"
    [ -f "$dir/kinematicCloudProperties" ] && cp "$dir/kinematicCloudProperties" "$dir/pass/constant/"
    cp -r "$dir/case/constant/polyMesh" "$dir/case/constant/granularProperties" \
        "$dir/case/constant/bendParameters" "$dir/pass/constant/"
    cp "$dir/case/system/feed" "$dir/pass/system/"
    mkdir -p "$dir/pass/0"
    [ -f "$dir/pass/0/U" ] || cp "$projectDir/tests/solver/pipeBend/ballistic/0/U" "$dir/pass/0/U"
    # The case's 0/n.<class> and the pass's 0/n.<class> (breakingRebound
    # builds the case's mixture from them), product and injectors
    "$tut/writeFeed" -case "$dir/case" -pass "$dir/pass" > "$dir/log.writeFeed" 2>&1 \
        || { cat "$dir/log.writeFeed"; return 1; }
    if [ "$#" -gt 0 ]
    then
        : > "$dir/pass/constant/injectionModels"
        for c in "$@"
        do
            d=$(foamDictionary -entry "species/$c/d" -value "$dir/case/constant/granularProperties") || return 1
            cat >> "$dir/pass/constant/injectionModels" <<INJ
$c { type patchInjection; patch inlet; SOI 0; duration 1; parcelsPerSecond \$parcelsPerSecond;
  U0 (\$Uin 0 0); flowRateProfile constant 1; massTotal 0; parcelBasisType fixed; nParticle 1;
  sizeDistribution { type fixedValue; fixedValueDistribution { value $d; } } }
INJ
        done
    fi
    # Recording from 0.025 s (bendRecordFrom), when the first particles
    # (20 m/s) have crossed the 0.39 m bend, to 0.05 s (bendPassEnd): the
    # pass is steady, so its crossings balance
    local passEnd="${bendPassEnd:-0.05}" recordFrom="${bendRecordFrom:-0.025}"
    foamDictionary -entry endTime -set "$passEnd" "$dir/pass/system/controlDict" > /dev/null
    foamDictionary -entry writeInterval -set "$passEnd" "$dir/pass/system/controlDict" > /dev/null
    foamDictionary -entry recordFrom -set "$recordFrom" "$dir/pass/constant/passParameters" > /dev/null
    foamDictionary -entry parcelsPerSecond -set 20000 "$dir/pass/constant/passParameters" > /dev/null
    foamDictionary -entry Uin -set "$Uin" "$dir/pass/constant/passParameters" > /dev/null
    foamDictionary -entry wallInteraction -set "${bendWall:-standardWallInteraction}" "$dir/pass/constant/passParameters" > /dev/null
    foamDictionary -entry fragments -set "${bendFragments:-sampled}" "$dir/pass/constant/passParameters" > /dev/null
    icoUncoupledKinematicParcelFoam -case "$dir/pass" > "$dir/log.pass" 2>&1 || { tail -30 "$dir/log.pass"; return 1; }
    # The solver's case
    cp "$dir/pass/$passEnd"/alphaPass.* "$dir/pass/$passEnd"/UPass.* "$dir/pass/$passEnd"/phiPass.* "$dir/case/0/"
    mkdir -p "$dir/case/constant/particlePass"
    cp "$dir/pass/postProcessing/lagrangian/kinematicCloud/particlePass/$passEnd"/impacts.* "$dir/case/constant/particlePass/"
    foamDictionary -entry endTime -set 0.04 "$dir/case/system/controlDict" > /dev/null
    foamDictionary -entry writeInterval -set 0.02 "$dir/case/system/controlDict" > /dev/null
}

# bend_solve DIR: segregationDegradationFoam on DIR/case (serial), then its
# fields bounded (no NaN, no negative class, the solids volume fraction
# at most 0.64, random close packing) and its solids balance:
# in = out + held up + dust to 1e-10 of the inflow. Prints the balance; FINES (exported) = the finer classes'
# held volume over the held solids
bend_solve()
{
    local dir="$1"
    segregationDegradationFoam -case "$dir/case" > "$dir/log.solver" 2>&1 || { tail -30 "$dir/log.solver"; return 1; }
    bend_solve_checks "$dir"
}

# bend_solve_checks DIR: the checks of bend_solve on a finished run
bend_solve_checks()
{
    local dir="$1"
    python3 -m sdfoam.fieldStats "$dir/case" bounds --tol 1e-12 || return 1
    python3 "$projectDir/tests/solver/pipeBend/balance.py" "$dir/log.solver" \
        "$dir/case/postProcessing/outletComposition/0/" "$dir/case/constant/granularProperties" \
        > "$dir/balance.txt" || { cat "$dir/balance.txt"; return 1; }
    python3 - "$dir/case" <<'PY' || return 1
import sys
from sdfoam import fieldStats, foamcase
case = sys.argv[1]
worst = 0.0
for t in foamcase.timeDirs(case):
    fields = [foamcase.readScalarField(case, t, n) for n in fieldStats.species(case, t)]
    worst = max([worst] + [sum(v) for v in zip(*fields)])
print("largest solids volume fraction %.3e (random close packing 0.64)" % worst)
sys.exit(0 if worst <= 0.64 else 1)
PY
    cat "$dir/balance.txt"
}

# The chain on the short bend in its 20 m/s gas (bend_gas; parcels fired
# at 20 m/s, gravity on), the classes carried with their own fluxes
# and broken at the wall (impactEnergy total): solids in = out + held up +
# dust to 1e-10 of the inflow, every class non-negative, the finer classes
# gained what the parent lost, 2 MPI ranks = serial
test_pipe_bend_mass_balance()
{
    local dir="$workRoot/pipeBendMassBalance"
    rm -rf "$dir"
    bend_gas "$dir" || return 1
    bend_chain "$dir" 20 0.8 d2mm d1mm d500um d250um || return 1
    cp -r "$dir/case" "$dir/parallel"
    bend_solve "$dir" || return 1
    grep -q "finer classes held 0.000e+00" "$dir/balance.txt" && { echo "no fines gained"; return 1; }
    printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmethod simple;\nsimpleCoeffs { n (2 1 1); delta 0.001; }\n' > "$dir/parallel/system/decomposeParDict"
    decomposePar -case "$dir/parallel" > "$dir/log.decomposePar" 2>&1 || { tail -20 "$dir/log.decomposePar"; return 1; }
    mpirun -np 2 segregationDegradationFoam -parallel -case "$dir/parallel" > "$dir/log.parallel" 2>&1 || { tail -30 "$dir/log.parallel"; return 1; }
    python3 - "$dir" <<'PY'
import re, sys
d = sys.argv[1]
line = r"^Solids: total volume (\S+)\s+dust volume (\S+)"
s = re.findall(line, open(d + "/log.solver").read(), re.M)[-1]
p = re.findall(line, open(d + "/log.parallel").read(), re.M)[-1]
diff = max(abs(float(p[0]) - float(s[0])) / float(s[0]),
           abs(float(p[1]) - float(s[1])) / max(float(s[1]), 1e-300))
print("2 ranks vs serial: held solids and dust to %.2e" % diff)
sys.exit(0 if diff < 1e-8 else 1)
PY
}

# The fragment pass on the short bend in its 20 m/s gas (bend_gas):
# d2mm fed at 20 m/s, walls breakingRebound with fragments expected
# (impactEnergy total): every impact splits the parcel into the expected
# shares of the classes, so the finer classes are born at the wall.
#   - the pass keeps volume: the fragments born plus dust equal the volume
#     broken out of the classes, to 1e-10 (the log's counters, 12 digits)
#   - `fragments expectation` (neither choice): FatalIOError naming the
#     entry and the valid choices, no time written
#   - the pass is steady: the fragments leaving equal those born less
#     those broken, to 5 % (outflow.dat against the counters)
#   - the continuum on this pass (bend_solve: bounded, balanced to 1e-10)
#     breaks and carries the classes as the pass does: per fed volume,
#     the parent broken out and each finer class gained at its outlet at
#     steady state equal the pass's counters to 2 % (the pass-on balance,
#     upwind transport of the pass's hold-up)
test_pipe_bend_fragment_pass()
{
    local dir="$workRoot/pipeBendFragmentPass"
    rm -rf "$dir"
    bend_gas "$dir" || return 1
    # The fragments, born at the bend and rebounding slower, need longer
    # than the parent to cross: the pass records once they leave steadily
    bendWall=breakingRebound bendFragments=expected bendRecordFrom=0.045 bendPassEnd=0.07 \
        bend_chain "$dir" 20 0.8 d2mm || return 1
    python3 - "$dir" <<'PY' || return 1
import re, sys
d = sys.argv[1]
log = open(d + "/log.pass").read()
m = re.findall(r"breakingRebound \(fragments expected\) from t = \S+ s over (\S+) s:[^\n]*\n((?:\s+\S+ \S+ \S+ \S+ \S+\n)+)\s+dust volume \[m3\] (\S+)", log)[-1]
T = float(m[0])
rows = {l.split()[0]: list(map(float, l.split()[1:])) for l in m[1].strip().splitlines()}
# The pass keeps volume: fragments born + dust = volume broken out
broken = sum(r[2] for r in rows.values())
born = sum(r[3] for r in rows.values())
dust = float(m[2])
error = abs(born + dust - broken) / broken
print("pass: broken %.6e m3, fragments born %.6e m3, dust %.3e m3: %.2e" % (broken, born, dust, error))
# The pass is steady: what leaves of each finer class equals what was born
# less what broke out of it, within 5 % (the parents of the two are
# injected at random points, 400 in the window)
out = d + "/pass/postProcessing/lagrangian/kinematicCloud/particlePass/0.07/outflow.dat"
names = [l for l in open(out) if l.startswith("# patch")][0].split()[2:]
left = dict(zip(names, map(float, [l.split() for l in open(out) if l.startswith("outlet")][0][1:])))
worst = 0.0
for c in names[1:]:
    expected = (rows[c][3] - rows[c][2]) / T
    worst = max(worst, abs(left[c] / expected - 1))
    print("pass %s: leaves %.4e m3/s, born less broken %.4e m3/s" % (c, left[c], expected))
sys.exit(0 if broken > 0 and error < 1e-10 and worst < 0.05 else 1)
PY
    # A fragments entry that is neither sampled nor expected: FatalIOError
    # naming the entry and the valid choices, before any step
    mkdir -p "$dir/badFragments"
    cp -r "$dir/pass/0" "$dir/pass/constant" "$dir/pass/system" "$dir/badFragments/"
    foamDictionary -entry fragments -set expectation "$dir/badFragments/constant/passParameters" > /dev/null
    if icoUncoupledKinematicParcelFoam -case "$dir/badFragments" > "$dir/log.badFragments" 2>&1
    then
        echo "fragments expectation: accepted"; return 1
    fi
    grep -q "'fragments expectation' in .*valid choices are sampled .* and expected" "$dir/log.badFragments" \
        || { tail -20 "$dir/log.badFragments"; echo "fragments expectation: no clear message"; return 1; }
    [ -z "$(foamListTimes -case "$dir/badFragments" 2>/dev/null)" ] || { echo "fragments expectation: a time was written"; return 1; }
    grep -m1 "'fragments expectation'" "$dir/log.badFragments"
    foamDictionary -entry endTime -set 0.06 "$dir/case/system/controlDict" > /dev/null
    bend_solve "$dir" || return 1
    python3 - "$dir" <<'PY'
import math, re, sys
from sdfoam.outletComposition import lastRow
d = sys.argv[1]
# Per fed volume: what the pass broke out of each class (and, fragments,
# what it gained: born less broken, over the window) against what the
# continuum's outlet gains or loses at steady state (outletComposition)
log = open(d + "/log.pass").read()
m = re.findall(r"breakingRebound \(fragments expected\) from t = \S+ s over (\S+) s:[^\n]*\n((?:\s+\S+ \S+ \S+ \S+ \S+\n)+)", log)[-1]
T = float(m[0])
rows = {l.split()[0]: list(map(float, l.split()[1:])) for l in m[1].strip().splitlines()}
fedPass = 20000 * math.pi / 6 * 0.002 ** 3


inlet, outlet = lastRow(d + "/case", "inlet"), lastRow(d + "/case", "outlet")
fed = -inlet["massFlow.d2mm[kg/s]"]
worst = 0.0
for c in rows:
    if c == "d2mm":
        passGain = -rows[c][2] / T / fedPass
        contGain = (outlet["massFlow.d2mm[kg/s]"] - fed) / fed
    else:
        passGain = (rows[c][3] - rows[c][2]) / T / fedPass
        contGain = outlet["massFlow.%s[kg/s]" % c] / fed
    worst = max(worst, abs(contGain / passGain - 1))
    print("%s gained per fed volume: continuum %.5e, pass %.5e" % (c, contGain, passGain))
print("largest relative difference %.4f (tolerance 0.02)" % worst)
sys.exit(0 if worst < 0.02 and rows["d250um"][3] > 0 else 1)
PY
}

# Extremes on the short bend (impactEnergy total): every variant but e = 0
# runs the chain to the end with bounded fields and the solids balance
#   zeroVelocity   parcels released at rest in still air: they fall onto
#                  the pipe floor far below the breakage threshold, so
#                  nothing breaks (S = 0 for every class, no fines, no dust)
#   restitution1   e = 1 in the 20 m/s gas: bounded, balanced, fines
#   restitution0   e = 0: the solver must stop, with its message, before
#                  the solids exceed a full cell (below)
#   emptyClass     d500um never injected: alphaPass.d500um = 0 everywhere,
#                  its flux is the gas's; it gains only fragments
test_pipe_bend_extremes()
{
    local root="$workRoot/pipeBendExtremes" dir
    rm -rf "$root"
    dir="$root/zeroVelocity"
    bend_chain "$dir" 0 0.8 d2mm d1mm d500um d250um || return 1
    bend_solve "$dir" || return 1
    [ "$(grep -c "broken volume rate 0 m3/s" "$dir/log.solver")" = 4 ] || { grep "broken volume rate" "$dir/log.solver"; echo "zeroVelocity: something breaks"; return 1; }
    # ... although the particles do hit the wall (they fall onto the floor)
    grep -q "broken volume rate 0 m3/s .*(0 impact records)" "$dir/log.solver" && { echo "zeroVelocity: a class without wall impacts"; return 1; }
    grep -q "finer classes held 0.000e+00" "$dir/balance.txt" || { echo "zeroVelocity: fines gained"; return 1; }
    # e = 1: the chain runs, bounded and balanced
    dir="$root/restitution1"
    bend_gas "$dir" || return 1
    bend_chain "$dir" 20 1 d2mm d1mm d500um d250um || return 1
    bend_solve "$dir" || return 1
    grep -q "finer classes held 0.000e+00" "$dir/balance.txt" && { echo "restitution 1: no fines gained"; return 1; }
    # e = 0: the pass's particles slide to rest on the pipe floor and stay
    # there (alphaPass 6 at the pass's own rate). Their classes' fluxes
    # converge into those cells and nothing leaves them, so n grows there
    # without bound: no steady state exists, and particlePass has no
    # packing to stop at. The solver must refuse as soon as a cell holds
    # more solids than space (granularMixture::checkFinite): exit status
    # non-zero, the message naming the fraction, the cause and the time,
    # that time not written, and every time written before finite and
    # within [0, 1]
    dir="$root/restitution0"
    bend_gas "$dir" || return 1
    bend_chain "$dir" 20 0 d2mm d1mm d500um d250um || return 1
    if segregationDegradationFoam -case "$dir/case" > "$dir/log.solver" 2>&1
    then
        tail -5 "$dir/log.solver"
        echo "restitution 0: the solver ran to the end with the solids piling up in the pass's resting cells"
        return 1
    fi
    local stop
    stop=$(sed -nE 's/.*Solids volume fraction ([0-9.e+-]+) > 1 after the species solve, time ([0-9.e+-]+): the bulk flow piles the species up.*/\1 \2/p' "$dir/log.solver" | head -1)
    [ -n "$stop" ] && grep -q "bulkFlow particlePass" "$dir/log.solver" \
        && grep -q "Stopping before this time is written" "$dir/log.solver" \
        || { tail -20 "$dir/log.solver"; echo "restitution 0: stopped without the message naming the solids volume fraction and particlePass"; return 1; }
    echo "restitution 0: stopped at solids volume fraction ${stop% *} > 1, time ${stop#* }"
    [ ! -d "$dir/case/${stop#* }" ] || { echo "restitution 0: time ${stop#* } written"; return 1; }
    python3 -m sdfoam.fieldStats "$dir/case" bounds --tol 1e-12 || return 1
    dir="$root/emptyClass"
    bend_gas "$dir" || return 1
    bend_chain "$dir" 20 0.8 d2mm d1mm d250um || return 1
    python3 -c "
import sys
from sdfoam.foamcase import readScalarField
a = readScalarField('$dir/pass', '0.05', 'alphaPass.d500um')
sys.exit(0 if max(a) == 0 else 1)" || { echo "emptyClass: alphaPass.d500um is not 0"; return 1; }
    bend_solve "$dir" || return 1
    grep "^Solids:" "$dir/log.solver" | tail -1 | grep -q "n.d500um volume 0 " \
        && { echo "emptyClass: d500um gained no fragments"; return 1; }
    return 0
}

# Tiny particles in the gas of the short bend (the tutorial's simpleFoam
# stage, 20 m/s, at most 150 iterations):
# 5 um grains (Stokes number 0.07 at the largest gas speed) follow the gas:
# fewer than 10 % of them touch the wall, at under 1 % of the gas speed
# (the few that reach the wall creep along it), and their mean velocity
# within 15 % of the gas's and under a third of the 2 mm class's slip
# (residence-weighted over the visited cells without a wall face).
# The solver may then move them with the gas flux (particlePassCoeffs
# gasVelocity (d5um)): it runs, bounded and balanced; asking the same for
# the 2 mm class (Stokes number about 10,000 with Stokes drag) is refused
# with a FatalIOError naming gasVelocity and stokesLimit, as are a class
# that is not a species and a missing pipeDiameter; nothing is written
test_pipe_bend_tiny_particles()
{
    local dir="$workRoot/pipeBendTiny" tut="$projectDir/tutorials/pipeBend"
    rm -rf "$dir"
    mkdir -p "$dir/pass/0"
    sed -e '/d1mm\|d500um\|d250um/d' -e 's/^\( *\)d2mm .*/&\n\1d5um    { d 5e-6;   rho 1590; }/' \
        "$tut/constant/granularProperties" > "$dir/granularProperties"
    # The continuum's feed: both classes (the pass below fires them at
    # equal number rates all the same)
    printf 'loading 1;\ngasDensity 1.2;\nmassFractions { d2mm 0.88; d5um 0.12; }\n' > "$dir/feed"
    bend_gas "$dir" || return 1
    bend_chain "$dir" 20 0.8 d5um d2mm || return 1
    python3 - "$dir" <<'PY' || return 1
import glob, math, re, sys
from sdfoam.foamcase import readScalarField, readVectorField, _body, _readLabelList
d = sys.argv[1]
out = glob.glob(d + "/pass/postProcessing/lagrangian/kinematicCloud/particlePass/0.05/summary.dat")[0]
rows = {l.split()[0]: l.split() for l in open(out) if not l.startswith("#")}
# The fed particles that touched the wall at all, and how hard
fed = 20000 * 0.025
touched = float(rows["d5um"][9]) / fed
speed = float(rows["d5um"][5])
alpha = readScalarField(d + "/pass", "0.05", "alphaPass.d5um")
gas = readVectorField(d + "/pass", "0", "U")
# Cells without a wall face: in the wall cells the particles see the
# cellPoint-interpolated gas, which falls linearly to 0 at the wall points
# (U = 0 there), not the cell value of the wall-function gas
boundary = _body(d + "/pass/constant/polyMesh/boundary")
wall = re.search(r"\bwall\s*\{[^}]*nFaces\s+(\d+);[^}]*startFace\s+(\d+);", boundary)
n, start = int(wall.group(1)), int(wall.group(2))
wallCells = set(_readLabelList(d + "/pass/constant/polyMesh/owner")[start:start + n])
def slip(name):
    alpha = readScalarField(d + "/pass", "0.05", "alphaPass." + name)
    U = readVectorField(d + "/pass", "0.05", "UPass." + name)
    cells = [i for i, a in enumerate(alpha) if a > 0 and i not in wallCells]
    return (sum(alpha[i] * math.dist(U[i], gas[i]) for i in cells)
            / sum(alpha[i] * math.hypot(*gas[i]) for i in cells))
tiny, large = slip("d5um"), slip("d2mm")
print("d5um: %.3f of the fed particles touch the wall, at %.2e m/s on average;"
      " mean |U_p - U_gas|/|U_gas| %.4f (cells without a wall face); d2mm: %.2f"
      " touch it, at %.1f m/s, slip %.4f" % (touched, speed, tiny,
      float(rows["d2mm"][9]) / fed, float(rows["d2mm"][5]), large))
# 0.15 and a third of the 2 mm class's slip (measured 0.095 against 0.30):
# the 5 um grains' response time is half a cell's transit time, so they
# lag the cell-to-cell changes, and cells touching the wall at a point or
# an edge still see some of the wall's U = 0
sys.exit(0 if touched < 0.1 and speed < 0.2 and tiny < 0.15 and tiny < large / 3 else 1)
PY
    # The solver, d5um with the gas flux
    cp "$dir/phiGas" "$dir/case/0/phiGas"
    cp -r "$dir/case" "$dir/refused"
    foamDictionary -entry bulkFlow/particlePassCoeffs -add "{ gasVelocity (d5um); gasViscosity 1.8e-5; pipeDiameter 0.05; }" \
        "$dir/case/constant/granularProperties" > /dev/null
    bend_solve "$dir" || return 1
    grep -q "d5um moves with the gas" "$dir/log.solver" || { echo "d5um does not move with the gas"; return 1; }
    foamDictionary -entry bulkFlow/particlePassCoeffs -add "{ gasVelocity (d2mm); gasViscosity 1.8e-5; pipeDiameter 0.05; }" \
        "$dir/refused/constant/granularProperties" > /dev/null
    if segregationDegradationFoam -case "$dir/refused" > "$dir/log.refused" 2>&1
    then
        echo "gasVelocity (d2mm) was accepted"; return 1
    fi
    grep -q "gasVelocity d2mm: Stokes number" "$dir/log.refused" && grep -q "stokesLimit" "$dir/log.refused" \
        || { tail -20 "$dir/log.refused"; return 1; }
    [ -z "$(foamListTimes -case "$dir/refused" 2>/dev/null)" ] || { echo "refused run wrote a time directory"; return 1; }
    grep -m1 "Stokes number" "$dir/log.refused"
    # A class that is not a species, and a missing pipeDiameter
    foamDictionary -entry bulkFlow/particlePassCoeffs -set "{ gasVelocity (d7um); gasViscosity 1.8e-5; pipeDiameter 0.05; }" \
        "$dir/refused/constant/granularProperties" > /dev/null
    segregationDegradationFoam -case "$dir/refused" > "$dir/log.unknown" 2>&1 && { echo "gasVelocity (d7um) accepted"; return 1; }
    grep -q "gasVelocity names d7um, which is not a species" "$dir/log.unknown" || { tail -20 "$dir/log.unknown"; return 1; }
    foamDictionary -entry bulkFlow/particlePassCoeffs -set "{ gasVelocity (d5um); gasViscosity 1.8e-5; }" \
        "$dir/refused/constant/granularProperties" > /dev/null
    segregationDegradationFoam -case "$dir/refused" > "$dir/log.missing" 2>&1 && { echo "missing pipeDiameter accepted"; return 1; }
    grep -q "pipeDiameter" "$dir/log.missing" || { tail -20 "$dir/log.missing"; return 1; }
    [ -z "$(foamListTimes -case "$dir/refused" 2>/dev/null)" ] || { echo "refused run wrote a time directory"; return 1; }
}

# A fed size distribution through the short bend in its 20 m/s gas
# (bend_gas; walls breakingRebound with fragments expected, impactEnergy
# total): the pass injects the feed's classes through the tutorial's
# writeFeed (number rates in the feed's proportions). Particles of the pass
# do not collide, so the pass, and the continuum on it, are linear in the
# feed: each class's gain at the outlet per fed mass for 60 % d2mm + 40 %
# d1mm by mass equals 0.6 times that of d2mm fed alone plus 0.4 times that
# of d1mm fed alone, within the passes' own noise: 4 standard errors of the
# difference, each pass's error from batch means of its breakage counters
# over 10 windows (the fragments born less the volume broken, per class).
# Each run bounded and balanced (bend_solve)
test_pipe_bend_fed_distribution()
{
    local root="$workRoot/pipeBendFedDistribution" run
    rm -rf "$root"
    for run in mix:"d2mm 0.6; d1mm 0.4;" d2mm:"d2mm 1;" d1mm:"d1mm 1;"
    do
        local dir="$root/${run%%:*}"
        mkdir -p "$dir"
        printf 'loading 1;\ngasDensity 1.2;\nmassFractions { %s }\n' "${run#*:}" > "$dir/feed"
        bend_gas "$dir" || return 1
        bendWall=breakingRebound bendFragments=expected bendRecordFrom=0.045 bendPassEnd=0.07 \
            bend_chain "$dir" 20 0.8 || return 1
        foamDictionary -entry endTime -set 0.06 "$dir/case/system/controlDict" > /dev/null
        bend_solve "$dir" > "$dir/solve.txt" || { cat "$dir/solve.txt"; return 1; }
    done
    python3 - "$root" "$projectDir/tests/solver/pipeBend" <<'PY'
import math, re, sys
root = sys.argv[1]
sys.path.insert(0, sys.argv[2])
import passCounters
from sdfoam.outletComposition import lastRow
K = 10


def gains(name):
    """Per class: the continuum's gain at the outlet per fed mass (the last
    rows of outletComposition), and the pass's gain per fed volume with
    its batch-means standard error."""
    d = root + "/" + name
    inlet, outlet = lastRow(d + "/case", "inlet"), lastRow(d + "/case", "outlet")
    classes = [k[9:-6] for k in outlet if k.startswith("massFlow.")]
    fed = {c: 0.0 - inlet["massFlow.%s[kg/s]" % c] for c in classes}
    total = sum(fed.values())
    continuum = {c: (outlet["massFlow.%s[kg/s]" % c] - fed[c]) / total for c in classes}
    # The pass's fed volume rate: every injector's parcels times particles
    injectors = open(d + "/pass/constant/injectionModels").read()
    fedPass = 0.0
    for m in re.finditer(r"nParticle\s+(\S+);\s*sizeDistribution\s*\{[^}]*value\s+(\S+);", injectors):
        fedPass += 20000 * float(m.group(1)) * math.pi / 6 * float(m.group(2)) ** 3
    # The pass's gain per fed volume and its batch-means error
    passGain, passError = {}, {}
    for c in classes:
        g, e = passCounters.rate(d + "/log.pass", lambda x: x[c][3] - x[c][2], K)
        passGain[c], passError[c] = g / fedPass, e / fedPass
    return classes, continuum, passGain, passError


classes, mix, mixPass, mixError = gains("mix")
_, single2, pass2, error2 = gains("d2mm")
_, single1, pass1, error1 = gains("d1mm")
ok = mix["d2mm"] < 0 and mix["d250um"] > 0
for c in classes:
    expected = 0.6 * single2[c] + 0.4 * single1[c]
    # The continuum's gain carries its pass's noise
    sigma = math.sqrt(mixError[c] ** 2 + (0.6 * error2[c]) ** 2 + (0.4 * error1[c]) ** 2)
    z = (mix[c] - expected) / sigma if sigma > 0 else float("inf")
    print("%-7s gain per fed mass: mix %+.5e, 0.6 d2mm + 0.4 d1mm %+.5e, difference %+.2e = %+.2f sigma"
          " (sigma %.2e from the passes' batch means)" % (c, mix[c], expected, mix[c] - expected, z, sigma))
    ok = ok and abs(z) <= 4
sys.exit(0 if ok else 1)
PY
}

# Another product through the tutorial, changed only in its dictionaries
# and the geometry's options (Allrun -D): three classes d3mm, d1500um,
# d750um of density 1100 kg/m3, wall restitution 0.7 and friction 0.2, fed
# 70/30 by mass at loading 0.5 through a 100 mm line (coarse mesh, 25 m/s).
#   - the run completes; results/productDistribution.dat lists exactly the
#     three classes and dust, the fed mass fractions 0.7, 0.3, 0 within 1 %
#     (each class crosses the inlet with its own pass velocity, not
#     exactly the gas's) and the fed mass flow loading rhoGas U A of the
#     snapped inlet's area A (its faces' areas, from the mesh) to 1e-3
#   - the pass carried that product (its product file: rho0 1100, e 0.7,
#     mu 0.2, tangential lossFraction and roughness 0: none given) and the mesh is 100 mm across (checkMesh's bounding box)
#   - the solids balance per run to 1e-10 (tests/solver/pipeBend/balance.py)
# Refused before anything runs, with the file and entry named and no stage
# made: classes of two densities, a feed naming a class that is not a
# species, feed fractions not summing to 1, a negative wall roughness, a
# tangential law that is not one, particlePassCoeffs pipeDiameter
# other than -D; and a pass whose kinematicCloudProperties hard-codes
# another rho0 than granularProperties stops at its first parcel naming both
test_pipe_bend_another_product()
{
    local dir="$workRoot/pipeBendAnotherProduct" case
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$projectDir/tutorials/pipeBend" "$dir/tutorial"
    case="$dir/tutorial"
    "$case/Allclean" > /dev/null 2>&1
    python3 - "$case" <<'PY'
import re, sys
case = sys.argv[1]
path = case + "/constant/granularProperties"
text = open(path).read()
text = re.sub(r"species\s*\{.*?\n\}", "species\n{\n    d3mm    { d 3e-3;   rho 1100; }\n"
              "    d1500um { d 1.5e-3; rho 1100; }\n    d750um  { d 7.5e-4; rho 1100; }\n}",
              text, count=1, flags=re.S)
text = re.sub(r"wallContact\s*\{.*?\}", "wallContact { e 0.7; mu 0.2; }", text, count=1, flags=re.S)
open(path, "w").write(text)
path = case + "/system/feed"
text = open(path).read()
text = re.sub(r"massFractions\s*\{.*?\}", "massFractions { d3mm 0.7; d1500um 0.3; }", text, flags=re.S)
text = re.sub(r"loading\s+\S+;", "loading 0.5;", text)
open(path, "w").write(text)
PY
    cp -r "$case" "$dir/pristine"
    "$case/Allrun" -D 0.1 -mesh coarse -velocity 25 > "$dir/log.Allrun" 2>&1 \
        || { tail -n 30 "$dir/log.Allrun"; return 1; }
    python3 "$projectDir/tests/solver/pipeBend/balance.py" "$case/log.segregationDegradationFoam" \
        "$case/postProcessing/outletComposition/0/" "$case/constant/granularProperties" || return 1
    grep -q "Mesh OK" "$case/log.checkMesh" || return 1
    python3 - "$case" <<'PY' || return 1
import math, re, sys
case = sys.argv[1]
rows = [l.split() for l in open(case + "/results/productDistribution.dat") if not l.startswith("#")]
names = [r[0] for r in rows]
fed = {r[0]: float(r[2]) for r in rows}
fraction = {r[0]: float(r[4]) for r in rows}
# The snapped inlet's area from the mesh: the sdfoam reader's faces and points
from sdfoam import foamcase
mesh = case + "/constant/polyMesh"
boundary = foamcase._body(mesh + "/boundary")
m = re.search(r"\binlet\s*\{[^}]*nFaces\s+(\d+);[^}]*startFace\s+(\d+);", boundary)
nFaces, start = int(m.group(1)), int(m.group(2))
points = [tuple(map(float, p.split())) for p in re.findall(r"\(([-0-9.eE+]+ [-0-9.eE+]+ [-0-9.eE+]+)\)", foamcase._body(mesh + "/points"))]
faces = re.findall(r"\d+\(([\d ]+)\)", foamcase._body(mesh + "/faces"))[start:start + nFaces]
area = 0.0
for f in faces:
    p = [points[int(i)] for i in f.split()]
    # the inlet is the plane x = const: the polygon's area in y-z
    area += 0.5 * abs(sum(p[i][1] * p[(i + 1) % len(p)][2] - p[(i + 1) % len(p)][1] * p[i][2] for i in range(len(p))))
expected = 0.5 * 1.2 * 25 * area
total = sum(fed.values())
box = re.search(r"Overall domain bounding box \(([^)]*)\) \(([^)]*)\)", open(case + "/log.checkMesh").read())
lo, hi = [list(map(float, b.split())) for b in box.groups()]
product = dict(re.findall(r"^(\w+)\s+(\S+);", open(case + "/stages/pass/constant/product").read(), re.M))
print("classes %s; fed fractions %s; fed %.6e kg/s against loading rhoGas U A = %.6e (A %.5e m2, pi D^2/4 %.5e);"
      " mesh across z %.4f m; pass product %s" % (names, fraction, total, expected, area, math.pi * 0.01 / 4, hi[2] - lo[2], product))
ok = (names == ["d3mm", "d1500um", "d750um", "dust"]
      and abs(fraction["d3mm"] - 0.7) < 0.007 and abs(fraction["d1500um"] - 0.3) < 0.003 and fraction["d750um"] == 0
      and abs(total / expected - 1) < 1e-3
      and abs(hi[2] - lo[2] - 0.1) < 1e-4
      and float(product["rho0"]) == 1100 and float(product["e"]) == 0.7 and float(product["mu"]) == 0.2
      and float(product["roughness"]) == 0 and product["tangential"] == "lossFraction"
      and float(rows[names.index("d750um")][3]) > 0)
sys.exit(0 if ok else 1)
PY
    # Refusals, each on a fresh copy: the message, and no stage made
    refused()
    {
        local name="$1" pattern="$2"; shift 2
        rm -rf "$dir/$name"; cp -r "$dir/pristine" "$dir/$name"
        python3 - "$dir/$name" <<PY
import re, sys
case = sys.argv[1]
$(cat)
PY
        if "$dir/$name/Allrun" "$@" > "$dir/log.$name" 2>&1
        then
            echo "$name: accepted"; return 1
        fi
        grep -q -- "$pattern" "$dir/log.$name" || { cat "$dir/log.$name"; echo "$name: no message matching '$pattern'"; return 1; }
        [ ! -d "$dir/$name/stages" ] || { echo "$name: a stage was made"; return 1; }
        grep -m1 -- "$pattern" "$dir/log.$name"
    }
    refused twoDensities "granularProperties: the classes' densities differ (d3mm 1100, d1500um 1100, d750um 1500)" -D 0.1 <<'PY' || return 1
p = case + "/constant/granularProperties"
text = open(p).read()
open(p, "w").write(text.replace("d 7.5e-4; rho 1100;", "d 7.5e-4; rho 1500;"))
PY
    refused unknownClass "massFractions names d2mm, which is not a species of .*granularProperties (species: d3mm d1500um d750um)" -D 0.1 <<'PY' || return 1
p = case + "/system/feed"
text = open(p).read()
open(p, "w").write(re.sub(r"massFractions\s*\{.*?\}", "massFractions { d3mm 0.7; d2mm 0.3; }", text, flags=re.S))
PY
    refused fractionSum "system/feed: massFractions sum to 0.9, not 1" -D 0.1 <<'PY' || return 1
p = case + "/system/feed"
text = open(p).read()
open(p, "w").write(re.sub(r"massFractions\s*\{.*?\}", "massFractions { d3mm 0.6; d1500um 0.3; }", text, flags=re.S))
PY
    refused roughness "granularProperties: wallContact/roughness -2: the standard deviation of the wall's inclination lies in \[0, 45) degrees" -D 0.1 <<'PY' || return 1
p = case + "/constant/granularProperties"
text = open(p).read()
open(p, "w").write(text.replace("wallContact { e 0.7; mu 0.2; }", "wallContact { e 0.7; mu 0.2; roughness -2; }"))
PY
    refused tangential "granularProperties: wallContact/tangential stick: valid choices are lossFraction" -D 0.1 <<'PY' || return 1
p = case + "/constant/granularProperties"
text = open(p).read()
open(p, "w").write(text.replace("wallContact { e 0.7; mu 0.2; }", "wallContact { e 0.7; mu 0.2; tangential stick; }"))
PY
    refused pipeDiameter "particlePassCoeffs/pipeDiameter 0.05 differs from the line's diameter (Allrun -D 0.1" -D 0.1 <<'PY' || return 1
p = case + "/constant/granularProperties"
text = open(p).read()
open(p, "w").write(text.replace("model       particlePass;", "model       particlePass;\n    particlePassCoeffs { pipeDiameter 0.05; }"))
PY
    # A pass whose cloud density is hard-coded apart from the product's
    mkdir -p "$dir/handDensity"
    sed 's/^\( *rho0 *\)\$rho0;/\11590;/' "$projectDir/tutorials/pipeBend/particlePass/constant/kinematicCloudProperties" \
        > "$dir/handDensity/kinematicCloudProperties"
    grep -q "rho0 *1590;" "$dir/handDensity/kinematicCloudProperties" || { echo "handDensity: rho0 not replaced"; return 1; }
    cp "$case/constant/granularProperties" "$dir/handDensity/"
    printf 'loading 1;\ngasDensity 1.2;\nmassFractions { d3mm 1; }\n' > "$dir/handDensity/feed"
    if bend_chain "$dir/handDensity" 20 0.8 > "$dir/log.handDensity" 2>&1
    then
        echo "handDensity: the pass ran with rho0 1590 for a product of 1100 kg/m3"; return 1
    fi
    grep -q "A parcel of species d3mm has density 1590 kg/m3 (kinematicCloudProperties constantProperties rho0) where constant/granularProperties gives 1100 kg/m3" \
        "$dir/handDensity/log.pass" || { tail -20 "$dir/handDensity/log.pass"; return 1; }
    grep -m1 "A parcel of species" "$dir/handDensity/log.pass"
}

# A line through the tutorial's Allrun (coarse mesh, 30 m/s): three bends
# joined by straights of half a diameter (the extreme of a very short
# straight), legs of 2 D, on 2 MPI ranks (-parallel), and one bend with
# the same legs and inlet conditions.
#   - both meshes "Mesh OK"; the line's solids balance to 1e-10
#     (balance.py), on 2 ranks and run again serial
#   - the flows through each bend's exit (outletComposition faceZones):
#     the total through every exit and the outlet lies between the inflow
#     and the inflow less all the dust made per unit time, falling along
#     the line, to 1e-6 of the inflow (the last time's unsteadiness; the
#     zones cover the section and are oriented along the flow)
#   - 2 MPI ranks = serial: every class's flow through every exit and the
#     outlet at the last time, to 1e-8 relative, with the tutorial's
#     decomposition and with one that puts the ranks' boundary exactly on
#     the first bend's exit (every face of exit1 a processor face)
#   - the first bend breaks the same fraction of the fed class in the
#     line as alone, within 4 standard errors of the difference, each from
#     batch means of its pass's broken volume (the line's over all its
#     bends, which overstates the first bend's: conservative)
test_pipe_bend_line()
{
    local root="$workRoot/pipeBendLine" name
    rm -rf "$root"; mkdir -p "$root"
    for name in line single
    do
        cp -r "$projectDir/tutorials/pipeBend" "$root/$name"
        "$root/$name/Allclean" > /dev/null 2>&1
    done
    "$root/line/Allrun" -mesh coarse -velocity 30 -bends 3 -straight 0.5 -upstream 2 -downstream 2 -parallel \
        > "$root/log.line" 2>&1 || { tail -n 30 "$root/log.line"; return 1; }
    "$root/single/Allrun" -mesh coarse -velocity 30 -bends 1 -upstream 2 -downstream 2 \
        > "$root/log.single" 2>&1 || { tail -n 30 "$root/log.single"; return 1; }
    for name in line single
    do
        grep -q "Mesh OK" "$root/$name/log.checkMesh" || { echo "$name: mesh not OK"; return 1; }
    done
    # The same case again, serial
    mkdir -p "$root/serial"
    cp -r "$root/line/0" "$root/line/constant" "$root/line/system" "$root/serial/"
    segregationDegradationFoam -case "$root/serial" > "$root/serial/log.segregationDegradationFoam" 2>&1 \
        || { tail -30 "$root/serial/log.segregationDegradationFoam"; return 1; }
    # And on 2 ranks split exactly at the first bend's exit: the cells on
    # either side of its plane on different ranks (decomposePar manual), so
    # every face of exit1 is a processor face
    mkdir -p "$root/split"
    cp -r "$root/line/0" "$root/line/constant" "$root/line/system" "$root/split/"
    python3 - "$root/split" <<'PY' || return 1
import re, sys
from sdfoam import foamcase
case = sys.argv[1]
geometry = open(case + "/system/bendGeometry").read()
text = re.search(r"^bendExits\s+\((.*)\);", geometry, re.M).group(1)
v = [tuple(map(float, t.split())) for t in re.findall(r"\(([^()]+)\)", text)]
c, t = v[0], v[1]
ranks = [1 if sum((x[i] - c[i]) * t[i] for i in range(3)) > 0 else 0 for x in foamcase.cellCentres(case)]
with open(case + "/constant/cellDecomposition", "w") as f:
    f.write("FoamFile { version 2.0; format ascii; class labelList; object cellDecomposition; }\n%d\n(\n%s\n)\n"
            % (len(ranks), "\n".join(map(str, ranks))))
with open(case + "/system/decomposeParDict", "w") as f:
    f.write("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
            "numberOfSubdomains 2;\nmethod manual;\nmanualCoeffs { dataFile \"cellDecomposition\"; }\n")
print("split at exit1: %d and %d cells" % (ranks.count(0), ranks.count(1)))
PY
    decomposePar -case "$root/split" > "$root/split/log.decomposePar" 2>&1 || { tail -20 "$root/split/log.decomposePar"; return 1; }
    python3 - "$root/split" <<'PY' || return 1
import re, sys
# exit1 is cut by the ranks' boundary: the zone holds no internal face of either rank
for p in ("processor0", "processor1"):
    owner = open(sys.argv[1] + "/%s/constant/polyMesh/owner" % p).read()
    nInternal = int(re.search(r"nInternalFaces:\s*(\d+)", owner).group(1))
    zones = open(sys.argv[1] + "/%s/constant/polyMesh/faceZones" % p).read()
    m = re.search(r"exit1\s*\{[^}]*?faceLabels\s*List<label>\s*(?:(\d+)\s*\(([^)]*)\)|(\d+)\{(\d+)\})", zones, re.S)
    faces = list(map(int, m.group(2).split())) if m.group(2) is not None else [int(m.group(4))] * int(m.group(3))
    inside = [f for f in faces if f < nInternal]
    print("%s: exit1 has %d faces, %d of them internal" % (p, len(faces), len(inside)))
    if not faces or inside:
        sys.exit(1)
PY
    mpirun -np 2 segregationDegradationFoam -parallel -case "$root/split" > "$root/split/log.segregationDegradationFoam" 2>&1 \
        || { tail -30 "$root/split/log.segregationDegradationFoam"; return 1; }
    local log
    for log in "$root/line/log.segregationDegradationFoam" "$root/serial/log.segregationDegradationFoam"
    do
        python3 "$projectDir/tests/solver/pipeBend/balance.py" "$log" \
            "${log%/log.*}/postProcessing/outletComposition/0/" "$root/line/constant/granularProperties" || return 1
    done
    python3 - "$root" "$projectDir/tests/solver/pipeBend" <<'PY'
import math, sys
root = sys.argv[1]
sys.path.insert(0, sys.argv[2])
import passCounters
from sdfoam.outletComposition import lastRow


def last(case, station):
    return {k[9:-6]: v for k, v in lastRow(case, station).items() if k.startswith("massFlow.")}


def dustRate(case):
    rows = [l.split() for l in open(case + "/results/productDistribution.dat") if l.startswith("dust")]
    return float(rows[0][3])


ok = True
line, serial = root + "/line", root + "/serial"
inlet = -sum(last(line, "inlet").values())
dust = dustRate(line)
previous = inlet
# the run's last time is steady to about 1e-7 of the inflow (hold-up still
# settling downstream)
tol = 1e-6 * inlet
for station in ("exit1", "exit2", "exit3", "outlet"):
    total = sum(last(line, station).values())
    # What reaches a section is the inflow less the dust made upstream of
    # it: at most the inflow, at least the inflow less all the dust, and no
    # more than what reached the section before
    print("%s: total %.12e kg/s, inlet %.12e, dust made %.3e: inlet - total = %.3e"
          % (station, total, inlet, dust, inlet - total))
    ok = ok and -tol <= inlet - total <= dust + tol and total <= previous + tol
    previous = total
for other, what in ((line, "2 ranks (simple)"), (root + "/split", "2 ranks split at exit1")):
    worst = 0.0
    for station in ("exit1", "exit2", "exit3", "outlet"):
        p, s = last(other, station), last(serial, station)
        for c in p:
            worst = max(worst, abs(p[c] - s[c]) / abs(s[c]) if abs(s[c]) > 1e-20 else abs(p[c]))
    print("%s against serial: every class through every exit and the outlet to %.2e" % (what, worst))
    ok = ok and worst < 1e-8


def bend1(case):
    rows = [l.split() for l in open(case + "/results/bendExits.dat") if l.strip() and l.split()[0] == "1"]
    return float(rows[0][3])


def relativeError(case):
    broken, error = passCounters.rate(case + "/log.icoUncoupledKinematicParcelFoam.pass",
                                      lambda x: x["d2mm"][2])
    return error / broken


bl, bs = bend1(line), bend1(root + "/single")
sigma = math.hypot(bl * relativeError(line), bs * relativeError(root + "/single"))
z = (bl - bs) / sigma
print("first bend's broken fraction: in the line %.5e, alone %.5e, difference %+.2e = %+.2f sigma (sigma %.2e)"
      % (bl, bs, bl - bs, z, sigma))
ok = ok and bs > 0 and abs(z) <= 4
sys.exit(0 if ok else 1)
PY
}

# Rough wall: 1 mm grains on no force (no drag, no gravity; nothing
# breaks) fired at a flat floor at 10 m/s, 2000 per run, caught in flight
# after one rebound from breakingRebound's wall (e 0.8, mu 0.1).
# - smooth walls, exactly (to 1e-12 of V, every grain): the loss fraction
#   at 30 degrees, (V cos a (1 - mu), 0, e V sin a); Coulomb friction at
#   30 degrees, a sliding impact, (V cos a - mu (1 + e) V sin a, 0,
#   e V sin a), and at 80 degrees, one that sticks, (5/7 V cos a, 0,
#   e V sin a);
# - roughness 5 degrees at impact angles 10 and 45 degrees (loss
#   fraction) and 10 degrees (Coulomb): the mean of each rebound velocity
#   component and the standard deviation of the vertical and lateral ones
#   against the model's (two Gaussian tilts, kept with probability U^ & n
#   and only when the rebound leaves the wall) computed by quadrature,
#   each within 4 standard errors of the sample; the same means without
#   the shadow effect's weighting are printed beside them, and at 10
#   degrees those of Ux and Uz must lie outside 4 standard errors (the
#   test tells the weighting from none)
# - roughness 50 degrees, and a tangential law that is not one: refused
#   by the pass, naming the entry
test_pipe_bend_rough_wall()
{
    local base="$workRoot/pipeBendRoughWall" run angle roughness tangential
    rm -rf "$base"
    mkdir -p "$base"
    for run in "30 0 lossFraction" "30 0 coulomb" "80 0 coulomb" "10 5 lossFraction" "45 5 lossFraction" "10 5 coulomb"
    do
        set -- $run
        angle=$1; roughness=$2; tangential=$3
        local dir="$base/angle$angle-roughness$roughness-$tangential"
        cp -r "$projectDir/tests/solver/pipeBend/roughWall" "$dir"
        python3 - "$dir" "$angle" "$roughness" "$tangential" <<'PY'
import math, sys
case, angle, roughness, tangential = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4]
a = math.radians(angle)
with open(case + "/constant/impact", "w") as f:
    f.write("U0 (%.17g 0 %.17g);\nroughness %s;\ntangential %s;\n"
            % (10 * math.cos(a), -10 * math.sin(a), roughness, tangential))
# 2000 grains 2 mm above the floor on a 40 x 50 grid, x in [-0.06, -0.01]
with open(case + "/constant/kinematicCloudPositions", "w") as f:
    f.write("FoamFile { version 2.0; format ascii; class vectorField; object kinematicCloudPositions; }\n(\n")
    for i in range(40):
        for j in range(50):
            f.write("(%.6f %.6f 0.002)\n" % (-0.06 + 0.05 * (i + 0.5) / 40, -0.04 + 0.08 * (j + 0.5) / 50))
    f.write(")\n")
PY
        blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || { tail -20 "$dir/log.blockMesh"; return 1; }
        icoUncoupledKinematicParcelFoam -case "$dir" > "$dir/log.pass" 2>&1 || { tail -30 "$dir/log.pass"; return 1; }
    done
    # refusedByPass ENTRY VALUE PATTERN: the rough 10-degree run with ENTRY
    # of its impact file set to VALUE; the pass stops with a message naming
    # the entry (PATTERN)
    refusedByPass()
    {
        local bad="$base/refused-$1-$2"
        cp -r "$base/angle10-roughness5-lossFraction" "$bad"
        sed -i "s/^$1 .*/$1 $2;/" "$bad/constant/impact"
        if icoUncoupledKinematicParcelFoam -case "$bad" > "$bad/log.pass" 2>&1
        then
            echo "$1 $2: accepted"; return 1
        fi
        grep -q "'$1 $2' in .*breakingReboundCoeffs.\?: $3" "$bad/log.pass" \
            || { tail -20 "$bad/log.pass"; echo "$1 $2: no message naming the entry"; return 1; }
        grep -m1 "'$1 $2'" "$bad/log.pass"
    }
    refusedByPass roughness 50 "the standard deviation of the wall's inclination, in degrees, lies in \[0, 45)" || return 1
    refusedByPass tangential stick "valid choices are lossFraction .* and coulomb" || return 1
    python3 - "$base" <<'PY'
import math, sys
from sdfoam.foamcase import readListFile
base = sys.argv[1]
V, e, mu = 10.0, 0.8, 0.1


def velocities(case):
    return readListFile(case + "/0.004/lagrangian/kinematicCloud/U", 3)


def rebound(U, n, law):
    Un = sum(u * c for u, c in zip(U, n))
    Ut = [u - Un * c for u, c in zip(U, n)]
    if law == "lossFraction":
        after = [(1 - mu) * u for u in Ut]
    else:
        magUt = math.sqrt(sum(u * u for u in Ut))
        slide = mu * (1 + e) * Un
        after = [(1 - slide / magUt) * u if magUt > 3.5 * slide else 5.0 / 7.0 * u for u in Ut]
    return tuple(u - e * Un * c for u, c in zip(after, n))


def model(angle, roughness, law, shadow=True, steps=241, width=6.0):
    """Mean and standard deviation of the rebound velocity's components
    over the tilts (midpoint quadrature over +-width sigma)."""
    a, s = math.radians(angle), math.radians(roughness)
    U = (V * math.cos(a), 0.0, -V * math.sin(a))
    nw, t, b = (0.0, 0.0, -1.0), (1.0, 0.0, 0.0), (0.0, -1.0, 0.0)
    h = 2 * width / steps
    m0 = 0.0
    m1 = [0.0] * 3
    m2 = [0.0] * 3
    for i in range(steps):
        g1 = s * (-width + (i + 0.5) * h)
        for k in range(steps):
            g2 = s * (-width + (k + 0.5) * h)
            f = math.exp(-0.5 * ((g1 / s) ** 2 + (g2 / s) ** 2))
            n = [nw[c] + math.tan(g1) * t[c] + math.tan(g2) * b[c] for c in range(3)]
            norm = math.sqrt(sum(c * c for c in n))
            n = [c / norm for c in n]
            hit = sum(U[c] * n[c] for c in range(3)) / V
            if hit <= 0:
                continue
            R = rebound(U, n, law)
            if R[2] <= 0:  # does not leave the floor (its outward normal is -z)
                continue
            w = f * (hit if shadow else 1.0)
            m0 += w
            for c in range(3):
                m1[c] += w * R[c]
                m2[c] += w * R[c] * R[c]
    mean = [m / m0 for m in m1]
    sd = [math.sqrt(max(m2[c] / m0 - mean[c] ** 2, 0)) for c in range(3)]
    return mean, sd


ok = True
# The smooth walls, exactly
for angle, law, want in [
        (30, "lossFraction", lambda a: (V * math.cos(a) * (1 - mu), 0.0, e * V * math.sin(a))),
        (30, "coulomb", lambda a: (V * math.cos(a) - mu * (1 + e) * V * math.sin(a), 0.0, e * V * math.sin(a))),
        (80, "coulomb", lambda a: (5.0 / 7.0 * V * math.cos(a), 0.0, e * V * math.sin(a)))]:
    w = want(math.radians(angle))
    got = velocities(base + "/angle%d-roughness0-%s" % (angle, law))
    worst = max(abs(g[c] - w[c]) / V for g in got for c in range(3))
    print("smooth wall, %s, %d deg: %d grains, largest |U - (%.6f, 0, %.6f)|/V = %.2e (tolerance 1e-12)"
          % (law, angle, len(got), w[0], w[2], worst))
    ok = ok and len(got) == 2000 and worst <= 1e-12

for angle, law in ((10, "lossFraction"), (45, "lossFraction"), (10, "coulomb")):
    got = velocities(base + "/angle%d-roughness5-%s" % (angle, law))
    N = len(got)
    mean = [sum(g[c] for g in got) / N for c in range(3)]
    sd = [math.sqrt(sum((g[c] - mean[c]) ** 2 for g in got) / (N - 1)) for c in range(3)]
    want, wantSd = model(angle, 5, law)
    plain, plainSd = model(angle, 5, law, shadow=False)
    print("roughness 5 deg, %s, impact angle %d deg, %d grains (model; without the shadow weighting):"
          % (law, angle, N))
    ok = ok and N == 2000
    checks = [("mean U%s" % "xyz"[c], mean[c], want[c], plain[c], sd[c] / math.sqrt(N)) for c in range(3)]
    # the standard error of a standard deviation from the sample's
    # kurtosis k (the tilts' rebounds are not normal): sd sqrt((k - 1)/(4N))
    for c in (1, 2):
        k = sum((g[c] - mean[c]) ** 4 for g in got) / N / sd[c] ** 4
        checks.append(("sd U%s" % "xyz"[c], sd[c], wantSd[c], plainSd[c], sd[c] * math.sqrt((k - 1) / (4 * N))))
    for name, m, w, p, se in checks:
        z = (m - w) / se
        print("  %-6s measured %9.5f model %9.5f (%+6.2f se)   unweighted %9.5f (%+6.2f se)"
              % (name, m, w, z, p, (m - p) / se))
        ok = ok and abs(z) <= 4
        # at a grazing 10 degrees the shadow effect shows: the means of Ux
        # and Uz without its weighting lie outside 4 standard errors
        if angle == 10 and name in ("mean Ux", "mean Uz") and not abs((m - p) / se) > 4:
            print("  the sample does not tell the shadow effect's weighting from none")
            ok = False
sys.exit(0 if ok else 1)
PY
}
