# shellcheck shell=bash
# The closed-box case tests/solver/closedBox (sourced by tests/run; tests
# solver/closedBox/*).

# Closed box (cyclic in x, walls elsewhere) with shear flow, percolation,
# kinetic sieving and diffusion, a partly empty initial state: mass of every
# species conserved to 1e-10 relative, 0 <= n_i <= phi at all times
test_closed_box()
{
    local dir="$workRoot/closedBox"
    rm -rf "$dir"; cp -r tests/solver/closedBox "$dir"
    blockMesh -case "$dir" > "$dir/log.blockMesh" 2>&1 || { cat "$dir/log.blockMesh"; return 1; }
    cp -r "$dir/0.orig" "$dir/0"
    setFields -case "$dir" > "$dir/log.setFields" 2>&1 || { cat "$dir/log.setFields"; return 1; }
    segregationDegradationFoam -case "$dir" > "$dir/log.solver" 2>&1 || { tail -30 "$dir/log.solver"; return 1; }
    python3 - "$dir/log.solver" <<'PY' || return 1
import re, sys
vols = {}
for line in open(sys.argv[1]):
    if line.startswith("Solids:"):
        for name, v in re.findall(r"(n\.\w+) volume (\S+)", line):
            vols.setdefault(name, []).append(float(v))
ok = True
for name, v in vols.items():
    rel = max(abs(x - v[0]) for x in v) / v[0]
    print("%s: initial volume %.12e, max relative change over %d steps %.2e" % (name, v[0], len(v), rel))
    ok &= rel < 1e-10
if not vols or len(next(iter(vols.values()))) < 10:
    print("too few steps parsed"); ok = False
sys.exit(0 if ok else 1)
PY
    python3 -m sdfoam.fieldStats "$dir" changed --tol 0.05 || return 1
    python3 -m sdfoam.fieldStats "$dir" bounds --tol 1e-8
}
