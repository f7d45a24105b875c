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
<patch>.dat, positive leaving; each stage's record starts from 0).

Exit status 1 if a species' balance is off by more than --tol (relative to
what entered), the solids' by more than --tol-total, nothing entered or
nothing was discharged, or more than --tol-top of what entered left
through the top.

Usage: checkFill.py CASE [--tol 1e-8] [--tol-total 1e-10] [--tol-top 1e-5]
"""
import argparse
import glob
import os
import re
import sys

rhoS = 2500.0


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


def cumulative(record, species, row):
    header, rows = record
    return rows[row][header.index("cumulativeMass.%s[kg]" % species)] / rhoS


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
    patches = {name: records(a.case, name) for name in ("inlet", "outlet", "top")}

    ok = True
    fedTotal = sum(-sum(cumulative(stage, sp, -1) for stage in patches["inlet"])
                   for sp in species)
    errTotal = 0.0
    for sp in species:
        # The start: the first logged volume plus what left in the first step
        start = fill[0][sp] + sum(cumulative(patches[name][0], sp, 0)
                                  for name in patches)
        through = {name: sum(cumulative(stage, sp, -1) for stage in patches[name])
                   for name in patches}
        expected = start - sum(through.values())
        end = discharge[-1][sp]
        err = (end - expected) / fedTotal
        errTotal += err
        print("%s: start %.10e, in %.10e, out %.10e, top %.3e, end %.10e"
              " (expected %.10e): balance %.3e of the fed"
              % (sp, start, -through["inlet"], through["outlet"],
                 through["top"], end, expected, err))
        ok = ok and abs(err) <= a.tol
    discharged = sum(cumulative(patches["outlet"][1], sp, -1) for sp in species)
    top = sum(cumulative(stage, sp, -1) for stage in patches["top"] for sp in species)
    print("fed %.6e m3, discharged %.6e m3, through the top %.3e of the fed;"
          " solids' balance %.3e" % (fedTotal, discharged, top / fedTotal, errTotal))
    if not (fedTotal > 0 and discharged > 0):
        print("FAIL: nothing fed or nothing discharged")
        ok = False
    if not (abs(errTotal) <= a.tol_total and top <= a.tol_top * fedTotal):
        print("FAIL: the solids' balance or the top's outflow")
        ok = False
    if not ok:
        print("FAIL: a species' balance beyond %.1e" % a.tol)
    print("PASS" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
