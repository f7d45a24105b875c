#!/usr/bin/env python3
"""Calibration cost versus the uncertainty it leaves in the silo2D outlet composition.

For a ladder of DEM calibration settings (particles per cell, sampling time,
replicas) over silo2D's envelope (tutorials/silo2D/Allrun -calibrated: phi 0.2
0.35 0.5, x 0.2 0.4, T 0.001 0.005 0.02, the seed's 2:1 species), this script

1. runs calibrateGranularMixture (one DEM thread per condition) and measures
   its CPU time (user + sys of the process and its children);
2. runs silo2D (30 s of discharge) with each setting's fitted diffusivity law
   and records the coarse mass fraction at the outlet, M(t);
3. at the reference (the most expensive setting) computes the sensitivity
   g_k(t) = dM/dp_k of the outlet history to each law parameter by one-sided
   finite differences (one solver run per parameter, step = the reference's
   standard error), so that every setting's statistical uncertainty follows
   from its covariance C: sigma_M(t) = sqrt(g(t)^T C g(t)) (linear
   propagation, i.e. the spread of solver runs at parameters +- 1 sigma);
4. reports, per setting: CPU seconds, the fitted parameters with errors,
   max_t sigma_M (statistical), max_t |M - M_ref| (deviation from the
   reference calibration: bias of short sampling + noise), and writes
   results.txt, results.dat and a PNG (gnuplot).

The engine binaries are copied first (a rebuild during the run does not mix
versions). Output: build/benchmarks/calibrationCost/. Takes ~30-40 min on one
core: a benchmark, not a test.

    benchmarks/calibrationCost/run.py [--only TAG ...] [--endTime 30]
"""

import argparse
import json
import math
import os
import re
import resource
import shutil
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
OUT = os.path.join(ROOT, "build", "benchmarks", "calibrationCost")

# tag: particles, samplingTime [s], replicas; the last one is the reference
SETTINGS = [
    ("N200_s0.02_r1", 200, 0.02, 1),
    ("N300_s0.05_r1", 300, 0.05, 1),   # silo2D/Allrun -calibrated before this study
    ("N300_s0.1_r2", 300, 0.1, 2),
    ("N300_s0.2_r1", 300, 0.2, 1),
    ("N600_s0.2_r1", 600, 0.2, 1),
    ("N600_s0.4_r1", 600, 0.4, 1),     # reference
]
PARAMS = ["A", "a", "m", "b"]


def sh(cmd, cwd, log):
    """Run cmd, return (wall, cpu) seconds of it and its children."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.time()
    with open(log, "w") as f:
        rc = subprocess.call(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT)
    wall = time.time() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if rc != 0:
        sys.exit("failed (%d): %s, see %s" % (rc, " ".join(cmd), log))
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def foam_set(path, entry, value):
    subprocess.check_call(["foamDictionary", "-entry", entry, "-set", value, path],
                          stdout=subprocess.DEVNULL)


def read_law(path):
    """D law of a granularCoefficients file: parameters, errors, covariance."""
    text = open(path).read()
    block = text[text.index("\nD\n"):]
    block = block[:block.index("\n}\n")]
    law = re.search(r"\blaw\s+(\w+);", block).group(1)
    if law != "powerLaw":
        sys.exit("%s: chosen law %s, this study propagates powerLaw" % (path, law))
    value = {p: float(re.search(r"\n\s+%s\s+([-+0-9.eE]+);" % p, block).group(1))
             for p in PARAMS}
    errs = block[block.index("errors"):]
    error = {p: float(re.search(r"\n\s+%s\s+([-+0-9.eE]+);" % p, errs).group(1))
             for p in PARAMS}
    cov_text = re.search(r"covariance\s+\((.*)\);", block).group(1)
    cov = [[float(v) for v in row.split()] for row in re.findall(r"\(([^()]*)\)", cov_text)]
    return {"law": law, "value": value, "error": error, "cov": cov}


def write_law(src, dst, changes):
    """Copy granularCoefficients src to dst with parameters changed."""
    text = open(src).read()
    head, rest = text.split("\nD\n", 1)
    body, tail = rest.split("\n}\n", 1)
    for p, v in changes.items():
        body = re.sub(r"(\n\s+%s\s+)([-+0-9.eE]+);" % p, r"\g<1>%.10g;" % v, body, count=1)
    open(dst, "w").write(head + "\nD\n" + body + "\n}\n" + tail)


def calibrate(tag, particles, sampling, replicas, bindir):
    case = os.path.join(OUT, tag, "calibration")
    done = os.path.join(case, "constant", "granularCoefficients")
    stamp = os.path.join(OUT, tag, "calibration.json")
    if os.path.exists(done) and os.path.exists(stamp):
        return json.load(open(stamp))
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(os.path.join(case, "constant"))
    shutil.copytree(os.path.join(ROOT, "tutorials", "calibration", "binary21", "system"),
                    os.path.join(case, "system"))
    shutil.copy(os.path.join(ROOT, "tutorials", "silo2D", "constant", "granularProperties"),
                os.path.join(case, "constant"))
    d = os.path.join(case, "system", "calibrationDict")
    foam_set(d, "phi", "(0.2 0.35 0.5)")
    foam_set(d, "T", "(0.001 0.005 0.02)")
    foam_set(d, "samplingTime", str(sampling))
    foam_set(d, "particles", str(particles))
    foam_set(d, "replicas", "(%s)" % " ".join(str(i + 1) for i in range(replicas)))
    foam_set(d, "threads", "1")
    foam_set(d, "plot", "false")
    wall, cpu = sh([os.path.join(bindir, "calibrateGranularMixture"), "-case", case],
                   case, os.path.join(OUT, tag, "log.calibrateGranularMixture"))
    log = open(os.path.join(OUT, tag, "log.calibrateGranularMixture")).read()
    result = {"wall": wall, "cpu": cpu, "conditions": 18 * replicas,
              "noPlateau": log.count("no plateau")}
    json.dump(result, open(stamp, "w"))
    return result


def outlet_history(case):
    """(t, coarse mass fraction) from results/outletComposition.dat."""
    path = os.path.join(case, "results", "outletComposition.dat")
    lines = [l for l in open(path) if l.strip()]
    header = lines[0].lstrip("#").split()
    col = header.index("massFraction.coarse")
    t, m = [], []
    for l in lines[1:]:
        if l.startswith("#"):
            continue
        v = l.split()
        t.append(float(v[0]))
        m.append(float(v[col]))
    return t, m


def resample(t, m, grid):
    out, j = [], 0
    for g in grid:
        while j + 1 < len(t) and t[j + 1] < g:
            j += 1
        if j + 1 >= len(t):
            out.append(m[-1])
        elif g <= t[0]:
            out.append(m[0])
        else:
            w = (g - t[j])/(t[j + 1] - t[j])
            out.append((1 - w)*m[j] + w*m[j + 1])
    return out


def silo(name, coefficients, end_time, grid):
    case = os.path.join(OUT, "silo", name)
    cache = case + ".json"
    if os.path.exists(cache):
        return json.load(open(cache))
    shutil.rmtree(case, ignore_errors=True)
    def not_results(folder, names):
        return [n for n in names
                if re.fullmatch(r"[0-9.e+-]+", n) or n.startswith(("processor", "log."))
                or n in ("postProcessing", "results", "calibration")]
    shutil.copytree(os.path.join(ROOT, "tutorials", "silo2D"), case, ignore=not_results)
    shutil.copy(coefficients, os.path.join(case, "constant", "granularCoefficients.shipped"))
    sh(["./Allrun", "-calibrated", "-quick", "-endTime", str(end_time)], case,
       case + ".log")    # Allclean removes log.* in the case
    t, m = outlet_history(case)
    result = resample(t, m, grid)
    json.dump(result, open(cache, "w"))
    # keep only what the study reads
    for entry in os.listdir(case):
        if re.fullmatch(r"[0-9.e+-]+", entry) and entry != "0":
            shutil.rmtree(os.path.join(case, entry), ignore_errors=True)
    return result


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--only", nargs="*", help="tags of SETTINGS to run (default all)")
    ap.add_argument("--endTime", type=float, default=30)
    ap.add_argument("--out", help="output folder (default build/benchmarks/calibrationCost)")
    args = ap.parse_args()
    global OUT
    if args.out:
        OUT = os.path.abspath(args.out)
    os.makedirs(OUT, exist_ok=True)

    bindir = os.path.join(OUT, "bin")
    os.makedirs(bindir, exist_ok=True)
    appbin = os.environ.get("FOAM_USER_APPBIN")
    if not appbin:
        sys.exit("source etc/bashrc first")
    shutil.copy(os.path.join(appbin, "calibrateGranularMixture"), bindir)
    commit = subprocess.check_output(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                                     text=True).strip()

    settings = [s for s in SETTINGS if not args.only or s[0] in args.only]
    grid = [0.1*i for i in range(int(args.endTime*10) + 1)]
    rows = []
    for k, (tag, n, s, r) in enumerate(settings):
        print("[%d/%d] calibration %s ..." % (k + 1, len(settings), tag), flush=True)
        cal = calibrate(tag, n, s, r, bindir)
        coeffs = os.path.join(OUT, tag, "calibration", "constant", "granularCoefficients")
        law = read_law(coeffs)
        print("    CPU %.0f s, wall %.0f s, %d conditions (%d without a Green-Kubo plateau);"
              " A %.3g a %.3g m %.3g b %.3g" % (cal["cpu"], cal["wall"], cal["conditions"],
              cal["noPlateau"], *[law["value"][p] for p in PARAMS]), flush=True)
        print("    silo2D with this law ...", flush=True)
        history = silo(tag, coeffs, args.endTime, grid)
        rows.append({"tag": tag, "particles": n, "sampling": s, "replicas": r,
                     "cal": cal, "law": law, "history": history, "coeffs": coeffs})

    ref = rows[-1]
    # sensitivity of the outlet history to each parameter at the reference
    sens = {}
    for p in PARAMS:
        h = ref["law"]["error"][p]
        changed = dict(ref["law"]["value"])
        changed[p] += h
        path = os.path.join(OUT, "ref_plus_%s" % p)
        write_law(ref["coeffs"], path, {p: changed[p]})
        print("sensitivity: silo2D with %s + %.3g ..." % (p, h), flush=True)
        hist = silo("ref_plus_" + p, path, args.endTime, grid)
        sens[p] = [(a - b)/h for a, b in zip(hist, ref["history"])]

    def sigma_m(law):
        cov = law["cov"]
        best = 0.0
        for i in range(len(grid)):
            g = [sens[p][i] for p in PARAMS]
            var = sum(g[a]*cov[a][b]*g[b] for a in range(4) for b in range(4))
            best = max(best, math.sqrt(max(var, 0.0)))
        return best

    lines = []
    lines.append("calibration cost vs silo2D outlet-composition uncertainty (engine commit %s)" % commit)
    lines.append("envelope phi (0.2 0.35 0.5) x (0.2 0.4) T (0.001 0.005 0.02): 18 conditions per replica;"
                 " one DEM thread; silo2D %g s of discharge" % args.endTime)
    lines.append("M(t) = coarse mass fraction at the outlet; sigma_M = max_t sqrt(g^T C g) (parameters +-1 sigma,"
                 " linear); dev = max_t |M - M_ref| (reference: %s)" % ref["tag"])
    lines.append("%-15s %6s %6s %4s %8s %8s %7s %-18s %-18s %-16s %8s %8s %8s" % (
        "setting", "N", "t_samp", "rep", "CPU[s]", "wall[s]", "noPlat", "m +- err", "b +- err",
        "A", "sigma_M", "dev", "peak M"))
    dat = ["# tag N samplingTime replicas cpu wall sigmaM dev peakM m mErr b bErr"]
    for row in rows:
        law = row["law"]
        sm = sigma_m(law)
        dev = max(abs(a - b) for a, b in zip(row["history"], ref["history"]))
        peak = max(row["history"])
        lines.append("%-15s %6d %6g %4d %8.0f %8.0f %7d %-18s %-18s %-16s %8.4f %8.4f %8.4f" % (
            row["tag"], row["particles"], row["sampling"], row["replicas"], row["cal"]["cpu"],
            row["cal"]["wall"], row["cal"]["noPlateau"],
            "%.3f +- %.3f" % (law["value"]["m"], law["error"]["m"]),
            "%.3f +- %.3f" % (law["value"]["b"], law["error"]["b"]),
            "%.3g +- %.2g" % (law["value"]["A"], law["error"]["A"]), sm, dev, peak))
        dat.append("%s %d %g %d %.1f %.1f %.5f %.5f %.5f %.4f %.4f %.4f %.4f" % (
            row["tag"], row["particles"], row["sampling"], row["replicas"], row["cal"]["cpu"],
            row["cal"]["wall"], sm, dev, peak, law["value"]["m"], law["error"]["m"],
            law["value"]["b"], law["error"]["b"]))
    report = "\n".join(lines)
    print(report)
    open(os.path.join(OUT, "results.txt"), "w").write(report + "\n")
    open(os.path.join(OUT, "results.dat"), "w").write("\n".join(dat) + "\n")
    with open(os.path.join(OUT, "histories.dat"), "w") as f:
        f.write("# t " + " ".join(r["tag"] for r in rows) + "\n")
        for i, t in enumerate(grid):
            f.write("%g %s\n" % (t, " ".join("%.6f" % r["history"][i] for r in rows)))
    if shutil.which("gnuplot"):
        png = os.path.join(OUT, "calibrationCost.png")
        gp = """set terminal pngcairo size 1500,450 noenhanced
set output '%s'
set multiplot layout 1,3
set logscale x
set xlabel 'calibration CPU time [s] (one core)'
set ylabel 'outlet coarse mass fraction'
set key top left
set title 'uncertainty left in the silo2D outlet composition'
plot '%s' using 5:7 with points pt 7 ps 1.5 title 'sigma_M (parameters +-1 sigma)', \\
     '' using 5:8 with points pt 5 ps 1.5 title 'max |M - M_ref|', \\
     '' using 5:7:1 with labels offset 0,1 font ',8' notitle
set ylabel 'fitted phi exponent b'
set key bottom left
set title 'phi exponent of D = A (1+x)^a T^m phi^b'
plot '%s' using 5:12:13 with yerrorbars pt 7 title 'DEM fit +- 1 s.e.', \\
     -1.5 with lines dt 2 title 'seed paper: -1.5', \\
     '' using 5:12:1 with labels offset 0,1 font ',8' notitle
unset logscale x
set xlabel 't [s]'
set ylabel 'coarse mass fraction at the outlet'
set key top left
set title 'outlet composition with each calibration'
plot for [i=2:%d] '%s' using 1:i with lines title columnhead(i)
unset multiplot
""" % (png, os.path.join(OUT, "results.dat"), os.path.join(OUT, "results.dat"),
       len(rows) + 1, os.path.join(OUT, "histories.dat"))
        # columnhead needs the header as a plain first line
        hist = os.path.join(OUT, "histories.dat")
        text = open(hist).read().replace("# t ", "t ", 1)
        open(hist, "w").write(text)
        subprocess.run(["gnuplot"], input=gp, text=True, check=False)
        print("plot:", png)


if __name__ == "__main__":
    main()
