#!/usr/bin/env bash
#------------------------------------------------------------------------------
# benchmarks/demVsLammps/run.sh
#
# The same Lees-Edwards sheared bidisperse cell (N, phi, contact law, e, mu, dt,
# gammaDot, initial state) run in Debian's LAMMPS (lmp, pair granular) and in
# our periodicDEM-cli; reports the steady granular temperature of both and the
# throughput (particle-steps per second, one core) as a ratio.
#
#   benchmarks/demVsLammps/run.sh [N] [equilibrationSteps] [runSteps] [rounds] [roundSteps]
#
# Also: D_yy of both species from the y mean-square displacement (LAMMPS: compute msd per
# type over 8 segments of runSteps/8 after the production run; ours: periodicDEM-cli's
# 4-block MSD with lags up to runSteps/8, same fit window) and the 2-thread speed-up
# (periodicDEM-cli threadScalingRounds: the same equilibrated state on 1 and 2 threads,
# alternately, `rounds` times).
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
rounds=${4:-5}         # thread-scaling rounds (1 and 2 threads from the same state)
nRound=${5:-20000}     # steps per run in each round

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
echo "== ours, 1 thread, with measurements (D from the y MSD and Green-Kubo, 4 blocks)"
OMP_NUM_THREADS=1 "$cli" "$out/cell.cfg" threads=1 equilibrationTime=$tEquil \
    maxEquilibrationTime=$tEquil samplingTime=$tRun throughputOnly=0 \
    | tee "$out/ours-measured.log"
echo "== ours, 2-thread speed-up: the equilibrated state run on 1 and on 2 threads, alternately"
tRound=$(awk -v n=$nRound -v dt=$dt 'BEGIN{printf "%.10g", n*dt}')
OMP_NUM_THREADS=2 "$cli" "$out/cell.cfg" threads=2 equilibrationTime=$tEquil \
    maxEquilibrationTime=$tEquil samplingTime=$tRound threadScalingRounds=$rounds \
    progressEvery=100000000 | tee "$out/ours-2threads.log"

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
    -var nequil $nEquil -var nrun $nRun -var nseg $((nRun/8)))

python3 - "$out" "$N" "$nRun" <<'PY'
import re, sys, statistics
out, N, nRun = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
def ours(name):
    text = open(f"{out}/{name}").read()
    T = float(re.search(r"T = ([0-9.eE+-]+) \+- ([0-9.eE+-]+)", text).group(1))
    Terr = float(re.search(r"T = ([0-9.eE+-]+) \+- ([0-9.eE+-]+)", text).group(2))
    rate = float(re.search(r"throughput ([0-9.eE+-]+) particle-steps/s", text).group(1))
    cpu = float(re.search(r"CPU use ([0-9.eE+-]+) %", text).group(1))
    return T, Terr, rate, cpu
T1, T1err, rate1, cpu1 = ours("ours-1thread.log")
# our D_yy (MSD, 4 blocks; Green-Kubo) per species
measured = open(f"{out}/ours-measured.log").read()
oursD = {}
for name, gk, gkErr, msd, msdErr in re.findall(
        r"^\s+(\w+) \(\d+\): T = [^,]+, D_GK = ([0-9.eE+-]+) \+- ([0-9.eE+-]+) m2/s[^,]*, "
        r"D_MSD = ([0-9.eE+-]+) \+- ([0-9.eE+-]+) m2/s", measured, re.M):
    oursD[name] = tuple(map(float, (gk, gkErr, msd, msdErr)))
# thread scaling rounds
scaling = open(f"{out}/ours-2threads.log").read()
rounds = [tuple(map(float, r)) for r in re.findall(
    r"^\s+1 thread ([0-9.eE+-]+), 2 threads ([0-9.eE+-]+) particle-steps/s", scaling, re.M)]
speedUps = sorted(b/a for a, b in rounds)
best = max(b for a, b in rounds)/max(a for a, b in rounds)

log = open(f"{out}/lammps.log").read()
loops = re.findall(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", log)
loopTime, procs, steps, atoms = loops[1]            # the production run
cpu = float(re.findall(r"([0-9.]+)% CPU use", log)[1])
lammpsRate = int(steps)*int(atoms)/float(loopTime)
# T from the thermo lines of the production run (second run block)
blocks = log.split("Loop time of")
prod = blocks[1].split("Step")[-1].splitlines()[1:]
vals = [float(l.split()[2]) for l in prod if len(l.split()) == 3 and l.split()[0].isdigit()]
vals = vals[1:]
mean = sum(vals)/len(vals)
nb = max(2, min(4, len(vals))); m = len(vals)//nb
bm = [sum(vals[k*m:(k+1)*m])/m for k in range(nb)]
err = (sum((b-mean)**2 for b in bm)/(nb*(nb-1)))**0.5

# LAMMPS D_yy: per segment, straight line through the y MSD over the last 60 % of the
# segment (our fit window), D = slope/2; mean and standard error over the 8 segments
def fitSlope(t, y):
    tm, ym = sum(t)/len(t), sum(y)/len(y)
    return sum((a - tm)*(b - ym) for a, b in zip(t, y))/sum((a - tm)**2 for a in t)
dt = 1e-6
lammpsD = {"fine": [], "coarse": []}
for k in range(1, 9):
    rows = [list(map(float, l.split())) for l in open(f"{out}/msd_{k}.txt")
            if l.strip() and not l.startswith("#")]
    # the segment's origin: the first row if it is the origin itself (MSD 0), else 100 before
    step0 = rows[0][0] if rows[0][1] == 0 and rows[0][2] == 0 else rows[0][0] - 100
    t = [(r[0] - step0)*dt for r in rows]
    tEnd = t[-1]
    sel = [i for i, x in enumerate(t) if x >= 0.4*tEnd]
    for col, name in ((1, "fine"), (2, "coarse")):
        lammpsD[name].append(fitSlope([t[i] for i in sel], [rows[i][col] for i in sel])/2)
def meanErr(v):
    return statistics.mean(v), statistics.stdev(v)/len(v)**0.5

gdd = 100*1.5e-3
lines = [f"""N = {N}, phi = 0.5, fines 1 mm / coarse 2 mm (equal solids volume), e = 0.7, mu = 0.5,
kn = 2000 N/m, dt = 1e-6 s, gammaDot = 100 1/s, {nRun} production steps
T (m2/s2, sum of 3 components):  ours {T1:.5g} +- {T1err:.2g}   LAMMPS {mean:.5g} +- {err:.2g}   difference {(T1-mean)/(T1err**2+err**2)**0.5:+.2f} combined sigma
T / (gammaDot d_mean)^2:          ours {T1/gdd**2:.4g}            LAMMPS {mean/gdd**2:.4g}"""]
for name in ("fine", "coarse"):
    gk, gkErr, msd, msdErr = oursD[name]
    lm, le = meanErr(lammpsD[name])
    lines.append(f"D_yy {name:6s} (m2/s): ours MSD {msd:.4g} +- {msdErr:.2g} (Green-Kubo {gk:.4g} +- {gkErr:.2g})   "
                 f"LAMMPS MSD {lm:.4g} +- {le:.2g}   difference {(msd-lm)/(msdErr**2+le**2)**0.5:+.2f} combined sigma")
lines.append(f"""throughput (particle-steps/s, 1 core, wall clock): ours {rate1:.4g} ({cpu1:.0f} % CPU use)   LAMMPS {lammpsRate:.4g} ({cpu:.0f} % CPU use)   ratio {rate1/lammpsRate:.3g}
throughput per CPU second (load-corrected):       ours {rate1/(cpu1/100):.4g}   LAMMPS {lammpsRate/(cpu/100):.4g}   ratio {rate1/(cpu1/100)/(lammpsRate/(cpu/100)):.3g}
ours, 2-thread speed-up over {len(rounds)} rounds (same state, 1 and 2 threads alternately): median {statistics.median(speedUps):.3g}, min {speedUps[0]:.3g}, max {speedUps[-1]:.3g}; best 2-thread / best 1-thread rate {best:.3g}
  rounds (1 thread, 2 threads particle-steps/s): {'; '.join(f'{a:.3g}, {b:.3g}' for a, b in rounds)}
""")
report = "\n".join(lines)
print(report)
open(f"{out}/report.txt", "w").write(report)
PY
