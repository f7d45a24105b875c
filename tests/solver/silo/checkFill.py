#!/usr/bin/env python3
"""The balance of a silo tutorial run with Allrun -fill (tutorials/silo2D,
tutorials/silo3D): per species, the volume in the silo at the end of the
discharge against the volume at the start plus what entered through the
inlet minus what left through the outlet and the top, over both stages.

The volumes in the silo come from the solver's log lines "Solids: total
volume ... n.<species> volume ..." (log.segregationDegradationFoam.fill and
.discharge; the first line is after the first step, so the start is that
line plus the first step's flows); the flows from the cumulative masses of
outletComposition (postProcessing/outletComposition/<stage start>/
<patch>.dat, positive leaving; each stage's record starts from 0). A fill
deposited where it lands (Allrun -deposition) enters through no patch: its
record postProcessing/deposition/<start>/deposition.dat (each species'
solids deposited in all, last line) counts as entered through the inlet.

Exit status 1 if a species' balance is off by more than --tol (relative to
what entered), the solids' by more than --tol-total, nothing entered or
nothing was discharged, more than --tol-top of what entered left through
the top, or anything entered through the closed inlet in the discharge
(more than 1e-12 of the fed). The species' densities are read from
constant/granularProperties.

Usage: checkFill.py CASE [--tol 1e-8] [--tol-total 1e-10] [--tol-top 1e-5]
"""
import argparse
import glob
import os
import re
import sys

from sdfoam import deposition



def densities(case):
    """{species: rho} from the species' dictionaries of granularProperties."""
    with open(os.path.join(case, "constant", "granularProperties")) as f:
        text = re.sub(r"//[^\n]*|/\*.*?\*/", " ", f.read(), flags=re.S)
    return {m.group(1): float(m.group(2)) for m in re.finditer(
        r"\b(\w+)\s*\{[^{}]*\brho\s+([^;\s]+)\s*;[^{}]*\}", text)}


def logVolumes(path):
    """Per logged step: {species: volume} from the "Solids:" lines."""
    steps = []
    with open(path) as f:
        for line in f:
            if line.startswith("Solids:"):
                steps.append({m.group(1): float(m.group(2)) for m in
                              re.finditer(r"n\.(\w+) volume (\S+)", line)})
    if not steps:
        sys.exit("checkFill: no 'Solids:' line in %s" % path)
    return steps


def records(case, patch):
    """Per stage (sorted by start time): header and rows of the patch."""
    out = []
    paths = glob.glob(os.path.join(case, "postProcessing",
                                   "outletComposition", "*", patch + ".dat"))
    for path in sorted(paths, key=lambda p: float(os.path.basename(
            os.path.dirname(p)))):
        header, rows = None, []
        with open(path) as f:
            for line in f:
                if line.startswith("#"):
                    h = line.lstrip("#").split()
                    if len(h) > 1:
                        header = h
                elif line.strip():
                    rows.append([float(v) for v in line.split()])
        out.append((header, rows))
    if len(out) != 2:
        sys.exit("checkFill: %d records of patch %s (the fill's and the"
                 " discharge's expected)" % (len(out), patch))
    return out


def cumulative(record, species, row, rho):
    header, rows = record
    return rows[row][header.index("cumulativeMass.%s[kg]" % species)] / rho[species]


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("case")
    p.add_argument("--tol", type=float, default=1e-8)
    p.add_argument("--tol-total", type=float, default=1e-10)
    p.add_argument("--tol-top", type=float, default=1e-5)
    a = p.parse_args()

    fill = logVolumes(os.path.join(a.case, "log.segregationDegradationFoam.fill"))
    discharge = logVolumes(os.path.join(a.case, "log.segregationDegradationFoam.discharge"))
    species = sorted(fill[0])
    rho = densities(a.case)
    missing = [sp for sp in species if sp not in rho]
    if missing:
        sys.exit("checkFill: no rho of %s in constant/granularProperties" % missing)
    patches = {name: records(a.case, name) for name in ("inlet", "outlet", "top")}

    def cum(stage, sp, row):
        return cumulative(stage, sp, row, rho)

    ok = True
    dep, depFirst = deposition.speciesTotals(a.case)
    fedTotal = sum(-sum(cum(stage, sp, -1) for stage in patches["inlet"])
                   + dep.get(sp, 0.0) for sp in species)
    if not fedTotal > 0:
        print("FAIL: nothing fed (%g m3)" % fedTotal)
        return 1
    errTotal = 0.0
    for sp in species:
        # The start: the first logged volume plus what left in the first
        # step (less what was deposited in it)
        start = fill[0][sp] + sum(cum(patches[name][0], sp, 0)
                                  for name in patches) - depFirst.get(sp, 0.0)
        through = {name: sum(cum(stage, sp, -1) for stage in patches[name])
                   for name in patches}
        through["inlet"] -= dep.get(sp, 0.0)
        expected = start - sum(through.values())
        end = discharge[-1][sp]
        err = (end - expected) / fedTotal
        errTotal += err
        print("%s: start %.10e, in %.10e, out %.10e, top %.3e, end %.10e"
              " (expected %.10e): balance %.3e of the fed"
              % (sp, start, -through["inlet"], through["outlet"],
                 through["top"], end, expected, err))
        if not abs(err) <= a.tol:
            print("FAIL: the balance of %s beyond %.1e" % (sp, a.tol))
            ok = False
    discharged = sum(cum(patches["outlet"][1], sp, -1) for sp in species)
    top = sum(cum(stage, sp, -1) for stage in patches["top"] for sp in species)
    closedInlet = sum(abs(cum(patches["inlet"][1], sp, -1)) for sp in species)
    print("fed %.6e m3, discharged %.6e m3, through the top %.3e of the fed,"
          " through the closed inlet %.3e of it; solids' balance %.3e"
          % (fedTotal, discharged, top / fedTotal, closedInlet / fedTotal,
             errTotal))
    if not discharged > 0:
        print("FAIL: nothing discharged")
        ok = False
    if not abs(errTotal) <= a.tol_total:
        print("FAIL: the solids' balance beyond %.1e" % a.tol_total)
        ok = False
    if not top <= a.tol_top * fedTotal:
        print("FAIL: more than %.1e of the fed through the top" % a.tol_top)
        ok = False
    if not closedInlet <= 1e-12 * fedTotal:
        print("FAIL: material through the closed inlet in the discharge")
        ok = False
    print("PASS" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
