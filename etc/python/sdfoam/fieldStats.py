"""Checks on the written fields of a segregationDegradationFoam case
(python3 standard library; reads ASCII fields with sdfoam.foamcase).

  python3 -m sdfoam.fieldStats CASE CHECK [options]; CHECK is one of
    bounds [--tol 1e-8] [--packed P]
                           0 <= n.* <= nTotal (+tol) and no non-finite value
                           in any field of any written time; with --packed
                           also nTotal <= P (+tol): no cell above the
                           packed solids fraction
    compare OTHER --tol T  max |n.*(CASE) - n.*(OTHER)| <= T at the latest
                           time of both
    changed --tol T        some n.* changed by more than T
    emptied                some cell full at t=0 (phi > 0.5) is empty
                           (< 1e-3) at the end
    inBulk --packed P [--tol 1e-8] [--uniform X]
                           sum_i n.i = P alpha.granular in every cell at
                           every written time (the species live in the
                           bulk of a free-surface flow, bulkFlow muI), and
                           with --uniform X the first species' share of
                           the solids is X (within 1e-6) wherever alpha >
                           1e-3 (a uniform fill advected without
                           segregation)
"""
import math
import os
import re
import sys

from sdfoam import foamcase

NONFINITE = re.compile(r"(?<![\w.])[-+]?(nan|inf|infinity)(?![\w.])", re.IGNORECASE)


def species(case, time):
    return sorted(f for f in os.listdir(os.path.join(case, time)) if f.startswith("n."))


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def bounds(case, tol, packed=None):
    times = foamcase.timeDirs(case, includeZero=True)
    if len(times) < 2:
        fail("no time written after 0 in " + case)
    worst = 0.0
    worstTotal = -math.inf
    for t in times:
        for f in os.listdir(os.path.join(case, t)):
            path = os.path.join(case, t, f)
            if os.path.isfile(path):
                with open(path, errors="replace") as fh:
                    m = NONFINITE.search(fh.read())
                if m:
                    fail("non-finite value '%s' in %s" % (m.group(0), path))
        names = species(case, t)
        fields = [foamcase.readScalarField(case, t, n) for n in names]
        total = [sum(v) for v in zip(*fields)]
        for n, vals in zip(names, fields):
            for i, v in enumerate(vals):
                if not math.isfinite(v):
                    fail("%s/%s cell %d: %r" % (t, n, i, v))
                worst = max(worst, -v, v - total[i])
                if v < -tol or v > total[i] + tol:
                    fail("%s/%s cell %d = %.3e outside [0, phi = %.3e]" % (t, n, i, v, total[i]))
        if packed is not None:
            i = max(range(len(total)), key=total.__getitem__)
            worstTotal = max(worstTotal, total[i] - packed)
            if total[i] > packed + tol:
                fail("%s: the species' sum in cell %d = %.10f above the packed fraction %g (tol %.1e)"
                     % (t, i, total[i], packed, tol))
    print("bounds hold at %d times; worst violation %.3e (tol %.1e)" % (len(times), worst, tol))
    if packed is not None:
        print("species' sum at most %g %+.3e" % (packed, worstTotal))


def compare(case, other, tol):
    t1 = foamcase.latestTime(case)
    t2 = foamcase.latestTime(other)
    if abs(float(t1) - float(t2)) > 1e-12 * max(1.0, abs(float(t1))):
        fail("latest times differ: %s vs %s" % (t1, t2))
    worst = 0.0
    for n in species(case, t1):
        a = foamcase.readScalarField(case, t1, n)
        b = foamcase.readScalarField(other, t2, n)
        if len(a) != len(b):
            fail("%s: %d vs %d cells" % (n, len(a), len(b)))
        worst = max(worst, max(abs(x - y) for x, y in zip(a, b)))
    print("max |difference| at t = %s: %.3e (tol %.1e)" % (t1, worst, tol))
    if not worst <= tol:
        fail("difference above tolerance")


def changed(case, tol):
    tEnd = foamcase.latestTime(case)
    worst = 0.0
    for n in species(case, "0"):
        a = foamcase.readScalarField(case, "0", n)
        b = foamcase.readScalarField(case, tEnd, n)
        worst = max(worst, max(abs(x - y) for x, y in zip(a, b)))
    print("largest change of a species fraction from t = 0 to %s: %.3e (must exceed %.1e)" % (tEnd, worst, tol))
    if not worst > tol:
        fail("the fields hardly changed: the test would not exercise the fluxes")


def emptied(case):
    t0 = "0"
    tEnd = foamcase.latestTime(case)
    names = species(case, t0)
    phi0 = [sum(v) for v in zip(*[foamcase.readScalarField(case, t0, n) for n in names])]
    phiEnd = [sum(v) for v in zip(*[foamcase.readScalarField(case, tEnd, n) for n in names])]
    count = sum(1 for a, b in zip(phi0, phiEnd) if a > 0.5 and b < 1e-3)
    print("%d cells went from full (phi > 0.5) to empty (phi < 1e-3) by t = %s" % (count, tEnd))
    if count == 0:
        fail("no cell emptied")


def inBulk(case, packed, tol, uniform=None):
    times = foamcase.timeDirs(case, includeZero=True)
    worst = 0.0
    worstShare = 0.0
    for t in times:
        names = species(case, t)
        alpha = foamcase.readScalarField(case, t, "alpha.granular")
        fields = [foamcase.readScalarField(case, t, n) for n in names]
        for i, (a, *ns) in enumerate(zip(alpha, *fields)):
            worst = max(worst, abs(sum(ns) - packed*a))
            if uniform is not None and a > 1e-3:
                worstShare = max(worstShare, abs(ns[0]/sum(ns) - uniform))
    print("sum of %s - %g alpha.granular: largest %.3e over %d times (tol %.1e)"
          % ("+".join(species(case, times[-1])), packed, worst, len(times), tol))
    if worst > tol:
        fail("species outside the bulk")
    if uniform is not None:
        print("share of %s where alpha > 1e-3: largest deviation from %g %.3e (tol 1e-6)"
              % (species(case, times[-1])[0], uniform, worstShare))
        if worstShare > 1e-6:
            fail("the composition of a uniform fill changed")


if __name__ == "__main__":
    case, what = sys.argv[1], sys.argv[2]
    args = sys.argv[3:]
    tol = float(args[args.index("--tol") + 1]) if "--tol" in args else 1e-8
    if what == "bounds":
        packed = float(args[args.index("--packed") + 1]) if "--packed" in args else None
        bounds(case, tol, packed)
    elif what == "compare":
        compare(case, args[0], tol)
    elif what == "changed":
        changed(case, tol)
    elif what == "emptied":
        emptied(case)
    elif what == "inBulk":
        uniform = float(args[args.index("--uniform") + 1]) if "--uniform" in args else None
        inBulk(case, float(args[args.index("--packed") + 1]), tol, uniform)
    else:
        fail("unknown check " + what)
