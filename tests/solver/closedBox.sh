# shellcheck shell=bash
# The closed-box case tests/solver/closedBox (sourced by tests/run; tests
# solver/closedBox/*), and the helpers that run and check it (also used by the
# extremes matrix, tests/solver/extremes.sh).

# closed_box_prepare DIR: mesh and initial fields of the closed box copied to DIR
closed_box_prepare()
{
    local dir="$1"
    blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || { cat "$dir/log.blockMesh"; return 1; }
    cp -r "$dir/0.orig" "$dir/0"
    setFields -case "$dir" > "$dir/log.setFields" 2>&1 || { cat "$dir/log.setFields"; return 1; }
}

# closed_box_run DIR: closed_box_prepare, then the solver (log in DIR/log.solver)
closed_box_run()
{
    local dir="$1"
    closed_box_prepare "$dir" || return 1
    segregationDegradationFoam -case "$dir" > "$dir/log.solver" 2>&1 || { tail -30 "$dir/log.solver"; return 1; }
}

# closed_box_check DIR [perSpecies|totalOnly] [PYTHON] [BOUNDS_TOLERANCE]: bounds (to
# BOUNDS_TOLERANCE, default 1e-8: absolute, so the extremes' trace cases pass 1e-8 of
# their amplitude), no non-finite value, conservation (each species, or only the total
# with breakage) to 1e-10 relative; then the case's own check PYTHON, run with the step
# rows in `rows` (dicts: total and each n.<species>, from the "Initial solids:" line
# on), `case` (the case directory) and `ok` (the verdict so far)
closed_box_check()
{
    local dir="$1" conserved="${2:-perSpecies}" own="${3:-}" tolerance="${4:-1e-8}"
    # the species' total to 1e-8 of itself at least: a trace tolerance is
    # far below what the linear solvers keep a total of 0.6 to
    python3 -m sdfoam.fieldStats "$dir" bounds --tol "$tolerance" --tol-total 1e-8 || return 1
    python3 - "$dir" "$conserved" "$own" <<'PY'
import re, sys
case, conserved, own = sys.argv[1], sys.argv[2], sys.argv[3]
rows = []
for line in open(case + "/log.solver"):
    if line.startswith("Solids:") or line.startswith("Initial solids:"):
        row = {"total": float(re.search(r"total volume (\S+)", line).group(1))}
        for name, v in re.findall(r"(n\.\w+) volume (\S+)", line):
            row[name] = float(v)
        rows.append(row)
if len(rows) < 3:
    print("FAIL: fewer than 2 steps in the log"); sys.exit(1)
species = sorted(k for k in rows[0] if k != "total")
if not species or any(sorted(k for k in r if k != "total") != species for r in rows):
    print("FAIL: the species' volumes are not on every line from the initial one"); sys.exit(1)
keys = ["total"] + ([] if conserved == "totalOnly" else species)
ok = True
for k in keys:
    first = rows[0][k]
    worst = max(abs(r[k] - first) for r in rows)
    rel = worst / first if first > 0 else worst
    print("%s: initial %.6e, max %s change over %d steps %.2e"
          % (k, first, "relative" if first > 0 else "absolute", len(rows) - 1, rel))
    # an absent species stays exactly 0
    ok &= rel <= (1e-10 if first > 0 else 0.0)
if own:
    exec(own)
sys.exit(0 if ok else 1)
PY
}

# Closed box (cyclic in x, walls elsewhere) with shear flow, percolation,
# kinetic sieving and diffusion, a partly empty initial state: mass of every
# species conserved to 1e-10 relative over at least 10 steps from the
# initial state, 0 <= n_i <= phi at all times
test_closed_box()
{
    local dir="$workRoot/closedBox"
    rm -rf "$dir"; cp -r tests/solver/closedBox "$dir"
    closed_box_run "$dir" || return 1
    closed_box_check "$dir" perSpecies '
if len(rows) - 1 < 10:
    print("too few steps parsed"); ok = False' || return 1
    python3 -m sdfoam.fieldStats "$dir" changed --tol 0.05
}

# The closed box with breakage as well (powerLaw S = 0.4 (d/2 mm)^3 1/s,
# uniform binary fragments, fines to the dust sink): solids + dust
# conserved to 1e-10 relative over every step, 0 <= n_i <= phi, dust
# formed; and the same case on 2 MPI ranks equals the serial run (species
# and dust) to 1e-9, and so does the sizeDistribution function object's file
test_closed_box_breakage()
{
    local serial="$workRoot/closedBoxBreakage" parallel="$workRoot/closedBoxBreakageParallel"
    local d
    for d in "$serial" "$parallel"
    do
        rm -rf "$d"; cp -r tests/solver/closedBox "$d"
        foamDictionary -entry endTime -set 1 "$d/system/controlDict" > /dev/null
        foamDictionary -entry breakage -remove "$d/constant/granularProperties" > /dev/null
        cat >> "$d/constant/granularProperties" <<'DICT'
breakage
{
    model       powerLaw;
    powerLawCoeffs { k 0.4; dRef 2e-3; a 3; }
    daughterSizeDistribution { model uniformBinary; }
    fines       dust;
}
DICT
        foamDictionary -entry writeFields -set "(nTotal D brokenVolume)" "$d/constant/granularProperties" > /dev/null
        cat >> "$d/system/controlDict" <<'DICT'
functions
{
    sizeDistribution
    {
        type    sizeDistribution;
        libs    ("libsegregationDegradationModels.so");
    }
}
DICT
        closed_box_prepare "$d" || return 1
    done
    segregationDegradationFoam -case "$serial" > "$serial/log.solver" 2>&1 || { tail -30 "$serial/log.solver"; return 1; }
    python3 - "$serial/log.solver" <<'PY' || return 1
import re, sys
totals = []
for line in open(sys.argv[1]):
    if line.startswith("Solids:") or line.startswith("Initial solids:"):
        m = re.search(r"total volume (\S+)\s+dust volume (\S+)", line)
        if m:
            totals.append((float(m.group(1)), float(m.group(2))))
if len(totals) < 10:
    print("too few steps parsed"); sys.exit(1)
# The state the run starts from (the solver's "Initial solids:" line)
first = totals[0][0] + totals[0][1]
rel = max(abs(s + d - first) for s, d in totals) / first
print("solids + dust: %.12e at the start, max relative change over %d steps %.2e; dust at the end %.4e (%.2f %% of the solids)"
      % (first, len(totals) - 1, rel, totals[-1][1], 100 * totals[-1][1] / first))
sys.exit(0 if rel < 1e-10 and totals[-1][1] > 1e-3 * first else 1)
PY
    python3 -m sdfoam.fieldStats "$serial" bounds --tol 1e-8 || return 1

    decomposePar -case "$parallel" > "$parallel/log.decomposePar" 2>&1 || { tail -20 "$parallel/log.decomposePar"; return 1; }
    mpirun -np 2 segregationDegradationFoam -parallel -case "$parallel" > "$parallel/log.solver" 2>&1 || { tail -20 "$parallel/log.solver"; return 1; }
    reconstructPar -latestTime -case "$parallel" > "$parallel/log.reconstructPar" 2>&1 || return 1
    python3 -m sdfoam.fieldStats "$parallel" compare "$serial" --tol 1e-9 || return 1
    python3 - "$serial" "$parallel" <<'PY'
import sys
from sdfoam import foamcase
a, b = sys.argv[1], sys.argv[2]
t = foamcase.latestTime(a)
da = foamcase.readScalarField(a, t, "dust")
db = foamcase.readScalarField(b, foamcase.latestTime(b), "dust")
worst = max(abs(x - y) for x, y in zip(da, db))
print("dust: max |parallel - serial| %.3e" % worst)

# The sizeDistribution function object: the same rows on 2 ranks (values
# reduced over the processors), its broken volume the dust's (the box's
# fragments above the fine pivot stay in the fine class: broken >= dust)
def rows(case):
    path = case + "/postProcessing/sizeDistribution/0/sizeDistribution.dat"
    lines = [l for l in open(path) if l.strip()]
    header = [l for l in lines if l.startswith("#")][-1].split()[1:]
    return header, [list(map(float, l.split())) for l in lines if not l.startswith("#")]
hs, rs = rows(a)
hp, rp = rows(b)
if hs != hp or len(rs) != len(rp) or "dust[m3]" not in hs or "broken[m3]" not in hs:
    print("sizeDistribution headers or row counts differ:", hs, hp, len(rs), len(rp)); sys.exit(1)
rel = max(abs(x - y) / max(abs(x), 1e-300) for r, q in zip(rs, rp) for x, y in zip(r, q) if x != 0)
last = dict(zip(hs, rs[-1]))
print("sizeDistribution: %d rows, max relative |parallel - serial| %.2e; at the end dust %.4e, broken %.4e m3"
      % (len(rs), rel, last["dust[m3]"], last["broken[m3]"]))
sys.exit(0 if worst <= 1e-9 and rel <= 1e-9 and last["broken[m3]"] >= last["dust[m3]"] > 0 else 1)
PY
}
