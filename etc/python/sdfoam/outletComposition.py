"""Plot the composition of the material leaving a silo (python3 + gnuplot).

The body of each silo tutorial's ./plotOutletComposition script.

Reads postProcessing/outletComposition/<startTime>/<patch>.dat (written by
segregationDegradationFoam: a header line starting with '#' naming the
columns: time, then per species its mass flow and its mass fraction),
joins restarts, and writes
    results/outletComposition.dat   time, per species mass flow [kg/s] and
                                    mass fraction, cumulative discharged mass
    results/outletComposition.png   mass fractions vs discharged mass,
                                    mass flows vs time
and prints a summary (discharged mass per species, range of the coarse
fraction). Exit status 1 if the file is missing, empty or holds NaN.

Usage: ./plotOutletComposition [--case DIR] [--patch outlet] [--no-plot]
(the case defaults to the directory of the calling script)
"""

import argparse
import glob
import math
import os
import re
import subprocess
import sys


def species(case):
    with open(os.path.join(case, "constant", "granularProperties")) as f:
        text = re.sub(r"//[^\n]*|/\*.*?\*/", " ", f.read(), flags=re.S)
    m = re.search(r"\bspecies\s*\{", text)
    depth, i, names = 1, m.end(), []
    while depth > 0:
        mm = re.compile(r"\s*([A-Za-z_][\w.]*)\s*\{|\s*\}").match(text, i)
        if not mm:
            i += 1
            continue
        if mm.group(0).strip() == "}":
            depth -= 1
        else:
            if depth == 1:
                names.append(mm.group(1))
            depth += 1
        i = mm.end()
    return names


def readSeries(case, patch):
    files = sorted(
        glob.glob(os.path.join(case, "postProcessing", "outletComposition",
                               "*", patch + ".dat")),
        key=lambda p: float(os.path.basename(os.path.dirname(p))))
    if not files:
        raise SystemExit("plotOutletComposition: no postProcessing/"
                         "outletComposition/*/%s.dat" % patch)
    header, rows = None, {}
    for path in files:
        with open(path) as f:
            for line in f:
                s = line.strip()
                if not s:
                    continue
                if s.startswith("#"):
                    h = s.lstrip("#").split()
                    if len(h) > 1:
                        header = h
                    continue
                vals = [float(v) for v in s.split()]
                rows[vals[0]] = vals     # later files override (restarts)
    if header is None or not rows:
        raise SystemExit("plotOutletComposition: %s has no header or data"
                         % files[-1])
    return header, [rows[t] for t in sorted(rows)]


def lastRow(case, station):
    """The last row of postProcessing/outletComposition/*/<station>.dat (a
    patch or a face zone; restarts joined) as {column: value}."""
    header, rows = readSeries(case, station)
    return dict(zip(header, rows[-1]))


def dustVolumeRate(logPath):
    """The dust volume made per unit time at the end of a run of
    segregationDegradationFoam [m3/s]: the difference of the last two
    "Solids:" lines of its log over their time step (0 with fewer)."""
    log = open(logPath).read()
    times = [float(t) for t in re.findall(r"^Time = (\S+)", log, re.M)]
    dusts = [float(v) for v in re.findall(r"^Solids: .*dust volume (\S+)", log, re.M)]
    if len(dusts) < 2:
        return 0.0
    return (dusts[-1] - dusts[-2]) / (times[-1] - times[-2])


def dictValue(path, key):
    """The value of entry KEY (a/b/c) of the OpenFOAM dictionary PATH, as
    text (foamDictionary: includes and macros expanded)."""
    return subprocess.run(["foamDictionary", "-entry", key, "-value", path],
                          capture_output=True, text=True, check=True).stdout.strip()


def columns(header, names):
    """Indices of (massFlow, massFraction) for each species from the header."""
    low = [h.lower() for h in header]
    cols = {}
    for sp in names:
        flow = frac = None
        for i, h in enumerate(low):
            if i == 0 or sp.lower() not in re.split(r"[^a-z0-9]+", h):
                continue
            if "frac" in h:
                frac = i
            elif "flow" in h or "rate" in h or "mdot" in h or "phi" in h:
                flow = i
        cols[sp] = (flow, frac)
    if all(f is not None and c is not None for f, c in cols.values()):
        return cols
    # fall back on the documented order: time, (flow, fraction) per species
    if len(header) >= 1 + 2 * len(names):
        return {sp: (1 + 2 * k, 2 + 2 * k) for k, sp in enumerate(names)}
    raise SystemExit("plotOutletComposition: cannot find the columns of %s "
                     "in the header %s" % (names, header))


def main(title, flowUnit="kg/s"):
    """title names the case in the plot; flowUnit says what share of the
    silo the mass flows are of (e.g. "kg/s (wedge)")."""
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--case", default=os.path.dirname(os.path.abspath(
        sys.argv[0])))
    p.add_argument("--patch", default="outlet")
    p.add_argument("--no-plot", action="store_true")
    a = p.parse_args()
    case = a.case

    names = species(case)
    header, rows = readSeries(case, a.patch)
    cols = columns(header, names)
    for r in rows:
        if not all(math.isfinite(v) for v in r):
            raise SystemExit("plotOutletComposition: non-finite value at "
                             "time %g" % r[0])

    # cumulative discharged mass per species (trapezoidal rule)
    cum = {sp: [0.0] for sp in names}
    for k in range(1, len(rows)):
        dt = rows[k][0] - rows[k - 1][0]
        for sp in names:
            fi = cols[sp][0]
            cum[sp].append(cum[sp][-1]
                           + 0.5 * dt * (abs(rows[k][fi]) + abs(rows[k - 1][fi])))

    out = os.path.join(case, "results", "outletComposition.dat")
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, "w") as f:
        f.write("# time " + " ".join(
            "massFlow.%s massFraction.%s" % (sp, sp) for sp in names)
            + " " + " ".join("discharged.%s" % sp for sp in names) + "\n")
        for k, r in enumerate(rows):
            vals = [r[0]]
            for sp in names:
                vals += [abs(r[cols[sp][0]]), r[cols[sp][1]]]
            vals += [cum[sp][k] for sp in names]
            f.write(" ".join("%.10g" % v for v in vals) + "\n")

    total = sum(cum[sp][-1] for sp in names)
    print("Outlet composition (%d samples, t = %g .. %g s), patch %s:"
          % (len(rows), rows[0][0], rows[-1][0], a.patch))
    print("  columns read: %s" % ", ".join(
        "%s flow '%s' fraction '%s'" % (sp, header[cols[sp][0]],
                                         header[cols[sp][1]])
        for sp in names))
    for sp in names:
        fr = [r[cols[sp][1]] for r in rows if abs(sum(
            r[cols[s][0]] for s in names)) > 0]
        print("  %-8s discharged %.6g kg (%.2f %% of the discharge), mass "
              "fraction %.4f .. %.4f" % (
                  sp, cum[sp][-1], 100 * cum[sp][-1] / total if total else 0,
                  min(fr) if fr else float("nan"),
                  max(fr) if fr else float("nan")))

    if a.no_plot:
        return 0
    nSp = len(names)
    totalCol = "(%s)" % "+".join("$%d" % (2 + 2 * nSp + k)
                                 for k in range(nSp))
    fracPlots = ", ".join(
        '"%s" using %s:%d with lines lw 2 title "%s"'
        % (out, totalCol, 3 + 2 * k, sp) for k, sp in enumerate(names))
    flowPlots = ", ".join(
        '"%s" using 1:%d with lines lw 2 title "%s"' % (out, 2 + 2 * k, sp)
        for k, sp in enumerate(names))
    png = os.path.join(case, "results", "outletComposition.png")
    gp = """set terminal pngcairo size 900,800 enhanced font ",11"
set output "%s"
set multiplot layout 2,1 title "%s: material leaving through patch %s"
set grid
set key outside right
set xlabel "discharged mass [kg]"
set ylabel "mass fraction in the outflow"
plot %s
set xlabel "time [s]"
set ylabel "mass flow [%s]"
plot %s
unset multiplot
""" % (png, title, a.patch, fracPlots, flowUnit, flowPlots)
    with open(os.path.join(case, "results", "outletComposition.gp"), "w") as f:
        f.write(gp)
    try:
        subprocess.run(["gnuplot", os.path.join(case, "results",
                                                "outletComposition.gp")],
                       check=True)
    except (OSError, subprocess.CalledProcessError) as e:
        print("plotOutletComposition: gnuplot failed: %s" % e)
        return 1
    print("  plot: %s" % png)
    return 0
