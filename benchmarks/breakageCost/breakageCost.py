#!/usr/bin/env python3
"""Side-by-side cost of the breakage population balance: ours vs v1912's.

See ./run. Per code and mesh: cpu seconds per step from the solver log's
ExecutionTime, (last - first)/(steps - 1) (the first value holds the
start-up), divided by classes and cells; the minimum over the rounds.
"""

import argparse
import os
import platform
import re
import shutil
import subprocess
import sys
import time

CLASSES = 29
STEPS = 100


def sh(cmd, cwd, log):
    with open(os.path.join(cwd, log), "w") as f:
        subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, check=True)


def cpuPerStep(logPath):
    text = open(logPath).read()
    ex = [float(x) for x in re.findall(r"ExecutionTime = ([0-9.eE+-]+) s", text)]
    if len(ex) < STEPS:
        raise SystemExit("breakageCost: %s has %d steps" % (logPath, len(ex)))
    return (ex[-1] - ex[0]) / (len(ex) - 1)


def runOurs(top, work, n):
    case = os.path.join(work, "ours%d" % n)
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(top, "validation", "breakageSingleCell"), case)
    sh(["./setup", "ziff", "--ratio", "1.5", "--classes", str(CLASSES), "--dt", "0.1",
        "--ddt", "Euler", "--cells", str(n)], case, "log.setup")
    sh(["blockMesh"], case, "log.blockMesh")
    sh(["segregationDegradationFoam"], case, "log.solver")
    return cpuPerStep(os.path.join(case, "log.solver"))


def runPeer(top, work, n):
    case = os.path.join(work, "peer%d" % n)
    shutil.rmtree(case, ignore_errors=True)
    peer = os.path.join(top, "validation", "breakagePeer", "peer")
    subprocess.run([sys.executable, os.path.join(peer, "makeCase.py"), case,
                    "--cells", str(n), "--write", "10"], check=True,
                   stdout=subprocess.DEVNULL)
    sh(["blockMesh"], case, "log.blockMesh")
    sh(["reactingMultiphaseEulerFoam"], case, "log.solver")
    return cpuPerStep(os.path.join(case, "log.solver"))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--top", required=True)
    p.add_argument("--meshes", default="10,20")
    p.add_argument("--rounds", type=int, default=3)
    a = p.parse_args()
    meshes = [int(m) for m in a.meshes.split(",")]
    work = os.path.join(a.top, "build", "benchmarks", "breakageCost")
    os.makedirs(work, exist_ok=True)

    best = {}
    t0 = time.time()
    for r in range(a.rounds):
        for n in meshes:
            for code, fn in (("ours", runOurs), ("peer", runPeer)):
                c = fn(a.top, work, n)
                key = (code, n)
                best[key] = min(best.get(key, float("inf")), c)
                print("round %d, %d^3 cells, %s: %.4e s/step (%.0f s elapsed)"
                      % (r + 1, n, code, c, time.time() - t0), flush=True)

    load = open("/proc/loadavg").read().split()[:3]
    here = os.path.dirname(os.path.abspath(__file__))
    lines = [
        "# breakageCost: %d classes, %d steps, minimum of %d alternating rounds" % (CLASSES, STEPS, a.rounds),
        "# %s, %s, load average at the end %s" % (platform.node(), time.strftime("%Y-%m-%d %H:%M"), " ".join(load)),
        "# cells  ours_s_per_step  peer_s_per_step  ours_per_class_cell_step  peer_per_class_cell_step  ratio_ours_over_peer",
    ]
    for n in meshes:
        o, q = best[("ours", n)], best[("peer", n)]
        cells = n ** 3
        lines.append("%d %.4e %.4e %.4e %.4e %.4f"
                     % (cells, o, q, o / CLASSES / cells, q / CLASSES / cells, o / q))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(here, "results.txt"), "w") as f:
        f.write(text)
    print(text)

    gp = """set terminal pngcairo size 800,500
set output '%s'
set logscale xy
set xlabel 'cells'
set ylabel 'cpu s per class, cell and step'
set key top right
set title 'Breakage population balance, 29 classes: cost per class per cell per step'
plot '%s' using 1:4 with linespoints pt 6 title 'segregationDegradationFoam', \\
     '' using 1:5 with linespoints pt 2 title 'OpenFOAM v1912 reactingMultiphaseEulerFoam'
""" % (os.path.join(a.top, "docs", "figures", "breakageCost.png"), os.path.join(here, "results.txt"))
    os.makedirs(os.path.join(a.top, "docs", "figures"), exist_ok=True)
    subprocess.run(["gnuplot"], input=gp.encode(), check=False)


if __name__ == "__main__":
    main()
