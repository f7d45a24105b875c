"""The record of a pour deposited where it lands (muICoeffs/deposition):
postProcessing/deposition/<start time>/deposition.dat, one per run of the
solver, each line the time, the bulk deposited per second in the step, the
bulk deposited in all and each species' solids deposited in all [m3] (the
species named in the header line "# time ...")."""
import glob
import os
import re


def records(case):
    """[(start time, species names, rows)] of every record, by start time."""
    out = []
    for path in glob.glob(os.path.join(case, "postProcessing", "deposition",
                                       "*", "deposition.dat")):
        names, rows = [], []
        with open(path) as f:
            for line in f:
                if line.startswith("# time"):
                    names = re.findall(r"solids (\w+) in all", line)
                elif line.strip() and not line.startswith("#"):
                    rows.append([float(v) for v in line.split()])
        start = float(os.path.basename(os.path.dirname(path)))
        out.append((start, names, rows))
    return sorted(out, key=lambda r: r[0])


def speciesTotals(case, upTo=None):
    """{species: solids volume} deposited in all by time upTo (default: the
    records' ends), summed over the records, and {species: volume} of the
    first run's first step."""
    total, first = {}, {}
    for start, names, rows in records(case):
        if upTo is not None:
            rows = [r for r in rows if r[0] <= upTo * (1 + 1e-12)]
        if not rows:
            continue
        for name, v in zip(names, rows[-1][-len(names):]):
            total[name] = total.get(name, 0.0) + v
        if not first:
            first = dict(zip(names, rows[0][-len(names):]))
    return total, first
