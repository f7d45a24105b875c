#!/usr/bin/env python3
"""benchmarks/muIBeverloo -axisymmetric: rates, constancy and the Beverloo
fit for the flat-bottomed cylindrical bin (validation/axisymmetricSiloMuI).

Usage: analyseAxisymmetric.py WORK RESULTS

Reads WORK/<run>/postProcessing/outletComposition/0/outlet.dat (mass flow
through the orifice of the 5-degree wedge: x 72 for the full bin) and the
run's Allrun options (WORK/runs.txt); writes RESULTS, WORK/<run>.rate (t,
mass flow of the full bin, discharged fraction) and WORK/fit.dat.

Rate: the time-weighted mean mass flow over [0.3 s, end] (`empty`: until
55 % of the fill has left: the rate falls from 57 %, when the crater
reaches the orifice and the flat bottom's shoulders hold the rest). Constancy: the
largest deviation of a 0.1 s mean from it. Fit: Q = rho_b C sqrt(g)
(D0 - k d)^n over the `fit` runs (2.5 mm cells) (rho_b = 0.6 x 2500 kg/m3, d = 1 mm): k on
a grid of 0.01 d (0-6) and n, C by least squares in log Q; and with k = 1.5
(Beverloo's k) fixed; C with n = 5/2, k = 1.5 against Beverloo's 0.58.
"""
import math
import os
import sys

from sdfoam.beverloo import fit as fitBeverloo, fitFixedK, measure, outletSeries, readRuns, writeRateFile

work, results = sys.argv[1], sys.argv[2]
g, rhoBulk, d, R = 9.81, 0.6 * 2500.0, 1.0e-3, 0.04
wedges = 360.0 / 5.0
tStart, window = 0.3, 0.1

runs = readRuns(work)

rates = {}
with open(results, "w") as out:
    out.write("# benchmarks/muIBeverloo -axisymmetric: flat-bottomed cylindrical bin R 40 mm, bulkFlow muI\n")
    out.write("# (validation/axisymmetricSiloMuI, 5-degree wedge x 72); mass flow Q [kg/s]; rho_b %.0f kg/m3, d %.1f mm\n"
              % (rhoBulk, d * 1e3))
    out.write("# run D0[mm] dx[mm] hFill[m] Q[kg/s] window[s] constancy(max 0.1s dev) discharged_in_window out_of_top/out_of_orifice\n")
    for name, o in runs:
        series = outletSeries(os.path.join(work, name), scale=wedges)
        fill = o["hFill"] * math.pi * R ** 2 * rhoBulk
        tEnd, Q, dev, frac = measure(series, fill, tStart, window,
                                     0.55 if name.startswith("empty") else None)
        top = outletSeries(os.path.join(work, name), "atmosphere", wedges)[-1][2] / series[-1][2]
        rates[name] = (o, Q, dev)
        out.write("%-11s %5.1f %4.1f %5.2f %9.5f %4.2f-%4.2f %.2e %.3f %.1e\n"
                  % (name, o["D0"] * 1e3, o["dx"] * 1e3, o["hFill"], Q, tStart, tEnd, dev, frac, top))
        writeRateFile(os.path.join(work, name + ".rate"), series, fill, "Q[kg/s]")

    fit = [(o["D0"], Q) for name, (o, Q, _) in rates.items() if name.startswith("fit")]
    prefactor = rhoBulk * math.sqrt(g)
    n, C, k, res = fitBeverloo(fit, d, prefactor, [k / 100.0 for k in range(0, 601)])
    n15, se15, C15 = fitFixedK(fit, d, prefactor, 1.5)
    C52 = sum(Q / (prefactor * (D - 1.5 * d) ** 2.5) for D, Q in fit) / len(fit)
    out.write("# Beverloo fit over D0 = %s mm: n %.3f, C %.4f, k %.2f (residual %.2e in log Q)\n"
              % (", ".join("%.0f" % (D * 1e3) for D, _ in fit), n, C, k, res))
    out.write("# with k = 1.5: n %.3f +- %.3f (standard error), C %.4f\n" % (n15, se15, C15))
    out.write("# with n = 5/2, k = 1.5: C %.4f (Beverloo C = 0.58)\n" % C52)
    out.write("# height_D20 / fit_D20 (fill height 0.22 / 0.17 m): %.4f\n"
              % (rates["height_D20"][1] / rates["fit_D20"][1]))
    out.write("# empty_D25 / fit_D25 (until 55 %% discharged / over 0.3-1 s): %.4f\n"
              % (rates["empty_D25"][1] / rates["fit_D25"][1]))
    out.write("# coarse_D20 / fit_D20 (5 / 2.5 mm cells): %.4f\n"
              % (rates["coarse_D20"][1] / rates["fit_D20"][1]))
    for D in (20, 30):
        out.write("# fine_D%d / fit_D%d (1.25 / 2.5 mm cells): %.4f\n"
                  % (D, D, rates["fine_D%d" % D][1] / rates["fit_D%d" % D][1]))
    # The exponent from two orifices at k = 1.5, on each mesh
    law = math.log((0.03 - 1.5 * d) / (0.02 - 1.5 * d))
    for mesh in ("fit", "fine"):
        ratio = rates[mesh + "_D30"][1] / rates[mesh + "_D20"][1]
        out.write("# %s_D30 / %s_D20: %.4f, n from the two at k = 1.5: %.3f\n"
                  % (mesh, mesh, ratio, math.log(ratio) / law))
    with open(os.path.join(work, "fit.dat"), "w") as f:
        f.write("# D0[m] Q[kg/s] fit(n,C,k) beverloo(0.58, k 1.5, n 2.5)\n")
        for D, Q in sorted(fit):
            f.write("%.4f %.6f %.6f %.6f\n" % (D, Q, prefactor * C * (D - k * d) ** n,
                                              prefactor * 0.58 * (D - 1.5 * d) ** 2.5))
print(open(results).read())
