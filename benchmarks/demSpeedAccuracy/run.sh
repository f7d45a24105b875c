#!/usr/bin/env bash
#------------------------------------------------------------------------------
# benchmarks/demSpeedAccuracy/run.sh
#
# Speed vs accuracy at one reference condition (calibration/apps/sheared.cfg: 2:1,
# 40 % coarse, phi 0.5, e 0.7, mu 0.5, gammaDot 100 1/s): Green-Kubo D_yy of the fines
# for several N and run lengths (strain) against a reference run of the largest N,
# 10 x the longest strain. Single thread.
#
#   benchmarks/demSpeedAccuracy/run.sh ["500 1000 2000 4000 8000"] ["5 10 20"] [referenceN]
#
# The engine binary is copied first, so a rebuild during the (long) run does not mix
# two engine versions in one table. The reference runs on SDF_DEM_REFERENCE_THREADS
# threads (default 2): trajectories do not depend on the thread count (dem.reproducibility),
# only its CPU time does (reported as measured).
#------------------------------------------------------------------------------
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
out="$root/build/benchmarks/demSpeedAccuracy"
cfg="$root/calibration/apps/sheared.cfg"
mkdir -p "$out"
cp "$root/build/calibration/apps/periodicDEM-cli" "$out/periodicDEM-cli"
cli="$out/periodicDEM-cli"
git -C "$root" rev-parse --short HEAD > "$out/engineCommit"
Ns=(${1:-500 1000 2000 4000 8000})
strains=(${2:-5 10 20})
refN=${3:-8000}
gd=100
longest=${strains[-1]}

refThreads=${SDF_DEM_REFERENCE_THREADS:-2}

run() {  # N strain tag [threads]
    local t; t=$(awk -v s=$2 -v g=$gd 'BEGIN{printf "%.6g", s/g}')
    /usr/bin/time -f "%U %S" -o "$out/$3.time" "$cli" "$cfg" threads=${4:-1} particles=$1 \
        samplingTime=$t progressEvery=0 > "$out/$3.log"
}
parse() {  # tag -> D err cpu
    python3 - "$out/$1.log" "$out/$1.time" <<'PY'
import re, sys
t = open(sys.argv[1]).read()
m = re.search(r"fine \(\d+\): T = [0-9.eE+-]+, D_GK = ([0-9.eE+-]+) \+- ([0-9.eE+-]+)", t)
u, s = map(float, open(sys.argv[2]).read().split()[-2:])
print(m.group(1), m.group(2), u + s)
PY
}

run $refN $((10*longest)) reference $refThreads
read -r Dref Eref Cref <<<"$(parse reference)"
report="$out/report.txt"
{
echo "engine commit $(cat "$out/engineCommit")"
echo "reference: N = $refN, strain $((10*longest)), $refThreads thread(s): D_fine = $Dref +- $Eref m2/s (CPU $Cref s)"
printf "%-6s %-7s %-12s %-10s %-9s %-8s\n" N strain D_fine stderr "err/ref" "CPU[s]"
} > "$report"
for N in "${Ns[@]}"; do
  for s in "${strains[@]}"; do
    run $N $s "N${N}_s${s}"
    read -r D E C <<<"$(parse N${N}_s${s})"
    awk -v N=$N -v s=$s -v D=$D -v E=$E -v C=$C -v R=$Dref \
        'BEGIN{printf "%-6d %-7d %-12.5g %-10.2g %-+9.3f %-8.1f\n", N, s, D, E, D/R-1, C}' >> "$report"
    tail -1 "$report"
  done
done
cat "$report"
