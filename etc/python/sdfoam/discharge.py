"""What leaves a bin, binned: the fines' share of each 5 % of the fill and
the discharge rate (benchmarks/siloFillDEM: its DEM peer's analyse and the
continuum's compare measure both the same way); and the peer's settled
grains (its fill.dump), which analyse, compare and surface read.

outs: (time, cumulative fines out, cumulative coarse out) in time order, in
any unit of amount (volume, mass per depth); total: the fill in that unit.
"""


def settledGrains(path):
    """[(x, z, diameter)] of the grains in a LAMMPS dump of columns id x z
    diameter (benchmarks/siloFillDEM/in.siloFill's fill.dump)."""
    with open(path) as f:
        lines = f.read().splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS")) + 1
    grains = []
    for l in lines[start:]:
        _, x, z, dia = l.split()
        grains.append((float(x), float(z), float(dia)))
    return grains


def shareBins(outs, total, nBins=20):
    """(bin centre as a fraction of the fill, fines' share of what left in
    the bin, time at the first record past the bin's edge) for each bin
    the records reach, to 1e-6 of the fill: a continuum bin that empties
    keeps a film of bulk decaying in its last cells (2.5e-9 to 2.5e-7 of
    the fill after the peer's hopper), so its last bin would never
    close."""
    res, prev, k = [], (0.0, 0.0), 1
    width = 1.0 / nBins
    for t, oF, oC in outs:
        while k <= nBins and oF + oC >= width * k * total - 1e-6 * total:
            dF, dC = oF - prev[0], oC - prev[1]
            res.append((width * (k - 0.5),
                        dF / (dF + dC) if dF + dC > 0 else float("nan"), t))
            prev = (oF, oC)
            k += 1
    return res


def firstHalfRate(outs, total):
    """Mean rate of the amount leaving while the first half of the fill
    leaves, after that half's first fifth of records (the start-up); nan
    with 10 records or fewer."""
    half = [(t, oF + oC) for t, oF, oC in outs if oF + oC <= 0.5 * total]
    if len(half) <= 10:
        return float("nan")
    t0, m0 = half[len(half) // 5]
    t1, m1 = half[-1]
    return (m1 - m0) / (t1 - t0) if t1 > t0 else float("nan")
