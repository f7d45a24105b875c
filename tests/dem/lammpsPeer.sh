# shellcheck shell=bash
# Our DEM against LAMMPS on a small sheared cell (sourced by tests/run; test
# dem/lammpsPeer/pairRestitution): benchmarks/demVsLammps/run, shortened, with a
# restitution per species pair (e_ff 0.9, e_fc 0.7, e_cc 0.5) set from the same
# values in both codes. Both codes are deterministic, so the comparison gives the
# same figures at every run on one machine.

# T of the mixture and of each species, and D_yy of the fines, within 3 combined
# standard errors of LAMMPS (the benchmark's N 3000 figures: docs/benchmarks.md)
test_lammps_peer_pair_restitution()
{
    local out="$workRoot/lammpsPeer"
    rm -rf "$out"
    command -v lmp > /dev/null || { echo "lmp not found (etc/bootstrap installs lammps)"; return 1; }
    SDF_DEM_BENCH_OUT="$out" SDF_DEM_BENCH_RESTITUTION="0.9 0.7 0.5" \
        "$projectDir/benchmarks/demVsLammps/run" 500 20000 100000 1 1000 > "$out.log" 2>&1 \
        || { tail -20 "$out.log"; return 1; }
    python3 - "$out/results.txt" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
print(text)
checks = {
    "T": r"^T \(m2/s2, sum of 3 components\):.*difference (\S+) combined sigma",
    "T fine": r"^T fine .*difference (\S+) combined sigma",
    "T coarse": r"^T coarse .*difference (\S+) combined sigma",
    "D_yy fine": r"^D_yy fine .*difference (\S+) combined sigma",
}
bad = []
for name, pattern in checks.items():
    m = re.search(pattern, text, re.M)
    if not m:
        bad.append("%s: not in the report" % name)
    elif abs(float(m.group(1))) > 3:
        bad.append("%s: %s combined sigma from LAMMPS" % (name, m.group(1)))
print("\n".join(bad) if bad else "T, T per species and D_yy of the fines within 3 combined sigma of LAMMPS")
sys.exit(1 if bad else 0)
PY
}
