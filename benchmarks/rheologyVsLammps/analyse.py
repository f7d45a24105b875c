#!/usr/bin/env python3
"""Reads benchmarks/rheologyVsLammps/run's cells and prints the comparison table.

Ours: the rheology line of periodicDEM-cli's summary (block means over 8 blocks).
LAMMPS: segments.txt (segment means of sigma_yy, sigma_xy, phi, Z every nb steps over the
production), from the time at which ours was declared equilibrated on (LAMMPS equilibrates
for the fixed strain the script gives; ours goes on while T or phi still move, up to 3 x,
and at I 0.005 the stress ratio's transient after the compaction, 0.414 in LAMMPS' first
production quarter against 0.38-0.39 after it, lasted past LAMMPS' 4 strains), cut into
8 blocks; mu and I per block from the block's means, as ours.
Agreement: |ours - LAMMPS| against 2 combined standard errors, per seed and for the
seed means (whose error is the larger of the seeds' spread and their block errors).
"""
import glob, math, os, re, statistics, sys

out, inertial, seeds = sys.argv[1], sys.argv[2].split(), sys.argv[3].split()
rollings = sys.argv[4].split() if len(sys.argv) > 4 else ["0"]
rho, d, dt = 2500.0, 0.0015, 1e-6
NUM = r"([0-9.eE+-]+)"

def ours(path):
    text = open(path).read()
    m = re.search(r"sigma_yy = %s \+- %s Pa, mu = %s \+- %s, I = %s \+- %s .*?phi = %s \+- %s, "
                  r"Z = %s \+- %s" % ((NUM,)*10), text)
    if not m:
        raise SystemExit(f"{path}: no rheology line")
    v = list(map(float, m.groups()))
    steady = re.search(r"steady: (yes|NO)", text).group(1)
    m = re.search(r"equilibrated: (\S+) after ([0-9.eE+-]+) s", text)
    # not equilibrated within its limit: LAMMPS is sampled over its whole production
    equilibrated = float(m.group(2)) if m.group(1) == "yes" else 0.0
    return {"equilibrated": equilibrated, "equilibratedText": m.group(1),"p": (v[0], v[1]), "mu": (v[2], v[3]), "I": (v[4], v[5]), "phi": (v[6], v[7]),
            "Z": (v[8], v[9]), "steady": steady}

def lag1(values):
    """Lag-1 autocorrelation of a series (a barostat that rings makes it negative)."""
    m = statistics.fmean(values)
    num = sum((a - m)*(b - m) for a, b in zip(values, values[1:]))
    den = sum((a - m)**2 for a in values)
    return num/den if den > 0 else 0.0

def lammps(path, gd, start):
    """segments.txt from time `start` [s] on (its first column: the step)."""
    rows = [list(map(float, l.split())) for l in open(path) if l.strip() and not l.startswith("#")]
    rows = [r for r in rows if r[0]*dt > start]
    n = len(rows) // 8
    blocks = []
    for b in range(8):
        part = rows[b*n:(b + 1)*n]
        p = statistics.fmean(r[1] for r in part)
        tau = abs(statistics.fmean(r[2] for r in part))
        blocks.append({"p": p, "mu": tau/p, "I": gd*d/math.sqrt(p/rho),
                       "phi": statistics.fmean(r[3] for r in part),
                       "Z": statistics.fmean(r[4] for r in part)})
    est = {"phiLag1": (lag1([r[3] for r in rows]), 0.0)}
    for k in blocks[0]:
        vals = [b[k] for b in blocks]
        est[k] = (statistics.fmean(vals), statistics.stdev(vals)/math.sqrt(len(vals)))
    return est

def combine(estimates):
    """Mean of the seeds; error: the larger of their spread's and their block errors'."""
    vals = [e[0] for e in estimates]
    spread = statistics.stdev(vals)/math.sqrt(len(vals)) if len(vals) > 1 else 0.0
    blockErr = math.sqrt(sum(e[1]**2 for e in estimates))/len(estimates)
    return statistics.fmean(vals), max(spread, blockErr), spread

print("Pressure-controlled sheared cell: ours (periodicDEM-cli) against LAMMPS, same cells")
print("columns: quantity, ours +- block error, LAMMPS +- block error, difference / combined"
      " standard error")
worst = 0.0
table = []
for I, muR in [(I, m) for m in rollings for I in inertial]:
    gd = float(I)*math.sqrt(1333/rho)/d
    o, l = {}, {}
    for seed in seeds:
        tag = f"I{I}-seed{seed}-muR{muR}"
        o[seed] = ours(os.path.join(out, tag, "ours.log"))
        l[seed] = lammps(os.path.join(out, tag, "segments.txt"), gd, o[seed]["equilibrated"])
        print(f"\nI target {I}, mu_r {muR}, seed {seed} (ours steady: {o[seed]['steady']},"
              f" equilibrated: {o[seed]['equilibratedText']}):")
        for k in ("p", "mu", "phi", "I", "Z"):
            a, b = o[seed][k], l[seed][k]
            sigma = math.hypot(a[1], b[1])
            z = abs(a[0] - b[0])/sigma if sigma > 0 else float("inf")
            print(f"  {k:4s} {a[0]:.5g} +- {a[1]:.2g}   {b[0]:.5g} +- {b[1]:.2g}   {z:.2f}")
        print(f"  LAMMPS phi per barostat segment: lag-1 autocorrelation {l[seed]['phiLag1'][0]:.2f}"
              " (a ringing barostat makes it negative)")
    print(f"I target {I}, mu_r {muR}, seeds combined (the error: max of the seeds' spread and"
          " block errors):")
    row = [I, muR]
    for k in ("mu", "phi"):
        a = combine([o[s][k] for s in seeds])
        b = combine([l[s][k] for s in seeds])
        sigma = math.hypot(a[1], b[1])
        z = abs(a[0] - b[0])/sigma
        worst = max(worst, z)
        row += [a, b, z]
        print(f"  {k:4s} ours {a[0]:.5g} +- {a[1]:.2g} (seed spread {a[2]:.2g})   LAMMPS "
              f"{b[0]:.5g} +- {b[1]:.2g} (seed spread {b[2]:.2g})   {z:.2f} combined s.e."
              f"  {'within 2' if z <= 2 else 'OUTSIDE 2'}")
    table.append(row)
print("\nsummary (seed means): I, mu_r | mu ours, LAMMPS, sigmas | phi ours, LAMMPS, sigmas")
for I, muR, mo, ml, mz, po, pl, pz in table:
    print(f"  {I:6s} {muR:4s} | {mo[0]:.4f}+-{mo[1]:.4f} {ml[0]:.4f}+-{ml[1]:.4f} {mz:.2f}"
          f" | {po[0]:.4f}+-{po[1]:.4f} {pl[0]:.4f}+-{pl[1]:.4f} {pz:.2f}")
print(f"\nlargest difference of the seed means (mu, phi over all I and mu_r): {worst:.2f}"
      " combined s.e.")

def lammpsRate(path):
    """Particle-steps per second of a LAMMPS log: the sum of its loop times over the
    barostat's segments (the set-ups of its runs between them left out)."""
    log = open(path).read()
    loops = [(float(t), int(s), int(a)) for t, s, a in re.findall(
        r"Loop time of %s on \d+ procs for (\d+) steps with (\d+) atoms" % NUM, log)]
    return sum(s for _, s, _ in loops)*loops[0][2]/sum(t for t, _, _ in loops), len(loops)


tp = os.path.join(out, "throughput")
rounds = sorted(glob.glob(os.path.join(tp, "round*")), key=lambda d: int(d.rsplit("round", 1)[1]))
if rounds:
    print("\nthroughput at I 0.2, one core each, in rounds (ours, then LAMMPS as in the physics"
          " runs: newton off, <sigma_yy> every step; then LAMMPS at its fastest: newton on,"
          " <sigma_yy> every 10 steps as ours) [particle-steps/s]:")
    print("  round  ours        LAMMPS physics  ratio   LAMMPS fastest  ratio")
    ratios = {"physics": [], "fastest": []}
    for d in rounds:
        text = open(os.path.join(d, "ours.log")).read()
        ours = float(re.search(r"throughput %s particle-steps/s" % NUM, text).group(1))
        row = f"  {os.path.basename(d)[5:]:5s}  {ours:.4g}"
        for name in ("physics", "fastest"):
            rate, segments = lammpsRate(os.path.join(d, f"lammps-{name}.log"))
            ratios[name].append(ours/rate)
            row += f"   {rate:.4g} ({segments} segments)  {ours/rate:.2f}"
        print(row)
    for name in ("physics", "fastest"):
        r = sorted(ratios[name])
        print(f"  median ratio against LAMMPS {name}: {statistics.median(r):.2f}"
              f" (range {r[0]:.2f}-{r[-1]:.2f}, {len(r)} rounds)")
