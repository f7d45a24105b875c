"""The exact solution of Ziff & McGrady (1985, J. Phys. A 18, 3027) for the
breakage checks (python3 standard library only).

Breakage with selection rate S = v^2 and uniform binary fragments from one
particle of volume v0 = 1 at t = 0 (numbers per initial particle):

    n(v, t) = 2 t exp(-t v^2) for v < 1, plus exp(-t) particles at v = 1
    M0(t) = sqrt(pi t) erf(sqrt t) + exp(-t)
    M2(t) = sqrt(pi) erf(sqrt t) / (2 sqrt t)

classNumbers gives the exact number each class of a fixed-pivot grid
stands for: int hat_i(v) n(v, t) dv with the pivot's hat function (the
finest class: only the upper half, what lies below its pivot is dust; the
top class: plus the surviving exp(-t)).
"""

import math

__all__ = ["numberDensity", "moment0", "moment2", "simpson", "classNumbers"]


def numberDensity(v, t):
    return 2 * t * math.exp(-t * v * v)


def moment0(t):
    return math.sqrt(math.pi * t) * math.erf(math.sqrt(t)) + math.exp(-t)


def moment2(t):
    return math.sqrt(math.pi) * math.erf(math.sqrt(t)) / (2 * math.sqrt(t))


def simpson(f, a, b, n=400):
    """Composite Simpson rule with n (even) intervals."""
    h = (b - a) / n
    s = f(a) + f(b)
    for k in range(1, n):
        s += (4 if k % 2 else 2) * f(a + k * h)
    return s * h / 3


def classNumbers(x, t):
    """Exact numbers of the classes of pivots x (increasing, x[-1] = 1)."""
    m = len(x) - 1
    out = []
    for i in range(m + 1):
        s = 0.0
        if i > 0:
            s += simpson(lambda v: (v - x[i - 1]) / (x[i] - x[i - 1])
                         * numberDensity(v, t), x[i - 1], x[i])
        if i < m:
            s += simpson(lambda v: (x[i + 1] - v) / (x[i + 1] - x[i])
                         * numberDensity(v, t), x[i], x[i + 1])
        out.append(s)
    out[m] += math.exp(-t)
    return out
