# shellcheck shell=bash
# The README's commands as a newcomer types them (sourced by tests/run;
# tests readme/allrun/*): the main job ./Allrun, serial and on 2 ranks, in
# the project's own tutorials/silo2D (where the README sends the user), and
# tutorials/pipeBend/Allrun in a copy of the tutorials, tutorials/conveyingLine
# in a copy of the case alone.

# The documented outcome of the default silo2D run (tutorials/silo2D/README.md,
# "What it shows"; docs/user/outputs.md): the fields each written time
# holds, the wedge's mass flow, the outflow's coarse fraction
readme_silo2D_checks()
{
    local case="$1"
    local t f
    for t in 5 10 15 20 25 30
    do
        for f in n.fine n.coarse U T gammaDot dMean D.fine D.coarse
        do
            [ -f "$case/$t/$f" ] || { echo "missing $case/$t/$f (README: fields in the time directories)"; return 1; }
        done
    done
    for f in postProcessing/outletComposition/0/outlet.dat postProcessing/sizeDistribution/0/sizeDistribution.dat
    do
        head -n 1 "$case/$f" | grep -q '^#' || { echo "$case/$f: missing or without a header line"; return 1; }
    done
    # a PNG, not an empty file or an error page: the signature's bytes
    head -c 8 "$case/results/outletComposition.png" | od -An -c | grep -q 'P   N   G' \
        || { echo "$case/results/outletComposition.png is not a PNG"; return 1; }
    python3 -m sdfoam.fieldStats "$case" bounds --tol 1e-8 || return 1
    python3 - "$case" <<'PY'
import math, sys
from sdfoam.beverloo import hopperRate
case = sys.argv[1]
rows = [l.split() for l in open(case + "/postProcessing/outletComposition/0/outlet.dat") if not l.startswith("#")]
header = [l for l in open(case + "/postProcessing/outletComposition/0/outlet.dat") if l.startswith("# time")][-1].split()[1:]
col = {name.split("[")[0]: i for i, name in enumerate(header)}   # time[s] -> time
t = [float(r[col["time"]]) for r in rows]
mdot = [float(r[col["massFlow"]]) for r in rows]
coarse = [float(r[col["massFraction.coarse"]]) for r in rows]
# Beverloo by hand (the kinematic discharge test's formula) through the 5-degree
# wedge's share of the outlet, at packed fraction 0.6 and rho 2500 kg/m3; the
# wedge's outlet area on the mesh differs from the disc's share by < 1e-3
Q = hopperRate(0.04, 1.2e-3, 30)
mBeverloo = Q * math.sin(math.radians(5)) / (2 * math.pi) * 0.6 * 2500
dev = max(abs(m / mBeverloo - 1) for m in mdot)
spread = max(abs(c - 0.20) for c in coarse)
print("outlet: %d rows to t = %g s; mass flow within %.2e of Beverloo's %.5e kg/s; "
      "coarse fraction within %.2e of the feed's 0.20 throughout"
      % (len(rows), t[-1], dev, mBeverloo, spread))
ok = abs(t[-1] - 30) < 1e-9 and dev < 1e-3
# the README's description: with the DEM-calibrated closures the well-mixed silo's
# outflow stays at its 0.20 coarse within 1e-3 over the 30 s (the seed's kinetic
# sieving took it to 0.43: Allrun -seedClosures)
ok = ok and spread < 1e-3
sys.exit(0 if ok else 1)
PY
}

# ./Allrun, then ./Allrun -parallel, in the project's tutorials/silo2D (each
# run starts with the tutorial's Allclean, so earlier results there are
# replaced, as they are when a user runs it; the tutorial is cleaned after):
# both succeed, write what the README lists, and the 2 ranks reproduce the
# serial outflow (to 1e-6 over the first 3 s, 1e-3 over the 30 s: below)
test_readme_allrun()
{
    local tutorial="$projectDir/tutorials/silo2D" dir="$workRoot/readmeAllrun"
    rm -rf "$dir"; mkdir -p "$dir"
    # shellcheck disable=SC2064
    trap "'$tutorial/Allclean' > /dev/null 2>&1" EXIT
    [ -z "${README_ALLRUN_KEEP:-}" ] || trap - EXIT   # keep the results to look at
    ./Allrun > "$dir/log.Allrun" 2>&1 || { tail -n 30 "$dir/log.Allrun"; return 1; }
    grep -q "silo2D results in" "$dir/log.Allrun" || { echo "./Allrun did not say where the results are"; return 1; }
    readme_silo2D_checks "$tutorial" || return 1
    cp "$tutorial/postProcessing/outletComposition/0/outlet.dat" "$dir/outlet.serial.dat"

    ./Allrun -parallel > "$dir/log.Allrun-parallel" 2>&1 || { tail -n 30 "$dir/log.Allrun-parallel"; return 1; }
    grep -q "^Starting.*-parallel\|mpirun" "$tutorial/log.segregationDegradationFoam" 2> /dev/null \
        || [ -d "$tutorial/processor1" ] || { echo "./Allrun -parallel did not run on 2 ranks"; return 1; }
    readme_silo2D_checks "$tutorial" || return 1
    cp "$tutorial/postProcessing/outletComposition/0/outlet.dat" "$dir/outlet.parallel.dat"
    python3 - "$dir/outlet.serial.dat" "$dir/outlet.parallel.dat" <<'PY'
import sys
rows = [[[float(x) for x in l.split()] for l in open(f) if not l.startswith("#")] for f in sys.argv[1:]]
header = [l for l in open(sys.argv[1]) if l.startswith("# time")][-1].split()[1:]
serial, parallel = rows
if len(serial) != len(parallel):
    print("serial %d rows, parallel %d" % (len(serial), len(parallel))); sys.exit(1)
# Relative to each column's largest value. Up to 3 s the 2 ranks give the
# serial series to 1e-6 (parallelCheck in the tutorial: 1.3e-8 over 2 s).
# Near 3.3 s the difference jumps from below 1e-8 to 1e-5 within 0.2 s (an
# event of the run, not round-off growing; not traced: the kinematic flow,
# solved by Gauss-Seidel to a residual of 1e-6, is the likely source) and
# the sieving carries it to about 2e-4 in the outflow's coarse
# fraction at 30 s: held to 1e-3, an eighth of the tutorial mesh's error in
# that fraction (0.008, docs/benchmarks.md)
def worst(until):
    w, where = 0.0, None
    for j in range(len(serial[0])):
        scale = max(abs(r[j]) for r in serial) or 1.0
        for a, b in zip(serial, parallel):
            if a[0] <= until and abs(a[j] - b[j]) / scale > w:
                w, where = abs(a[j] - b[j]) / scale, (header[j], a[0], a[j], b[j])
    return w, where
early, whereEarly = worst(3.0)
whole, whereWhole = worst(float("inf"))
print("serial and 2 ranks (relative to each column's largest value): to 3 s %.2e, to 30 s %.2e; "
      "worst: %s at t = %g s, %.9g serial, %.9g on 2 ranks" % ((early, whole) + whereWhole))
sys.exit(0 if early < 1e-6 and whole < 1e-3 else 1)
PY
}

# tutorials/pipeBend/Allrun as the README gives it, on the tutorial's coarse
# mesh (-mesh coarse) at 30 m/s, where the parent breaks most (the smallest
# relative error of the reference), with its Lagrangian reference
# (-reference): fines per bend written with a header and a row whose broken
# fraction is the sum of its shares, and the continuum's broken fraction
# within 2 sqrt(2) sigma_ref of the reference's (docs/validation.md, "Continuum
# against the Lagrangian reference": the reference's binomial error, and the
# continuum's pass of as many parents carrying about the same)
test_readme_pipe_bend()
{
    local dir="$workRoot/readmePipeBend"
    rm -rf "$dir"; mkdir -p "$dir/tutorials"
    cp -r "$projectDir/tutorials/pipeBend" "$dir/tutorials/"
    "$dir/tutorials/pipeBend/Allclean" > /dev/null 2>&1
    "$dir/tutorials/pipeBend/Allrun" -mesh coarse -velocity 30 -reference > "$dir/log.Allrun" 2>&1 \
        || { tail -n 30 "$dir/log.Allrun"; return 1; }
    python3 - "$dir/tutorials/pipeBend/results" <<'PY'
import math, sys
results = sys.argv[1]
lines = open(results + "/finesPerBend.dat").read().splitlines()
if len(lines) != 2 or not lines[0].startswith("#"):
    print("finesPerBend.dat: expected one header line and one row, got", lines); sys.exit(1)
header, row = lines[0][1:].split(), lines[1].split()
values = dict(zip(header, row))
broken = float(values["brokenFraction"])
shares = [float(values[k]) for k in header if k.endswith("/fed")]
print("finesPerBend: broken fraction %.6e, shares %s (sum %.6e)" % (broken, shares, sum(shares)))
ok = 0 < broken < 1 and all(s >= 0 for s in shares) and abs(sum(shares) - broken) <= 1e-6 * broken
rows = [l.split() for l in open(results + "/reference.dat") if not l.startswith("#")]
parent, cont, ref, sigma = rows[0][0], float(rows[0][1]), float(rows[0][2]), float(rows[0][3])
z = (cont - ref) / sigma
print("continuum %.4e, reference %.4e +- %.2e: %.2f sigma_ref (band 2 sqrt(2) = %.2f)"
      % (cont, ref, sigma, z, 2 * math.sqrt(2)))
ok = ok and parent == "d2mm" and abs(cont - broken) <= 1e-6 * broken and abs(z) <= 2 * math.sqrt(2)
sys.exit(0 if ok else 1)
PY
}

# tutorials/conveyingLine/Allrun as the README gives it, in a copy of the
# case alone outside the project (the case runs the pipe bend's stages by
# $SDF_PROJECT_DIR and includes its dictionaries: a copied case must work),
# its line shortened on the command line (two bends, straights of 2 D, legs
# of 1 D, 5,000 parcels per second per class; options after the case's own
# override them): results/bendExits.dat with the inlet, exit1, exit2 and
# the outlet for every class and one row per bend, each bend's broken
# fraction in [0, 1), the first's > 0; the inlet values of 0/n.<class>
# exactly loading rho_gas w / rho (1e-9) for the feed's mass fractions 0.6,
# 0.3, 0.1 and 0; results/productDistribution.dat with fed mass fractions
# within 1 % of those (each class crosses the inlet at its own pass
# velocity, not exactly the gas's); results/bendExits.png
test_readme_conveying_line()
{
    local dir="$workRoot/readmeConveyingLine"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$projectDir/tutorials/conveyingLine" "$dir/"
    "$dir/conveyingLine/Allclean" > /dev/null 2>&1
    "$dir/conveyingLine/Allrun" -bends 2 -straight 2 -upstream 1 -downstream 1 -parcels 5000 \
        > "$dir/log.Allrun" 2>&1 || { tail -n 30 "$dir/log.Allrun"; return 1; }
    [ -s "$dir/conveyingLine/results/bendExits.png" ] || { echo "no results/bendExits.png"; return 1; }
    python3 - "$dir/conveyingLine/results" <<'PY'
import sys
results = sys.argv[1]
rows = [l.split() for l in open(results + "/bendExits.dat") if l.strip() and not l.startswith("#")]
stations = [r for r in rows if len(r) == 7 and not r[0].isdigit()]
bends = [r for r in rows if r[0].isdigit()]
names = sorted(set(r[0] for r in stations))
classes = ["d2mm", "d1mm", "d500um", "d250um"]
ok = names == sorted(["inlet", "exit1", "exit2", "outlet"]) and len(stations) == 4 * len(classes) and len(bends) == 2
broken = [float(b[3]) for b in bends]
print("stations %s, bends' broken fractions %s" % (names, broken))
ok = ok and all(0 <= b < 1 for b in broken) and broken[0] > 0
fed = {l.split()[0]: float(l.split()[4]) for l in open(results + "/productDistribution.dat") if not l.startswith("#")}
print("fed mass fractions %s" % fed)
want = {"d2mm": 0.6, "d1mm": 0.3, "d500um": 0.1, "d250um": 0.0}
ok = ok and all(abs(fed[c] - w) <= 0.01 * w for c, w in want.items())
import re
for c, w in want.items():
    text = open(results + "/../0/n." + c).read()
    inlet = float(re.search(r"inlet\s*\{[^}]*value\s+uniform\s+(\S+);", text).group(1))
    print("0/n.%s inlet %.9e, loading rho_gas w / rho %.9e" % (c, inlet, 1.2 * w / 1590))
    ok = ok and abs(inlet - 1.2 * w / 1590) <= 1e-9 * 1.2 / 1590
sys.exit(0 if ok else 1)
PY
}
