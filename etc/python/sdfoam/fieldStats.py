"""Checks on the written fields of a segregationDegradationFoam case
(python3 standard library; reads ASCII fields with sdfoam.foamcase).

  python3 -m sdfoam.fieldStats CASE CHECK [options]; CHECK is one of
    bounds [--tol 1e-8] [--packed P] [--tol-total R]
                           in every cell at every written time, every field
                           finite and, with P the case's largest solids
                           fraction,
                             -tol <= n_i <= P + T  for every species, and
                             sum_j n_j <= P + T
                           T = max(tol, R P) (R default 0): R holds the
                           total to a part of itself where tol is set for
                           a trace species far below it. P is --packed
                           when given, otherwise read from the case
                           (packedFraction below)
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

The largest solids fraction of a case (packedFraction(case)) follows the
bulk flow of constant/granularProperties (its #include files read):
  muI           muICoeffs packedFraction (default 0.6): the species live in
                the bulk, sum_j n_j = packedFraction alpha.granular
  kinematic     kinematicCoeffs packedFraction, by default the largest
                initial sum_j n_j, as the model itself takes it
  particlePass  1: every class moves with its own flux, nothing holds the
                total below a full cell (the solver stops above 1)
  any other     (one flux and one diffusivity for every species, exchange
                fluxes that leave each cell's total unchanged: the total
                obeys one bounded transport equation) the largest total at
                the first written time, over the cells and the values the
                boundaries hold (value, inletValue, refValue: the inflow)
"""
import math
import os
import re
import sys

from sdfoam import foamcase

NONFINITE = re.compile(r"(?<![\w.])[-+]?(nan|inf|infinity)(?![\w.])", re.IGNORECASE)


def species(case, time):
    """The species' fields n.<species> written at time: the species of
    constant/granularProperties when it names them, otherwise every n.*
    file but the old-time fields a second-order time scheme writes
    (n.fine_0)."""
    written = set(os.listdir(os.path.join(case, time)))
    path = os.path.join(case, "constant", "granularProperties")
    names = None
    if os.path.isfile(path):
        try:
            declared = readDict(path, case).get("species")
        except ValueError:
            declared = None
        if isinstance(declared, dict) and declared:
            names = ["n." + k for k in declared]
    if names is None:
        names = [f for f in written if f.startswith("n.") and not f.endswith("_0")]
    return sorted(n for n in names if n in written)


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


_TOKEN = re.compile(r'"[^"]*"|[{}();]|\d+\{[^{}]*\}|[^\s{}();"]+')


def _tokens(text):
    """The tokens of an OpenFOAM dictionary's text (comments removed): a
    word glued to a bracketed group, like div(phi,n), stays one token."""
    out = []
    pos = 0
    text = foamcase.stripComments(text)
    while True:
        m = _TOKEN.search(text, pos)
        if not m:
            return out
        tok, pos = m.group(0), m.end()
        if tok[0].isalpha() and text.startswith("(", pos):
            depth, end = 0, pos
            while end < len(text):
                depth += {"(": 1, ")": -1}.get(text[end], 0)
                end += 1
                if depth == 0:
                    break
            tok, pos = tok + text[pos:end], end
        out.append(tok)


def _merge(into, other):
    """OpenFOAM's default #inputMode merge: a dictionary entry read again
    merges into the first, any other entry replaces it."""
    for k, v in other.items():
        if isinstance(v, dict) and isinstance(into.get(k), dict):
            _merge(into[k], v)
        else:
            into[k] = v


def _includePath(name, here, case):
    name = name.strip('"')
    for var in ("$FOAM_CASE", "${FOAM_CASE}", "<case>"):
        name = name.replace(var, case)
    name = name.replace("<constant>", os.path.join(case, "constant"))
    name = name.replace("<system>", os.path.join(case, "system"))
    return name if os.path.isabs(name) else os.path.join(here, name)


def _parse(tok, i, here, case):
    d = {}
    while i < len(tok) and tok[i] != "}":
        key = tok[i]
        if key in ("#include", "#includeIfPresent"):
            path = _includePath(tok[i + 1], here, case)
            if os.path.isfile(path):
                _merge(d, readDict(path, case))
            elif key == "#include":
                raise ValueError("#include %s: no such file" % path)
            i += 2
            continue
        if key.startswith("#"):
            # #inputMode, #remove and the like: the directive and its word
            i += 2
            continue
        if i + 1 < len(tok) and tok[i + 1] == "{":
            sub, i = _parse(tok, i + 2, here, case)
            i += 1
            if isinstance(d.get(key), dict):
                _merge(d[key], sub)
            else:
                d[key] = sub
            continue
        value, i, depth = [], i + 1, 0
        while i < len(tok) and not (tok[i] == ";" and depth == 0):
            depth += {"(": 1, ")": -1}.get(tok[i], 0)
            value.append(tok[i])
            i += 1
        d[key] = value
        i += 1
    return d, i


def readDict(path, case=None):
    """The entries of an OpenFOAM dictionary file as nested dicts (an entry's
    value: the list of its tokens), #include and #includeIfPresent files
    read, later entries merged into or replacing earlier ones."""
    case = case or os.path.dirname(os.path.dirname(os.path.abspath(path)))
    with open(path, errors="replace") as fh:
        tok = _tokens(fh.read())
    return _parse(tok, 0, os.path.dirname(os.path.abspath(path)), case)[0]


def _scalar(value, where):
    """The number of a scalar entry (the last token: 'packedFraction 0.6;'
    or a dimensioned 'packedFraction [0 0 0 0 0] 0.6;')."""
    try:
        return float(value[-1])
    except (IndexError, ValueError):
        raise ValueError("%s: a number expected, got '%s'" % (where, " ".join(value)))


def _boundaryTotal(case, time, names):
    """The largest sum over the species of the values a patch holds (value,
    inletValue, refValue) at time: what an inflow brings in."""
    perPatch = {}
    for n in names:
        path = os.path.join(case, time, n)
        with open(path, errors="replace") as fh:
            text = fh.read()
        k = text.find("boundaryField")
        if k < 0:
            continue
        patches = _parse(_tokens(text[k:]), 2, case, case)[0]
        for patch, entries in patches.items():
            if not isinstance(entries, dict):
                continue
            vals = []
            for key in ("value", "inletValue", "refValue"):
                v = entries.get(key)
                if not isinstance(v, list) or not v:
                    continue
                if v[0] == "uniform" and len(v) == 2:
                    vals.append(float(v[1]))
                elif v[0] == "nonuniform" and len(v) > 2:
                    # List<scalar> N{x} or List<scalar> N ( x ... )
                    m = re.fullmatch(r"\d+\{(.*)\}", v[2])
                    if m:
                        vals.append(float(m.group(1)))
                    else:
                        vals.extend(float(x) for x in v[3:] if x not in ("(", ")"))
            if vals:
                perPatch[patch] = perPatch.get(patch, 0.0) + max(vals)
    return max(perPatch.values()) if perPatch else -math.inf


def packedFraction(case):
    """(P, how): the largest solids fraction the case admits, by the rule of
    the module's docstring, and how it was found."""
    first = foamcase.timeDirs(case, includeZero=True)[0]
    names = species(case, first)

    def initialTotal():
        fields = [foamcase.readScalarField(case, first, n) for n in names]
        return max(sum(v) for v in zip(*fields))

    path = os.path.join(case, "constant", "granularProperties")
    if not os.path.isfile(path):
        fail("%s not found: give the largest solids fraction with --packed P" % path)
    try:
        props = readDict(path, case)
        bulk = props.get("bulkFlow")
        if not isinstance(bulk, dict) or not bulk.get("model"):
            raise ValueError("no bulkFlow { model ...; }")
        model = bulk["model"][0]
        coeffs = bulk.get(model + "Coeffs", {})
        given = coeffs.get("packedFraction") if isinstance(coeffs, dict) else None
        where = "%s bulkFlow/%sCoeffs/packedFraction" % (path, model)
        if model == "muI":
            return (_scalar(given, where) if given else 0.6,
                    "bulkFlow muI, packedFraction" + ("" if given else " (default)"))
        if model == "kinematic":
            if given:
                return _scalar(given, where), "bulkFlow kinematic, packedFraction"
            return initialTotal(), "bulkFlow kinematic, the largest initial total"
        if model == "particlePass":
            return 1.0, "bulkFlow particlePass: a full cell"
        return (max(initialTotal(), _boundaryTotal(case, first, names)),
                "bulkFlow %s: the largest total in the cells and on the boundaries at t = %s"
                % (model, first))
    except ValueError as e:
        fail("%s: %s; give the largest solids fraction with --packed P" % (path, e))


def bounds(case, tol, packed=None, tolTotal=0.0):
    times = foamcase.timeDirs(case, includeZero=True)
    if len(times) < 2:
        fail("no time written after 0 in " + case)
    if not species(case, times[0]):
        fail("no n.* field in %s/%s" % (case, times[0]))
    if packed is None:
        packed, how = packedFraction(case)
    else:
        how = "given"
    upper = max(tol, tolTotal * packed)
    lowest = math.inf
    highest = -math.inf
    highestTotal = -math.inf
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
        for n, vals in zip(names, fields):
            for i, v in enumerate(vals):
                if not math.isfinite(v):
                    fail("%s/%s cell %d: %r" % (t, n, i, v))
                lowest = min(lowest, v)
                highest = max(highest, v)
                if v < -tol:
                    fail("%s/%s cell %d = %.3e below 0 (tol %.1e)" % (t, n, i, v, tol))
                if v > packed + upper:
                    fail("%s/%s cell %d = %.10g above the largest solids fraction %.10g (%s; tol %.1e)"
                         % (t, n, i, v, packed, how, upper))
        total = [sum(v) for v in zip(*fields)]
        i = max(range(len(total)), key=total.__getitem__)
        highestTotal = max(highestTotal, total[i])
        if total[i] > packed + upper:
            fail("%s: the species' sum in cell %d = %.10g above the largest solids fraction %.10g (%s; tol %.1e)"
                 % (t, i, total[i], packed, how, upper))
    print("bounds hold at %d times: n_i from %.3e to %.6g, sum_j n_j at most %.10g = P %+.3e; "
          "P = %.10g (%s); tol %.1e, above P %.1e"
          % (len(times), lowest, highest, highestTotal, highestTotal - packed, packed, how, tol, upper))


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
        tolTotal = float(args[args.index("--tol-total") + 1]) if "--tol-total" in args else 0.0
        bounds(case, tol, packed, tolTotal)
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
