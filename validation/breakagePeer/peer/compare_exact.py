#!/usr/bin/env python3
"""Compare the v1912 peer (extract.py output) with the exact solution.

Exact solution (Ziff & McGrady 1985, J. Phys. A 18:3027) of the pure
breakage equation with selection rate S(v) = v^2 and uniform binary
daughters b(v|v') = 2/v', monodisperse start N0 delta(v - v0), v0 = 1:

    n(v, t) = N0 [ exp(-t) delta(v - 1) + 2 t exp(-t v^2) ],   0 < v < 1

(check: d/dt of the smooth part = 2 N0 exp(-t v^2) - v^2 n, and the gain
2 int_v^1 v' n dv' + 2 N0 exp(-t) = 2 N0 exp(-t v^2)).  Integrals over a
class interval [a, b]:

    number  N0 sqrt(pi t) [erf(sqrt(t) b) - erf(sqrt(t) a)]
    volume  N0 [exp(-t a^2) - exp(-t b^2)]

(the total volume is N0 at all times).  A class interval is bounded by the
geometric means of neighbouring pivots, sqrt(v_{i-1} v_i) and
sqrt(v_i v_{i+1}); the lowest class starts at v_0/sqrt(r), the highest ends
at sqrt(v_n v_n r) > 1 and so holds the surviving delta N0 exp(-t).
Also given: the same with v1912's own class boundaries (halfway between
pivots, populationBalanceModel::v_), which for a constant density match the
fixed-pivot hat functions (the geometric edges give a class 2 % narrower in
v for r = 1.5, hence a systematic +2 % on the small classes).

Two further references are computed (--ref, plain python):
  * 'ode': the semi-discrete equations v1912 solves for one velocity group
    (fixed pivot, Kumar & Ramkrishna 1996, with v1912's uniformBinary n_ik,
    which drops the fragments below v_0, plus the velocityGroup term
    -f*dmdt that returns that volume to the classes in proportion to f),
    integrated with RK4 at dt/100: the error of the size grid alone.
  * 'ode-raw': the same without the -f*dmdt term (the birth/death source
    terms alone): this one loses the fragments below v_0 (and half of what
    breaks in class 0), e.g. 8 classes, r = 1.5, S = 1, t = 5 keep 0.672 of
    the volume; the full v1912 equations keep 1 (see README.md).
  * 'replica': the ode equations, time-stepped as reactingMultiphaseEulerFoam does
    it for one phase (Euler implicit, sources of all classes from the
    previous iterate, 2 outer correctors, the -f*dmdt term with dmdt from
    the previous iterate, the death term implicit): should equal the peer
    run with --split single to round-off.  (--split foundation moves the
    classes of air1/air2/air3 between phases through pDmdt and alpha; the
    replica does not model that, compare it as a check only.)

Usage: compare_exact.py RESULTSDIR [--time T] [--power 2] [--dt 0.1]
                        [--nouter 2] [--out FILE]
RESULTSDIR holds classes_all.dat and volume.dat from extract.py.
Python 3 standard library only (numpy is not needed).
"""
import argparse
import math
import os
import sys


def read_classes_all(path):
    rows = {}
    alpha0 = None
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                if "alpha0 =" in line:
                    alpha0 = float(line.split("alpha0 =")[1].split()[0])
                continue
            t, i, v, n, a, ar = line.split()
            rows.setdefault(float(t), []).append((int(i), float(v), float(n), float(a)))
    return rows, alpha0


# ------------------------------------------------------------------ exact
def exact_number(a, b, t, N0):
    """Number in [a, b] of the smooth part (v < 1), N0 = initial number."""
    b = min(b, 1.0)
    if b <= a:
        return 0.0
    if t == 0:
        return 0.0
    s = math.sqrt(t)
    return N0 * math.sqrt(math.pi * t) * (math.erf(s * b) - math.erf(s * a))


def exact_volume(a, b, t, N0):
    b = min(b, 1.0)
    if b <= a:
        return 0.0
    return N0 * (math.exp(-t * a * a) - math.exp(-t * b * b))


def edges(v):
    n = len(v)
    r = v[1] / v[0]
    lo = [v[0] / math.sqrt(r)] + [math.sqrt(v[i - 1] * v[i]) for i in range(1, n)]
    hi = [math.sqrt(v[i] * v[i + 1]) for i in range(n - 1)] + [v[-1] * math.sqrt(r)]
    return lo, hi


def edges_arith(v):
    """v1912's own class boundaries (populationBalanceModel::v_, used by
    the sizeDistribution function object): halfway between pivots, the
    first and last boundaries at the first and last pivots."""
    n = len(v)
    b = [v[0]] + [0.5 * (v[i] + v[i + 1]) for i in range(n - 1)] + [v[-1]]
    # extend the end classes symmetrically (half-widths as the neighbours)
    lo = [v[0] - 0.5 * (v[1] - v[0])] + b[1:n]
    hi = b[1:n] + [v[-1] + 0.5 * (v[-1] - v[-2])]
    return lo, hi


def exact_classes(v, t, N0, arith=False):
    lo, hi = edges_arith(v) if arith else edges(v)
    N = [exact_number(lo[i], hi[i], t, N0) for i in range(len(v))]
    V = [exact_volume(lo[i], hi[i], t, N0) for i in range(len(v))]
    # the surviving parent particles (delta at v = 1) sit in the top class
    N[-1] += N0 * math.exp(-t)
    V[-1] += N0 * math.exp(-t)
    return lo, hi, N, V


def exact_total_number(t, N0):
    return N0 * (math.exp(-t) + math.sqrt(math.pi * t) * math.erf(math.sqrt(t)))


# ----------------------------------------------- v1912 discrete equations
def nik_uniformBinary(x, i, k):
    """v1912 daughterSizeDistributionModels::uniformBinary::calcNik."""
    if i == 0:
        return (x[1] - x[0]) / x[k]
    elif i == k:
        return (x[i] - x[i - 1]) / x[k]
    return (x[i + 1] - x[i]) / x[k] + (x[i] - x[i - 1]) / x[k]


def make_nik(x):
    return [[nik_uniformBinary(x, i, k) if i <= k else 0.0 for k in range(len(x))]
            for i in range(len(x))]


def sources(x, S, nik, f, alpha):
    """Su_i (1/s, volume fraction) and SuSp_i as populationBalanceModel::
    birthByBreakup / deathByBreakup (one phase, phase fraction alpha)."""
    n = len(x)
    Su = [0.0] * n
    for k in range(n):
        src = S[k] * f[k] * alpha / x[k]          # breakup events of class k
        if src == 0.0:
            continue
        for i in range(k + 1):
            Su[i] += x[i] * nik[i][k] * src
    SuSp = [S[i] * alpha for i in range(n)]
    return Su, SuSp


def ode_reference(x, power, t_out, dt, compensate=True):
    """RK4 of alpha df_i/dt = Su_i - SuSp_i f_i - f_i dmdt (one phase);
    compensate=False drops the -f_i dmdt term: the source terms alone."""
    n = len(x)
    S = [xi ** power for xi in x]
    nik = make_nik(x)
    alpha = 1.0                          # scales out (f is a fraction)

    def rhs(f):
        Su, SuSp = sources(x, S, nik, f, alpha)
        dmdt = sum(Su[i] - SuSp[i] * f[i] for i in range(n))
        if not compensate:
            dmdt = 0.0
        return [(Su[i] - SuSp[i] * f[i] - f[i] * dmdt) / alpha for i in range(n)]

    f = [0.0] * n
    f[-1] = 1.0
    out = {0.0: list(f)}
    t = 0.0
    for tt in sorted(t_out):
        nsteps = max(1, int(round((tt - t) / dt)))
        h = (tt - t) / nsteps
        for _ in range(nsteps):
            k1 = rhs(f)
            k2 = rhs([f[i] + 0.5 * h * k1[i] for i in range(n)])
            k3 = rhs([f[i] + 0.5 * h * k2[i] for i in range(n)])
            k4 = rhs([f[i] + h * k3[i] for i in range(n)])
            f = [f[i] + h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]) for i in range(n)]
        t = tt
        out[tt] = list(f)
    return out


def replica(x, power, t_out, dt, nouter, alpha, residualAlpha=1e-6):
    """populationBalanceModel::solve() for one phase, Euler implicit."""
    n = len(x)
    S = [xi ** power for xi in x]
    nik = make_nik(x)
    f = [0.0] * n
    f[-1] = 1.0
    out = {0.0: list(f)}
    nsteps = int(round(max(t_out) / dt))
    want = {int(round(t / dt)): t for t in t_out}
    for step in range(1, nsteps + 1):
        f0 = list(f)
        for _ in range(nouter):
            Su, SuSp = sources(x, S, nik, f, alpha)
            dmdt = sum(Su[i] - SuSp[i] * f[i] for i in range(n))   # dmdt()
            # fvm::ddt(alpha,rho,f) - fvm::Sp(ddt(alpha rho) - dmdt, f)
            #   == Su - fvm::SuSp(SuSp, f)
            #    + fvc::ddt(residualAlpha rho, f) - fvm::ddt(residualAlpha rho, f)
            # (alpha constant: ddt(alpha rho) = 0; rho cancels; SuSp >= 0,
            # so fvm::SuSp is implicit; dmdt enters the diagonal.)
            fc = f
            f = [(alpha * f0[i] / dt + Su[i] + residualAlpha * fc[i] / dt)
                 / (alpha / dt + dmdt + SuSp[i] + residualAlpha / dt)
                 for i in range(n)]
        if step in want:
            out[want[step]] = list(f)
    return out


# ------------------------------------------------------------------- main
def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("results")
    ap.add_argument("--time", type=float, default=None, help="default: last")
    ap.add_argument("--power", type=float, default=2.0)
    ap.add_argument("--dt", type=float, default=0.1, help="the peer's deltaT")
    ap.add_argument("--nouter", type=int, default=2)
    ap.add_argument("--no-ref", action="store_true",
                    help="skip the ode/replica references")
    ap.add_argument("--out", default=None,
                    help="default RESULTSDIR/compare_t<T>.dat")
    a = ap.parse_args()

    rows, alpha0 = read_classes_all(os.path.join(a.results, "classes_all.dat"))
    times = sorted(rows)
    T = times[-1] if a.time is None else a.time
    if T not in rows:
        sys.exit("time %g not in classes_all.dat" % T)
    N0 = alpha0                          # all particles start at v0 = 1 m^3
    v = [r[1] for r in rows[T]]
    if abs(v[-1] - 1.0) > 1e-12:
        sys.exit("the largest class must be v = 1 (the exact solution has v0 = 1)")
    exact_ok = a.power == 2.0
    ref = {}
    if not a.no_ref:
        ref["ode"] = ode_reference(v, a.power, times[1:], a.dt / 100.0)
        ref["ode-raw"] = ode_reference(v, a.power, times[1:], a.dt / 100.0, False)
        ref["replica"] = replica(v, a.power, times[1:], a.dt, a.nouter, alpha0)

    lines = []
    P = lines.append
    P("# v1912 peer vs exact (Ziff & McGrady 1985, S = v^%g, uniform binary), t = %g, N0 = %g"
      % (a.power, T, N0))
    P("# classes: %d, v_i = %g^(i-%d); intervals: geometric-mean edges"
      % (len(v), v[1] / v[0], len(v) - 1))
    P("# numbers are N/N0 (N0 = alpha0 = initial number in the 1 m^3 cell)")
    cols = ["class", "v_i", "lo", "hi", "N_peer", "N_exact", "relerr_N",
            "N_exact_arith", "relerr_arith"]
    if ref:
        cols += ["N_ode", "N_replica", "peer/replica-1"]
    cols += ["Vfrac_peer", "Vfrac_exact"]
    P("# " + "  ".join(cols))
    lo, hi, Nex, Vex = exact_classes(v, T, N0) if exact_ok else (None, None, None, None)
    Nar = exact_classes(v, T, N0, arith=True)[2] if exact_ok else None
    errs_ar = []
    if lo is None:
        lo, hi = edges(v)
    errs = []
    rep_errs = []
    for i, vi, Np, ap_ in rows[T]:
        rec = [i, vi, lo[i], hi[i], Np / N0]
        if exact_ok:
            e = Np / Nex[i] - 1.0 if Nex[i] > 0 else float("nan")
            errs.append((i, e, Vex[i] / N0))
            ea = Np / Nar[i] - 1.0 if Nar[i] > 0 else float("nan")
            errs_ar.append((i, ea, Vex[i] / N0))
            rec += [Nex[i] / N0, e, Nar[i] / N0, ea]
        else:
            rec += [float("nan")] * 4
        if ref:
            No = ref["ode"][T][i] / vi
            Nr = ref["replica"][T][i] / vi
            rr = (Np / N0) / Nr - 1.0 if Nr > 0 else float("nan")
            rep_errs.append(rr)
            rec += [No, Nr, rr]
        rec += [ap_ / alpha0, Vex[i] / N0 if exact_ok else float("nan")]
        P(" ".join(("%d" % x) if isinstance(x, int) else ("% .6e" % x) for x in rec))

    Vp = sum(r[3] for r in rows[T]) / alpha0
    Np_tot = sum(r[2] for r in rows[T]) / N0
    P("#")
    P("# totals at t = %g:" % T)
    P("#   volume  V/V0: peer %.10f   exact 1" % Vp)
    if exact_ok:
        P("#   number  N/N0: peer %.8f   exact in [lo_0, 1] %.8f   exact total %.8f"
          " (below lo_0: %.3e)"
          % (Np_tot, sum(Nex) / N0, exact_total_number(T, N0) / N0,
             exact_number(0.0, lo[0], T, N0) / N0))
    if ref:
        for name in ("ode", "ode-raw", "replica"):
            f = ref[name][T]
            P("#   %-7s V/V0 = %.10f  N/N0 = %.8f" % (name, sum(f), sum(f[i] / v[i] for i in range(len(v)))))
        P("#   max |peer/replica - 1| over classes: %.3e" % max(abs(x) for x in rep_errs))
    if exact_ok:
        big = [e for i, e, vf in errs if vf >= 1e-3]
        P("#   per-class number error vs exact: max |e| = %.4f (class %d), "
          "classes with >= 0.1%% of the volume (%d): max |e| = %.4f, rms = %.4f"
          % (max(abs(e) for _, e, _ in errs),
             max(errs, key=lambda r: abs(r[1]))[0], len(big),
             max(abs(e) for e in big), math.sqrt(sum(e * e for e in big) / len(big))))
        big_ar = [e for i, e, vf in errs_ar if vf >= 1e-3]
        P("#   same with v1912's arithmetic-mean edges: max |e| = %.4f (class %d), "
          "classes with >= 0.1%% of the volume: max |e| = %.4f, rms = %.4f"
          % (max(abs(e) for _, e, _ in errs_ar),
             max(errs_ar, key=lambda r: abs(r[1]))[0],
             max(abs(e) for e in big_ar), math.sqrt(sum(e * e for e in big_ar) / len(big_ar))))
        inner = [e for i, e, _ in errs[1:-1]]
        inner_ar = [e for i, e, _ in errs_ar[1:-1]]
        P("#   classes 1..n-2 (no end class): geometric edges e in [%+.4f, %+.4f], "
          "arithmetic edges e in [%+.4f, %+.4f]"
          % (min(inner), max(inner), min(inner_ar), max(inner_ar)))
    P("#")
    P("# time series: t  V/V0_peer  N/N0_peer  N/N0_exact_total"
      + ("  V/V0_replica  N/N0_replica" if ref else ""))
    for t in times:
        Vt = sum(r[3] for r in rows[t]) / alpha0
        Nt = sum(r[2] for r in rows[t]) / N0
        s = "#   %4g  %.10f  %.8f  %.8f" % (t, Vt, Nt, exact_total_number(t, N0) / N0
                                           if exact_ok else float("nan"))
        if ref:
            f = ref["replica"][t]
            s += "  %.10f  %.8f" % (sum(f), sum(f[i] / v[i] for i in range(len(v))))
        P(s)
    text = "\n".join(lines) + "\n"
    out = a.out or os.path.join(a.results, "compare_t%g.dat" % T)
    with open(out, "w") as f:
        f.write(text)
    sys.stdout.write(text)


if __name__ == "__main__":
    main()
