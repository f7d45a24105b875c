#!/usr/bin/env python3
"""The sheared cell under gravity against its LAMMPS peer (run writes the inputs).

Per seed: ours from DIR/seed<n>/ours-profiles.dat (block means and errors per layer)
and the diffusion lag from ours.log; LAMMPS' from its frames (DIR/seed<n>/frames.txt,
the flowing grains every 1000 steps) analysed exactly as ours measures: layers of
gap(t)/10 from the bottom wall's plane (the top plane moving with the rigid wall,
wall.txt), per frame the coarse and fine grains' volume-weighted mean v_y minus the
layer's, averaged over the frames of each of 5 blocks; D per species and layer from the
y displacements over the same lag as ours, origins every lag within a block, by the
layer at the origin, D = variance/(2 lag). Errors: block standard errors; a code's seed
mean carries the larger of sqrt(sum of squares)/n and the seeds' own scatter (the standard
error of the seeds' mean), since the blocks of one run share its trajectory.

Printed: per layer both codes' seed means and the difference in combined standard
errors; per code the seeds' own scatter; the interior (layers 2-7: two coarse diameters
from the walls) means as the comparison's summary, and the chi-square of all per-layer
differences (the sound form of "within 2 combined errors" over many layers: one in
twenty exceeds 2 by chance).

Usage: analyse.py DIR seed...
"""
import math
import re
import sys

LAYERS = 10
BLOCKS = 5
QUANTITIES = ["wCoarse", "wFine", "Dcoarse", "Dfine"]
# columns of ours-profiles.dat (value, error)
OURS_COLUMNS = {"wCoarse": 11, "wFine": 13, "Dfine": 15, "Dcoarse": 17}


def mean_se(values):
    n = len(values)
    if n == 0:
        return float("nan"), float("nan")
    m = sum(values)/n
    if n < 2:
        return m, 0.0
    return m, math.sqrt(sum((v - m)**2 for v in values)/(n - 1)/n)


def ours(directory):
    lag = None
    planes = None
    for line in open(directory + "/ours.log"):
        m = re.search(r"diffusion lag ([0-9.eE+-]+) s", line)
        if m:
            lag = float(m.group(1))
        m = re.search(r"y_b ([0-9.eE+-]+) m, y_t ([0-9.eE+-]+) m", line)
        if m:
            planes = (float(m.group(1)), float(m.group(2)))
    rows = [list(map(float, l.split())) for l in open(directory + "/ours-profiles.dat") if not l.startswith("#")]
    if len(rows) != LAYERS or lag is None or planes is None:
        sys.exit("analyse: %s: expected %d layers, the lag and the planes" % (directory, LAYERS))
    result = {q: [(r[OURS_COLUMNS[q]], r[OURS_COLUMNS[q] + 1]) for r in rows] for q in QUANTITIES}
    return result, lag, planes


def lammps_frames(path):
    """Yields (step, {id: (type, radius, y, vy)})."""
    with open(path) as f:
        while True:
            line = f.readline()
            if not line:
                return
            if not line.startswith("ITEM: TIMESTEP"):
                continue
            step = int(f.readline())
            f.readline()
            n = int(f.readline())
            for _ in range(4):
                f.readline()
            header = f.readline().split()[2:]
            col = {name: k for k, name in enumerate(header)}
            atoms = {}
            for _ in range(n):
                v = f.readline().split()
                atoms[int(v[col["id"]])] = (int(v[col["type"]]), float(v[col["radius"]]), float(v[col["y"]]),
                                             float(v[col["vy"]]))
            yield step, atoms


def lammps(directory, lag, planes, dt=1e-6):
    yb, yt = planes
    ytop0 = None
    lines = open(directory + "/lammps.log").read().split("\n")
    for k, line in enumerate(lines):
        if line.split()[:3] == ["Step", "Time", "v_ytop"]:
            ytop0 = float(lines[k + 1].split()[2])
            break
    wall = {}
    for line in open(directory + "/wall.txt"):
        if line.startswith("#"):
            continue
        s, v = line.split()
        wall[int(s)] = float(v)
    frames = list(lammps_frames(directory + "/frames.txt"))
    if ytop0 is None or len(frames) < 2 * BLOCKS:
        sys.exit("analyse: %s: no thermo start or too few frames" % directory)
    # ours samples after the first interval of the sampling: the first frame is where the
    # sampling starts, the origin of the first block's displacements, not a sample
    origins = frames
    frames = frames[1:]
    every = frames[1][0] - frames[0][0]
    lag_frames = max(1, int(round(lag/(every*dt))))

    def layer_of(y, step):
        gap = yt + (wall[step] - ytop0) - yb
        return min(LAYERS - 1, max(0, int(math.floor((y - yb)/(gap/LAYERS)))))

    per_block = {q: [[] for _ in range(LAYERS)] for q in QUANTITIES}
    size = len(frames)//BLOCKS
    for b in range(BLOCKS):
        block = frames[b*size:(b + 1)*size]
        drift = {"wCoarse": [[] for _ in range(LAYERS)], "wFine": [[] for _ in range(LAYERS)]}
        for step, atoms in block:
            sums = [[0.0]*6 for _ in range(LAYERS)]   # v, v vy, vc, vc vy, vf, vf vy
            for t, r, y, vy in atoms.values():
                s = sums[layer_of(y, step)]
                v = r**3
                s[0] += v; s[1] += v*vy
                if t == 2:
                    s[2] += v; s[3] += v*vy
                else:
                    s[4] += v; s[5] += v*vy
            for l, s in enumerate(sums):
                if s[0] <= 0:
                    continue
                mean = s[1]/s[0]
                if s[2] > 0:
                    drift["wCoarse"][l].append(s[3]/s[2] - mean)
                if s[4] > 0:
                    drift["wFine"][l].append(s[5]/s[4] - mean)
        for q in drift:
            for l in range(LAYERS):
                per_block[q][l].append(sum(drift[q][l])/len(drift[q][l]) if drift[q][l] else 0.0)
        tally = {t: [[0, 0.0, 0.0] for _ in range(LAYERS)] for t in (1, 2)}
        # as ours: origins every lag from the block's start (the frame before its first
        # sample), each displacement over one lag within the block
        for k in range(b*size, (b + 1)*size - lag_frames + 1, lag_frames):
            step0, a0 = origins[k]
            _, a1 = origins[k + lag_frames]
            for i, (t, r, y, vy) in a0.items():
                dy = a1[i][2] - y
                c = tally[t][layer_of(y, step0)]
                c[0] += 1; c[1] += dy; c[2] += dy*dy
        tau = lag_frames*every*dt
        for t, q in ((1, "Dfine"), (2, "Dcoarse")):
            for l in range(LAYERS):
                n, s1, s2 = tally[t][l]
                per_block[q][l].append((s2/n - (s1/n)**2)/(2*tau) if n > 1 else 0.0)
    return {q: [mean_se(per_block[q][l]) for l in range(LAYERS)] for q in QUANTITIES}


def seed_mean(per_seed, q, l):
    """The seeds' mean, its error and the seeds' spread (largest - smallest). The error is
    the larger of the blocks' (sqrt(sum of squares)/n) and the seeds' own scatter (the
    standard error of the seeds' mean): blocks of one run share its trajectory (where the
    shear band sits), so they understate what a second seed shows."""
    values = [s[q][l][0] for s in per_seed]
    errors = [s[q][l][1] for s in per_seed]
    n = len(values)
    mean = sum(values)/n
    blocks = math.sqrt(sum(e*e for e in errors))/n
    seeds = math.sqrt(sum((v - mean)**2 for v in values)/(n - 1)/n) if n > 1 else 0.0
    return mean, max(blocks, seeds), (max(values) - min(values))


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    directory, seeds = sys.argv[1], sys.argv[2:]
    codes = {"ours": [], "LAMMPS": []}
    for seed in seeds:
        d = "%s/seed%s" % (directory, seed)
        o, lag, planes = ours(d)
        codes["ours"].append(o)
        codes["LAMMPS"].append(lammps(d, lag, planes))
    print("# sheared cell under gravity against LAMMPS: %s seeds, %d layers, interior 2-7" % (len(seeds), LAYERS))
    print("# per layer: seed means (value +- error) and the difference in combined standard errors z;"
          " spread: the two seeds' difference in each code")
    chi2, dof, worst = 0.0, 0, 0.0
    for q in QUANTITIES:
        print("\n## %s [%s]" % (q, "m/s" if q.startswith("w") else "m2/s"))
        print("# layer ours ours_err ours_seedSpread LAMMPS LAMMPS_err LAMMPS_seedSpread z"
              " (err: the larger of the blocks' error and the seeds' scatter)")
        for l in range(LAYERS):
            a, sa, da = seed_mean(codes["ours"], q, l)
            b, sb, db = seed_mean(codes["LAMMPS"], q, l)
            z = (a - b)/math.sqrt(sa*sa + sb*sb) if sa*sa + sb*sb > 0 else float("nan")
            if z == z:
                chi2 += z*z; dof += 1; worst = max(worst, abs(z))
            print("%d %.4g %.2g %.2g %.4g %.2g %.2g %+.2f" % (l, a, sa, da, b, sb, db, z))
    print("\n# interior (layers 2-7) means: ours, LAMMPS, z")
    for q in QUANTITIES:
        vals = {}
        for code in codes:
            ms = [seed_mean(codes[code], q, l) for l in range(2, 8)]
            vals[code] = (sum(m[0] for m in ms)/len(ms), math.sqrt(sum(m[1]**2 for m in ms))/len(ms))
        (a, sa), (b, sb) = vals["ours"], vals["LAMMPS"]
        print("%s %.4g +- %.2g  %.4g +- %.2g  z %+.2f" % (q, a, sa, b, sb, (a - b)/math.sqrt(sa*sa + sb*sb)))
    # chi-square's upper tail by the Wilson-Hilferty normal approximation
    x = ((chi2/dof)**(1.0/3) - (1 - 2.0/(9*dof)))/math.sqrt(2.0/(9*dof))
    p = 0.5*math.erfc(x/math.sqrt(2))
    print("# all layers: chi-square %.1f over %d differences (p %.2f), the largest |z| %.2f" % (chi2, dof, p, worst))


if __name__ == "__main__":
    main()
