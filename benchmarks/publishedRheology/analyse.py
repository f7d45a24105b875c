#!/usr/bin/env python3
"""The quasi-static limit of benchmarks/publishedRheology's envelopes against
published DEM values.

Reads OUT/<name>-cells.dat (rheologyEnvelope's table: I_target gammaDot I
I_err mu mu_err phi phi_err Z sigma_yy sigma_yy_err T steady regime) and
extrapolates mu and phi to I -> 0 with straight lines in I over the steady
cells at I <= 0.08, weighted by their block errors (the errors of the
intercepts scaled by sqrt(chi2/dof) when that exceeds 1).

Published values: only second-hand ones could be read here (the pages of
Chialvo, Sun & Sundaresan 2012, Phys. Rev. E 85, 021305, return their
abstract only): the input file testCases/jetBedPU/constant/kineticTheoryProperties
of github.com/gudaxia/twoPhaseEulerPimpleFoamPU (commit 80de762, a solver
implementing "the modified kinetic theory by Chialvo-Sundaresan") lists
  alphaCritical 0.613; // 0.587;   muFriction 0.1; //0.5;
  yieldStressRatio 0.268; // 0.382;
i.e. phi_c 0.613 and mu_s 0.268 at friction 0.1, 0.587 and 0.382 at 0.5,
without their conditions or scatter.

Usage: analyse.py OUT
"""
import math
import os
import sys

PUBLISHED = {0.5: (0.382, 0.587), 0.1: (0.268, 0.613)}
RUNS = [("mono_mu0.5", 0.5, "one size 1.5 mm, 200 grains"),
        ("poly_mu0.5", 0.5, "1.2/1.5/1.8 mm, equal volumes, 300 grains"),
        ("poly_mu0.1", 0.1, "1.2/1.5/1.8 mm, equal volumes, 300 grains")]
IMAX = 0.08


def line(xs, ys, es):
    """Weighted least squares y = c0 + c1 x: (c0, c1, se(c0), chi2/dof)."""
    w = [1 / e ** 2 for e in es]
    S, Sx, Sy = sum(w), sum(wi * x for wi, x in zip(w, xs)), sum(wi * y for wi, y in zip(w, ys))
    Sxx = sum(wi * x * x for wi, x in zip(w, xs))
    Sxy = sum(wi * x * y for wi, x, y in zip(w, xs, ys))
    D = S * Sxx - Sx * Sx
    c0, c1 = (Sxx * Sy - Sx * Sxy) / D, (S * Sxy - Sx * Sy) / D
    dof = len(xs) - 2
    chi2 = sum(wi * (y - c0 - c1 * x) ** 2 for wi, x, y in zip(w, xs, ys)) / dof if dof > 0 else float("nan")
    se0 = math.sqrt(Sxx / D) * (math.sqrt(chi2) if chi2 > 1 else 1)
    return c0, c1, se0, chi2


def main():
    out = sys.argv[1]
    print("# The embedded DEM's quasi-static limit (pressure-controlled Lees-Edwards cells, sigma_yy 1333 Pa,")
    print("# linear spring-dashpot kn/(p d) = 1000, e 0.7) against published values (second-hand, see analyse.py)")
    print("# run  friction  grains | cells used (I <= %g)  mu_s +- se  phi_c +- se  (chi2/dof mu, phi) | published mu_s, phi_c | differences" % IMAX)
    for name, friction, grains in RUNS:
        path = os.path.join(out, name + "-cells.dat")
        if not os.path.exists(path):
            print("%-11s %.1f  %s | no cells (%s missing)" % (name, friction, grains, path))
            continue
        rows = []
        skipped = []
        for l in open(path):
            if l.startswith("#") or not l.strip():
                continue
            v = l.split()
            # the tables before the bond order column Q6 (index 9) have 12 numbers
            q6 = len(v) > 14 and v[13] in ("yes", "no")
            steady = v[13] if q6 else v[12]
            regime = " ".join(v[14:] if q6 else v[13:]).strip('"')
            I, mu, muErr, phi, phiErr = float(v[2]), float(v[4]), float(v[5]), float(v[6]), float(v[7])
            if steady != "yes":
                skipped.append("%.3g (not steady)" % I)
            elif regime != "dense flow":
                skipped.append("%.3g (%s)" % (I, regime))
            elif I <= IMAX * 1.01:
                rows.append((I, mu, muErr, phi, phiErr))
        for r in rows:
            print("#   %s  I %.4f  mu %.4f +- %.4f  phi %.4f +- %.4f" % (name, *r))
        if len(rows) < 3:
            print("%-11s %.1f  %s | %d steady cells at I <= %g: too few%s"
                  % (name, friction, grains, len(rows), IMAX, "; " + ", ".join(skipped) if skipped else ""))
            continue
        I = [r[0] for r in rows]
        muS, _, muSe, muChi = line(I, [r[1] for r in rows], [r[2] for r in rows])
        phiC, _, phiSe, phiChi = line(I, [r[3] for r in rows], [r[4] for r in rows])
        pub = PUBLISHED[friction]
        print("%-11s %.1f  %s | %d cells  mu_s %.4f +- %.4f  phi_c %.4f +- %.4f  (%.2f, %.2f) | %.3f %.3f | %+.4f %+.4f%s"
              % (name, friction, grains, len(rows), muS, muSe, phiC, phiSe, muChi, phiChi,
                 pub[0], pub[1], muS - pub[0], phiC - pub[1],
                 "; left out: " + ", ".join(skipped) if skipped else ""))


main()
