#!/usr/bin/env python3
"""Extract the size classes of a finished v1912 breakup case (makeCase.py).

For every written time directory (ASCII, one cell) reads alpha.<phase> and
f<i>.<phase>.bubbles and writes, into OUTDIR:

  classes_all.dat     time, class index, v_i, N_i, alpha_i, alpha_i/alpha0
  classes_t<T>.dat    the same columns for the last time (default) or --time
  volume.dat          per time: total particle volume in the classes
                      sum_i alpha_p(i) f_i (per m^3), relative to the start,
                      the sum of the dispersed phase fractions sum_p alpha_p,
                      total number sum_i N_i, and sum_i f_i per phase

Definitions (v1912, checked in the source):
  * sizeGroup: x_i = formFactor*d_i^3 (the particle volume; formFactor 1
    here), f_i = the fraction of the phase (velocityGroup) volume fraction
    carried by class i, so the volume fraction in class i is
    alpha_i = alpha_p*f_i and the number density is N_i = alpha_p*f_i/x_i
    (functionObjects/sizeDistribution/sizeDistribution.C does the same).
  * The cell is 1 m^3, so N_i is also the number of particles in the case.

Usage: extract.py CASEDIR OUTDIR [--time T]
Python 3 standard library only.
"""
import argparse
import os
import re
import sys


def read_uniform(path):
    """internalField of a one-cell ASCII volScalarField."""
    with open(path) as f:
        s = f.read()
    m = re.search(r"internalField\s+uniform\s+([^;\s]+)\s*;", s)
    if m:
        return float(m.group(1))
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*1\s*\(\s*([^)\s]+)\s*\)", s)
    if m:
        return float(m.group(1))
    sys.exit("cannot read internalField of %s (one cell, ASCII expected)" % path)


def read_classes(case):
    """[(index, name, phase, x)] ordered by x, from constant/phaseProperties."""
    with open(os.path.join(case, "constant", "phaseProperties")) as f:
        s = f.read()
    s = re.sub(r"//.*", "", s)
    classes = []
    phase = None
    ff = {}
    # phase blocks: name { ... velocityGroupCoeffs { ... formFactor X; sizeGroups ( ... ) } }
    for m in re.finditer(r"(\w+)\s*\{\s*type\s+\w+;\s*diameterModel\s+velocityGroup;"
                         r"(.*?)residualAlpha", s, re.S):
        phase = m.group(1)
        body = m.group(2)
        fm = re.search(r"formFactor\s+([^;\s]+)\s*;", body)
        form = float(fm.group(1)) if fm else 1.0
        for g in re.finditer(r"(f\d+)\s*\{\s*d\s+([^;\s]+)\s*;\s*value\s+([^;\s]+)\s*;\s*\}", body):
            name = g.group(1)
            d = float(g.group(2))
            classes.append((name, phase, form * d ** 3))
    if not classes:
        sys.exit("no sizeGroups found in %s/constant/phaseProperties" % case)
    classes.sort(key=lambda c: c[2])
    return [(i, n, p, x) for i, (n, p, x) in enumerate(classes)]


def time_dirs(case):
    out = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if os.path.isfile(os.path.join(case, d, "alpha.water")):
            out.append((t, d))
    out.sort()
    return out


def fmt(x):
    return "%.12e" % x


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case")
    ap.add_argument("outdir")
    ap.add_argument("--time", type=float, default=None,
                    help="time for classes_t<T>.dat (default: last)")
    a = ap.parse_args()

    classes = read_classes(a.case)
    phases = []
    for _, _, p, _ in classes:
        if p not in phases:
            phases.append(p)
    times = time_dirs(a.case)
    if not times:
        sys.exit("no time directories in %s" % a.case)
    os.makedirs(a.outdir, exist_ok=True)

    rows = {}
    vol = []
    alpha0 = None
    for t, d in times:
        alpha = {p: read_uniform(os.path.join(a.case, d, "alpha." + p)) for p in phases}
        fsum = {p: 0.0 for p in phases}
        r = []
        for i, name, p, x in classes:
            path = os.path.join(a.case, d, "%s.%s.bubbles" % (name, p))
            if os.path.isfile(path):
                f = read_uniform(path)
            else:
                # not written at t = 0: READ_IF_PRESENT with the default value
                f = float(re.search(r"\b%s\s*\{\s*d\s+[^;]+;\s*value\s+([^;\s]+)"
                                    % name, open(os.path.join(a.case, "constant",
                                                              "phaseProperties")).read()).group(1))
            fsum[p] += f
            ai = alpha[p] * f
            r.append((i, x, ai / x, ai))
        V = sum(ai for _, _, _, ai in r)
        if alpha0 is None:
            alpha0 = V
        rows[t] = r
        vol.append((t, V, V / alpha0, sum(alpha.values()),
                    sum(n for _, _, n, _ in r), [fsum[p] for p in phases]))

    hdr = ("# v1912 reactingMultiphaseEulerFoam, populationBalance bubbles, case %s\n"
           "# N_i = alpha_p*f_i/v_i [1/m^3] (= number in the 1 m^3 cell), "
           "alpha_i = alpha_p*f_i (volume fraction in class i), alpha0 = %.12g\n"
           % (os.path.abspath(a.case), alpha0))
    with open(os.path.join(a.outdir, "classes_all.dat"), "w") as f:
        f.write(hdr)
        f.write("# time  class  v_i[m^3]  N_i[1/m^3]  alpha_i  alpha_i/alpha0\n")
        for t in sorted(rows):
            for i, x, n, ai in rows[t]:
                f.write("%g %d %s %s %s %s\n" % (t, i, fmt(x), fmt(n), fmt(ai), fmt(ai / alpha0)))
    tsel = times[-1][0] if a.time is None else a.time
    if tsel not in rows:
        sys.exit("time %g not written" % tsel)
    with open(os.path.join(a.outdir, "classes_t%g.dat" % tsel), "w") as f:
        f.write(hdr)
        f.write("# time = %g\n# class  v_i[m^3]  N_i[1/m^3]  alpha_i  alpha_i/alpha0\n" % tsel)
        for i, x, n, ai in rows[tsel]:
            f.write("%d %s %s %s %s\n" % (i, fmt(x), fmt(n), fmt(ai), fmt(ai / alpha0)))
    with open(os.path.join(a.outdir, "volume.dat"), "w") as f:
        f.write(hdr)
        f.write("# time  V=sum_i alpha_p*f_i  V/V0  sum_p alpha_p  N=sum_i N_i  "
                + "  ".join("fsum.%s" % p for p in phases) + "\n")
        for t, V, rel, asum, N, fs in vol:
            f.write("%g %s %s %s %s %s\n" % (t, fmt(V), fmt(rel), fmt(asum), fmt(N),
                                              " ".join(fmt(x) for x in fs)))
    t, V, rel, asum, N, fs = vol[-1]
    print("%s: %d classes, phases %s, t = %g: V/V0 = %.10f, sum alpha_p/alpha0 = %.10f, N = %.6g"
          % (a.case, len(classes), phases, t, rel, asum / alpha0, N))


if __name__ == "__main__":
    main()
