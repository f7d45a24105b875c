"""Discharge rates from an outlet record and the Beverloo fit
(benchmarks/muIBeverloo: the planar and the axisymmetric bin).

    readRuns(work)               (name, {option: value}) from WORK/runs.txt
                                 (a run's name, then its Allrun options)
    outletSeries(case, patch, scale)
                                 (t, mass flow, cumulative mass) through a
                                 patch (outletComposition), times scale
    measure(series, fill, t0, window, untilFraction)
                                 the rate over [t0, end] (or until that
                                 fraction of the fill has left), its
                                 constancy and the fraction discharged
    writeRateFile(path, series, fill, rateLabel)
                                 t, rate and discharged fraction as text
    timeMean(series, t0, t1)     time-weighted mean of (t, w) on [t0, t1]
    maxWindowDeviation(series, t0, t1, window)
                                 largest |mean over a window / mean - 1|
    fit(points, d, prefactor, kGrid)
                                 Q = prefactor C (D - k d)^n through
                                 points (D, Q): k on kGrid (the least-squares
                                 one kept), n and C by least squares in log Q
    fitFixedK(points, d, prefactor, k)
                                 the same at a given k, with the standard
                                 error of n
    hopperRate(D0, d, hopperHalfAngle, C, k, g)
                                 Beverloo's volume rate through a circular
                                 outlet of a conical hopper, as the
                                 kinematic bulk flow's dischargeRate
                                 beverloo takes it (the tutorials' C 0.58,
                                 k 1.5 by default)
"""
import math
import os


def hopperRate(D0, d, hopperHalfAngle, C=0.58, k=1.5, g=9.81):
    """C sqrt(g) (D0 - k d)^2.5 tan(hopperHalfAngle)^-0.35 [m3/s]: the
    whole outlet's rate, outlet diameter D0 and mean particle diameter d in
    m, the hopper's half angle in degrees."""
    return C * math.sqrt(g) * (D0 - k * d) ** 2.5 * math.tan(math.radians(hopperHalfAngle)) ** -0.35


def readRuns(work):
    """[(name, {option without '-': float})] from WORK/runs.txt, the runs
    whose cases wrote an outlet record (run -only leaves some out)."""
    runs = []
    for line in open(os.path.join(work, "runs.txt")):
        if line.strip():
            name, *opts = line.split()
            if not os.path.isdir(os.path.join(work, name, "postProcessing", "outletComposition")):
                print("readRuns: %s has no outlet record (not run, or failed): left out" % name)
                continue
            o = dict(zip(opts[::2], opts[1::2]))
            runs.append((name, {k.lstrip("-"): float(v) for k, v in o.items()}))
    return runs


def outletSeries(case, patch="outlet", scale=1.0):
    """[(t, mass flow, cumulative mass)] through the patch, from
    postProcessing/outletComposition/0/<patch>.dat (columns: time, Q, mass
    flow, then per species its mass flow, its mass fraction and, last, its
    cumulative mass), each mass times scale (e.g. 72 for a 5-degree
    wedge, 1/depth for a slab)."""
    rows = [l.split() for l in open(os.path.join(case, "postProcessing", "outletComposition", "0",
                                                 patch + ".dat"))
            if not l.startswith("#")]
    series = []
    for r in rows:
        nSpecies = (len(r) - 3) // 3
        series.append((float(r[0]), scale * float(r[2]),
                       scale * sum(float(x) for x in r[len(r) - nSpecies:])))
    return series


def measure(series, fill, t0, window, untilFraction=None):
    """(tEnd, rate, constancy, fraction discharged) of an outletSeries over
    [t0, tEnd]: tEnd the end of the record or, with untilFraction, the time
    that fraction of the fill (same mass units) has left; the rate its
    time-weighted mean, the constancy maxWindowDeviation."""
    ts = [(t, w) for t, w, _ in series]
    tEnd = series[-1][0]
    if untilFraction is not None:
        tEnd = next((t for t, _, m in series if m > untilFraction * fill), tEnd)
    massIn = [m for t, _, m in series if t0 <= t <= tEnd]
    return (tEnd, timeMean(ts, t0, tEnd), maxWindowDeviation(ts, t0, tEnd, window),
            (massIn[-1] - massIn[0]) / fill)


def writeRateFile(path, series, fill, rateLabel):
    """The series as text: t, rate, discharged fraction of the fill."""
    with open(path, "w") as f:
        f.write("# t[s] %s discharged_fraction\n" % rateLabel)
        for t, w, m in series:
            f.write("%.5f %.6f %.5f\n" % (t, w, m / fill))


def timeMean(series, t0, t1):
    """Time-weighted mean of (t, w) on [t0, t1] (trapezoidal between the
    solver's steps); nan when the interval holds no step."""
    acc = span = 0.0
    for (ta, wa), (tb, wb) in zip(series, series[1:]):
        a, b = max(ta, t0), min(tb, t1)
        if b > a:
            acc += 0.5 * (wa + wb) * (b - a)
            span += b - a
    return acc / span if span > 0 else float("nan")


def maxWindowDeviation(series, t0, t1, window):
    """Largest |mean over [a, a + window] / mean over [t0, t1] - 1| over
    consecutive windows from t0."""
    whole = timeMean(series, t0, t1)
    edges = [t0 + i * window for i in range(int((t1 - t0) / window + 1e-9))]
    return max(abs(timeMean(series, a, a + window) / whole - 1) for a in edges)


def _lsq(points, d, k):
    xs = [math.log(D - k * d) for D, _ in points]
    ys = [math.log(Q) for _, Q in points]
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
    icept = my - slope * mx
    res = sum((y - icept - slope * x) ** 2 for x, y in zip(xs, ys))
    return res, slope, icept, sxx


def fit(points, d, prefactor, kGrid):
    """(n, C, k, residual) of the least-squares fit of log Q; the k of
    kGrid (those with D - k d > 0 for every point) with the least residual."""
    Dmin = min(D for D, _ in points)
    res, n, icept, _, k = min((_lsq(points, d, k) + (k,) for k in kGrid if Dmin > k * d),
                              key=lambda r: r[0])
    return n, math.exp(icept) / prefactor, k, res


def fitFixedK(points, d, prefactor, k):
    """(n, standard error of n, C) at the given k."""
    res, n, icept, sxx = _lsq(points, d, k)
    se = math.sqrt(res / (len(points) - 2) / sxx) if len(points) > 2 else float("nan")
    return n, se, math.exp(icept) / prefactor


def richardson(coarse, medium, fine, ratio=2.0):
    """(observed order, Richardson estimate) of a quantity on three meshes
    refined by ratio: p = ln((coarse - medium)/(medium - fine))/ln(ratio),
    the estimate extrapolate(medium, fine, p); (nan, nan) when the three do
    not converge monotonically (the differences change sign or do not
    shrink)."""
    d1, d2 = coarse - medium, medium - fine
    if d1 == 0 or d2 == 0 or d1 * d2 < 0 or abs(d2) >= abs(d1):
        return float("nan"), float("nan")
    p = math.log(d1 / d2) / math.log(ratio)
    return p, extrapolate(medium, fine, p, ratio)


def extrapolate(medium, fine, order, ratio=2.0):
    """Richardson's estimate from two meshes refined by ratio at a known
    order: fine + (fine - medium)/(ratio^order - 1)."""
    return fine + (fine - medium) / (ratio ** order - 1)

