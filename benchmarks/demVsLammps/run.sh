#!/usr/bin/env bash
#------------------------------------------------------------------------------
# benchmarks/demVsLammps/run.sh
#
# The same Lees-Edwards sheared bidisperse cell (N, phi, contact law, e, mu, dt,
# gammaDot, initial state) run in Debian's LAMMPS (lmp, pair granular) and in
# our periodicDEM-cli; reports the steady granular temperature of both and the
# throughput (particle-steps per second, one core) as a ratio.
#
#   benchmarks/demVsLammps/run.sh [N] [equilibrationSteps] [runSteps]
#
# Needs: build/calibration (cmake -S calibration -B build/calibration ...) and lmp
# (etc/bootstrap installs lammps). Results go to build/benchmarks/demVsLammps/.
# Environment: SDF_DEM_CLI (another periodicDEM-cli, e.g. of a second build tree),
# SDF_DEM_BENCH_OUT (another output folder, so two runs do not share one).
#------------------------------------------------------------------------------
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
here="$root/benchmarks/demVsLammps"
out="${SDF_DEM_BENCH_OUT:-$root/build/benchmarks/demVsLammps}"
cli="${SDF_DEM_CLI:-$root/build/calibration/apps/periodicDEM-cli}"
mkdir -p "$out"

N=${1:-3000}
nEquil=${2:-30000}
nRun=${3:-40000}

# the cell (SI): fines 1 mm, coarse 2 mm, equal solids volume, phi 0.5
kn=2000; e=0.7; mu=0.5; ktRatio=0.2857142857142857; xgammat=0.5
gd=100; dt=1e-6; skin=3e-4

[ -x "$cli" ] || { echo "build calibration first: $cli missing" >&2; exit 1; }
command -v lmp >/dev/null || { echo "lmp not found (apt-get install lammps)" >&2; exit 1; }

cat > "$out/cell.cfg" <<CFG
species = fine:0.001:2500 coarse:0.002:2500
volumeFractions = 0.5 0.5
particles = $N
solidsFraction = 0.5
mode = leesEdwards
shearRate = $gd
model = linearSpringDashpot
restitution = $e
friction = $mu
normalStiffness = $kn
tangentialStiffnessRatio = $ktRatio
tangentialDampingRatio = $xgammat
timeStep = $dt
skin = $skin
seed = 1
sampleEvery = 100
blocks = 4
throughputOnly = 1
CFG

# equilibration in the CLI: at least nEquil steps (T windows checked for a steady state)
tEquil=$(awk -v n=$nEquil -v dt=$dt 'BEGIN{printf "%.10g", n*dt}')
tRun=$(awk -v n=$nRun -v dt=$dt 'BEGIN{printf "%.10g", n*dt}')

echo "== ours, 1 thread"
OMP_NUM_THREADS=1 "$cli" "$out/cell.cfg" threads=1 equilibrationTime=$tEquil \
    maxEquilibrationTime=$tEquil samplingTime=$tRun lammpsData="$out/cell.data" \
    | tee "$out/ours-1thread.log"
echo "== ours, 2 threads"
OMP_NUM_THREADS=2 "$cli" "$out/cell.cfg" threads=2 equilibrationTime=$tEquil \
    samplingTime=$tRun | tee "$out/ours-2threads.log"

echo "== LAMMPS, 1 process"
kt=$(awk -v k=$kn -v r=$ktRatio 'BEGIN{printf "%.10g", k*r}')
# constant dashpots per type pair: gamma_n = -2 ln(e) sqrt(m* kn)/sqrt(pi^2 + ln^2 e)
read -r g11 g12 g22 <<<"$(awk -v k=$kn -v e=$e 'BEGIN{
    pi = 3.141592653589793; le = log(e)
    mf = 2500*pi/6*1e-9; mc = 2500*pi/6*8e-9
    c = -2*le/sqrt(pi*pi + le*le)
    printf "%.10g %.10g %.10g", c*sqrt(mf/2*k), c*sqrt(mf*mc/(mf + mc)*k), c*sqrt(mc/2*k) }')"

(cd "$out" && OMP_NUM_THREADS=1 lmp -in "$here/in.shear" -log lammps.log -screen none \
    -var data cell.data -var kn $kn -var g11 $g11 -var g12 $g12 -var g22 $g22 \
    -var kt $kt -var xgammat $xgammat \
    -var mu $mu -var gd $gd -var dt $dt -var skin $skin \
    -var nequil $nEquil -var nrun $nRun)

python3 - "$out" "$N" "$nRun" <<'PY'
import re, sys
out, N, nRun = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
def ours(name):
    text = open(f"{out}/{name}").read()
    T = float(re.search(r"T = ([0-9.eE+-]+) \+- ([0-9.eE+-]+)", text).group(1))
    Terr = float(re.search(r"T = ([0-9.eE+-]+) \+- ([0-9.eE+-]+)", text).group(2))
    rate = float(re.search(r"throughput ([0-9.eE+-]+) particle-steps/s", text).group(1))
    cpu = float(re.search(r"CPU use ([0-9.eE+-]+) %", text).group(1))
    return T, Terr, rate, cpu
T1, T1err, rate1, cpu1 = ours("ours-1thread.log")
T2, T2err, rate2, cpu2 = ours("ours-2threads.log")
log = open(f"{out}/lammps.log").read()
loops = re.findall(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", log)
loopTime, procs, steps, atoms = loops[-1]
cpu = float(re.findall(r"([0-9.]+)% CPU use", log)[-1])
lammpsRate = int(steps)*int(atoms)/float(loopTime)
# T from the thermo lines of the production run (second run block)
blocks = log.split("Loop time of")
prod = blocks[-2].split("Step")[-1].splitlines()[1:]
vals = [float(l.split()[2]) for l in prod if len(l.split()) == 3 and l.split()[0].isdigit()]
vals = vals[1:]
mean = sum(vals)/len(vals)
nb = max(2, min(4, len(vals))); m = len(vals)//nb
bm = [sum(vals[k*m:(k+1)*m])/m for k in range(nb)]
err = (sum((b-mean)**2 for b in bm)/(nb*(nb-1)))**0.5
gdd = 100*1.5e-3
report = f"""N = {N}, phi = 0.5, fines 1 mm / coarse 2 mm (equal solids volume), e = 0.7, mu = 0.5,
kn = 2000 N/m, dt = 1e-6 s, gammaDot = 100 1/s, {nRun} production steps
T (m2/s2, sum of 3 components):  ours {T1:.5g} +- {T1err:.2g}   LAMMPS {mean:.5g} +- {err:.2g}
T / (gammaDot d_mean)^2:          ours {T1/gdd**2:.4g}            LAMMPS {mean/gdd**2:.4g}
throughput (particle-steps/s, 1 core, wall clock): ours {rate1:.4g} ({cpu1:.0f} % CPU use)   LAMMPS {lammpsRate:.4g} ({cpu:.0f} % CPU use)   ratio {rate1/lammpsRate:.3g}
throughput per CPU second (load-corrected):       ours {rate1/(cpu1/100):.4g}   LAMMPS {lammpsRate/(cpu/100):.4g}   ratio {rate1/(cpu1/100)/(lammpsRate/(cpu/100)):.3g}
ours on 2 threads: {rate2:.4g} particle-steps/s wall clock ({cpu2:.0f} % CPU use; speed-up {rate2/rate1:.3g} on the shared 2-core machine)
"""
print(report)
open(f"{out}/report.txt", "w").write(report)
PY
