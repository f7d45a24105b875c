#!/usr/bin/env python3
"""benchmarks/muIBeverloo: rates, constancy and the Beverloo fit.

Usage: analyse.py WORK RESULTS [PACKED D [COEFFICIENTS]]

Reads WORK/<run>/postProcessing/outletComposition/0/outlet.dat (mass flow
through the slot of a one-cell-deep planar bin) and the run's Allrun
options (WORK/runs.txt); writes RESULTS and WORK/<run>.rate (t, mass flow
per metre of slot) and WORK/fit.dat for the plot.

Rate: the time-weighted mean mass flow per metre of slot W over
[0.3 s, end] (`empty`: until 60 % of the fill has left). Constancy: the
largest |W_0.1 - W| / W over consecutive 0.1 s windows of that interval.
Fit: W = rho_b C sqrt(g) (b - k d)^n over the `fit` runs, rho_b = 0.6 x
2500 kg/m3, d = 1.2 mm (the mixture's solids-weighted mean, muI's d): k
on a grid of 0.01 d (0-6), n and C by least squares in log W at each k,
the k of least squares kept; and with k = 1.5 fixed (Beverloo's k).
With PACKED and D (run -granularCoefficients: the calibrated rheology's
packed fraction and d) rho_b = PACKED x 2500 kg/m3 and d = D instead.

Mesh convergence: for each slot run on 5, 2.5 and 1.25 mm cells (coarse_,
fit_, fine_), the rates over the common window [0.2 s, 0.4 s] (the rate is
steady from 0.1 s; the fine runs end at 0.4 s), the observed order and the
Richardson estimate; a slot on 2.5 and 1.25 mm cells only is extrapolated
at the mean of those orders; the same fits over the estimates (the
converged rates) when every fit slot has one, and over the 1.25 mm rates.
"""
import math
import os
import sys

from sdfoam.beverloo import (fit as fitBeverloo, fitFixedK, measure, outletSeries, readRuns,
                             extrapolate, richardson, timeMean, writeRateFile)

work, results = sys.argv[1], sys.argv[2]
packed = float(sys.argv[3]) if len(sys.argv) > 3 else 0.6
g, rhoBulk = 9.81, packed * 2500.0
d = float(sys.argv[4]) if len(sys.argv) > 4 else 1.2e-3
source = sys.argv[5] if len(sys.argv) > 5 and sys.argv[5] else ""
tStart, window = 0.3, 0.1
convergenceWindow = (0.2, 0.4)

runs = readRuns(work)

rates = {}
series = {}
with open(results, "w") as out:
    out.write("# benchmarks/muIBeverloo: planar flat-bottomed bin, bulkFlow muI (validation/planarSiloMuI),\n")
    out.write("# mass flow per metre of slot W [kg/s/m]; rho_b %.0f kg/m3, d %.1f mm; mu(I) %s\n"
              % (rhoBulk, d * 1e3, "calibrated (%s)" % source if source else "glass beads (Jop et al. 2006)"))
    out.write("# run b[mm] dx[mm] hFill[m] W[kg/s/m] window[s] constancy(max 0.1s dev) discharged_in_window\n")
    for name, o in runs:
        series[name] = outletSeries(os.path.join(work, name), scale=1 / o["dx"])
        fill = o["hFill"] * o["W"] * rhoBulk
        if series[name][-1][0] < o["endTime"] - 1e-3:
            out.write("# %s: not finished (t = %.3f s of %g)\n" % (name, series[name][-1][0], o["endTime"]))
            del series[name]
            continue
        # the fine runs end at 0.4 s: their rate over the common window
        fine = name.startswith("fine")
        t0 = convergenceWindow[0] if fine else tStart
        tEnd, W, dev, frac = measure(series[name], fill, t0, window,
                                     0.6 if name.startswith("empty") else None)
        rates[name] = (o, W, dev)
        out.write("%-11s %5.1f %4s %5.2f %9.4f %4.2f-%4.2f %.2e %.3f\n"
                  % (name, o["b"] * 1e3, ("%.2f" if fine else "%.1f") % (o["dx"] * 1e3), o["hFill"], W,
                     t0, tEnd, dev, frac))
        writeRateFile(os.path.join(work, name + ".rate"), series[name], fill, "W[kg/s/m]")

    fit = [(o["b"], W) for name, (o, W, _) in rates.items() if name.startswith("fit")]

    prefactor = rhoBulk * math.sqrt(g)
    n, C, k, res = fitBeverloo(fit, d, prefactor, [k / 100.0 for k in range(0, 601)])
    n15, se15, C15 = fitFixedK(fit, d, prefactor, 1.5)
    # C at n = 3/2 and k = 1.5 (the slot law's form)
    C32 = sum(W / (rhoBulk * math.sqrt(g) * (b - 1.5 * d) ** 1.5) for b, W in fit) / len(fit)
    out.write("# Beverloo fit over b = %s mm: n %.3f, C %.4f, k %.2f (residual %.2e in log W)\n"
              % (", ".join("%.0f" % (b * 1e3) for b, _ in fit), n, C, k, res))
    out.write("# with k = 1.5: n %.3f +- %.3f (standard error), C %.4f\n" % (n15, se15, C15))
    out.write("# with n = 3/2, k = 1.5: C %.4f (slot law C = 1.03, Nedderman after Myers & Sellers)\n" % C32)
    # mesh convergence: each slot on 5, 2.5 and 1.25 mm cells over the
    # common window, the observed order and the Richardson estimate
    # (slots with two meshes only: the estimate at the mean order of the others)
    converged, finest, convergence, orders = [], [], [], []
    windowRate = lambda run: timeMean([(t, x) for t, x, _ in series[run]], *convergenceWindow)
    twoMeshes = []
    for name, (o, _, _) in rates.items():
        if not name.startswith("fit"):
            continue
        tag = name[len("fit"):]
        if "fine" + tag not in rates:
            continue
        if "coarse" + tag not in rates:
            twoMeshes.append((o, [float("nan"), windowRate(name), windowRate("fine" + tag)]))
            continue
        w = [windowRate(level + tag) for level in ("coarse", "fit", "fine")]
        p, estimate = richardson(*w)
        if not convergence:
            out.write("# mesh convergence over t = %.1f-%.1f s: W on 5, 2.5, 1.25 mm cells, observed order,"
                      " Richardson estimate W_h->0, fine / estimate\n" % convergenceWindow)
        out.write("#   b %4.1f mm: %.4f %.4f %.4f  order %.2f  W_h->0 %.4f  %.4f\n"
                  % (o["b"] * 1e3, w[0], w[1], w[2], p, estimate, w[2] / estimate))
        finest.append((o["b"], w[2]))
        if math.isfinite(estimate):
            converged.append((o["b"], estimate))
            orders.append(p)
        convergence.append((o["b"], w, estimate))
    if twoMeshes and orders:
        p = sum(orders) / len(orders)
        for o, w in twoMeshes:
            estimate = extrapolate(w[1], w[2], p)
            out.write("#   b %4.1f mm: (no 5 mm mesh) %.4f %.4f  at the mean order %.2f  W_h->0 %.4f  %.4f\n"
                      % (o["b"] * 1e3, w[1], w[2], p, estimate, w[2] / estimate))
            finest.append((o["b"], w[2]))
            converged.append((o["b"], estimate))
            convergence.append((o["b"], w, estimate))
        finest.sort()
        converged.sort()
    for label, points in (("1.25 mm cells (t = %.1f-%.1f s)" % convergenceWindow, finest),
                          ("the Richardson estimates", converged)):
        if len(points) == len(fit) and len(points) >= 3:
            nR, CR, kR, resR = fitBeverloo(points, d, prefactor, [k / 100.0 for k in range(0, 601)])
            C32R = sum(W / (prefactor * (b - 1.5 * d) ** 1.5) for b, W in points) / len(points)
            C32k0 = sum(W / (prefactor * b ** 1.5) for b, W in points) / len(points)
            out.write("# Beverloo fit over %s: n %.3f, C %.4f, k %.2f%s (residual %.2e);"
                      " with n = 3/2, k = 1.5: C %.4f; with n = 3/2, k = 0: C %.4f\n"
                      % (label, nR, CR, kR, " (the grid's lower end: no empty annulus)" if kR == 0 else "",
                         resR, C32R, C32k0))
        elif points:
            out.write("# no Beverloo fit over %s: %d of %d slots\n" % (label, len(points), len(fit)))
    # the ratios of the runs that ran (run -only leaves some out)
    if "height_b20" in rates and "coarse_b20" in rates:
        out.write("# height_b20 / coarse_b20 (fill height 0.42 / 0.34 m): %.4f\n"
                  % (rates["height_b20"][1] / rates["coarse_b20"][1]))
    for b in (20, 30):
        if "coarse_b%d" % b in rates and "fit_b%d" % b in rates:
            out.write("# coarse_b%d / fit_b%d (5 / 2.5 mm cells): %.4f\n"
                      % (b, b, rates["coarse_b%d" % b][1] / rates["fit_b%d" % b][1]))
    # for the plot: W over the Richardson estimate against the cell size, per slot
    with open(os.path.join(work, "convergence.dat"), "w") as f:
        f.write("# dx[mm] W/W_h->0, one block per slot headed by its name (gnuplot columnheader)\n")
        for b, w, estimate in convergence:
            if math.isfinite(estimate):
                f.write("b=%.0fmm -\n" % (b * 1e3))
                for dx, rate in zip((5.0, 2.5, 1.25), w):
                    if math.isfinite(rate):
                        f.write("%.3f %.5f\n" % (dx, rate / estimate))
                f.write("\n\n")
    with open(os.path.join(work, "fit.dat"), "w") as f:
        f.write("# b[m] W[kg/s/m] fit(n,C,k) slotLaw(1.03, k 1.5, n 1.5)\n")
        for b, W in sorted(fit):
            f.write("%.4f %.5f %.5f %.5f\n" % (b, W, rhoBulk * C * math.sqrt(g) * (b - k * d) ** n,
                                              rhoBulk * 1.03 * math.sqrt(g) * (b - 1.5 * d) ** 1.5))
print(open(results).read())
