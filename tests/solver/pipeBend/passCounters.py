"""The counters of a particle pass with breakingRebound (its log's
"breakingRebound (fragments ...) from t = ... over T s:" blocks, one per
time step, cumulative over the counting window) as rates with their
batch-means standard errors: the window cut into K batches, each batch's
rate a sample, the error of their mean sd/sqrt(K). Batches of a steady
pass hold different particles, so they are close to independent.
"""
import math
import re
import statistics

_BLOCK = re.compile(r"breakingRebound \(fragments \w+\) from t = \S+ s over (\S+) s:[^\n]*\n"
                    r"((?:\s+\S+ \S+ \S+ \S+ \S+\n)+)")


def series(logPath):
    """[(T, {class: (impacts, events, broken, born)})] over the window."""
    out = []
    for T, body in _BLOCK.findall(open(logPath).read()):
        out.append((float(T), {l.split()[0]: tuple(map(float, l.split()[1:]))
                               for l in body.strip().splitlines()}))
    if not out or not out[-1][0] > 0:
        raise ValueError("no breakingRebound counters over a window in " + logPath)
    return out


def rate(logPath, quantity, K=10):
    """The mean rate of quantity(counters of one time) over the window and
    its batch-means standard error, both per second."""
    s = series(logPath)
    T = s[-1][0]
    marks = [min(s, key=lambda x: abs(x[0] - T * k / K)) for k in range(K + 1)]
    rates = [(quantity(b[1]) - quantity(a[1])) / (b[0] - a[0]) for a, b in zip(marks[:-1], marks[1:])]
    return (quantity(s[-1][1]) - quantity(marks[0][1])) / (T - marks[0][0]), statistics.stdev(rates) / math.sqrt(K)
