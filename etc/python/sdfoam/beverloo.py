"""Discharge rates from an outlet record and the Beverloo fit
(benchmarks/muIBeverloo: the planar and the axisymmetric bin).

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
"""
import math


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
