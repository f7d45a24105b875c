"""Kinematic discharge of silo2D below a level free surface (tests/solver/silo.sh).

Usage: freeSurface.py CASE

Checks, from the run's outlet record, log and written nTotal fields:
- the mass flow through the outlet equals the Beverloo rate by hand (the
  wedge's share, packed solids fraction 0.6, rho 2500) within 2 % at every
  step while the free surface is in the cylinder (above the hopper);
- the free surface at every written time lies where the volume balance puts
  it, z = H - Qmesh t / A (A the cylinder's section on the mesh): the
  height where nTotal crosses half the packed fraction, found in every
  column of cells of the cylinder but the wall's and averaged over the
  section (weights r), is within half a cell height of it; the surface
  sinks into a shallow crater (the Nedderman-Tuzun draw reaches through the
  plug above the turn), whose slope stays below the angle of repose of
  glass beads (25 degrees).
"""
import math
import re
import sys

from sdfoam import foamcase
from sdfoam.beverloo import hopperRate

case = sys.argv[1]
packed, rho = 0.6, 2500.0
R, Hc, D0, theta, wedge = 0.15, 0.5, 0.04, 30.0, 5.0
Hh = (R - D0 / 2) / math.tan(math.radians(theta))
H = Hh + Hc
d = 0.8e-3 + 0.2 * 2e-3
Qfull = hopperRate(D0, d, theta)
Qmesh = Qfull * math.sin(math.radians(wedge)) / (2 * math.pi)
massRate = Qmesh * packed * rho

log = open(case + "/log.solver").read()
# The free surface level at the steps where the flux was recomputed
levels = []
time = 0.0
for line in log.splitlines():
    m = re.match(r"Time = (\S+)", line)
    if m:
        time = float(m.group(1))
    m = re.search(r"free surface at z = (\S+) m", line)
    if m:
        levels.append((time, float(m.group(1))))
tHopper = next((t for t, z in levels if z < Hh), float("inf"))

rows = [list(map(float, l.split())) for l in open(case + "/postProcessing/outletComposition/0/outlet.dat")
        if l.strip() and not l.startswith("#")]
inCylinder = [r for r in rows if r[0] < tHopper]
worst = max(abs(r[2] / massRate - 1) for r in inCylinder)
last = inCylinder[-1][0]
print("outlet mass flow vs Beverloo by hand %.6e kg/s: worst %.2e relative over %d steps to t = %.2f s"
      " (the surface reaches the hopper top at %.2f s)" % (massRate, worst, len(inCylinder), last, tHopper))
ok = worst < 0.02 and len(inCylinder) > 100

# Free-surface height against the volume balance
C = foamcase.cellCentres(case)
cyl = [i for i, c in enumerate(C) if c[2] > Hh]
area = None
dz = Hc / 67
columns = {}
for i in cyl:
    r = round(math.hypot(C[i][0], C[i][1]), 6)
    columns.setdefault(r, []).append(i)
rs = sorted(columns)
# The cylinder's section on the mesh: the wedge's triangle of radius R
area = R * R * math.sin(math.radians(wedge)) / 2
for t in foamcase.timeDirs(case):
    tv = float(t)
    zBalance = H - Qmesh * tv / area
    if zBalance < Hh + 3 * dz or zBalance > H - 3 * dz:
        continue
    nTotal = foamcase.readScalarField(case, t, "nTotal")
    off = []
    for r in rs[:-1]:          # every column but the wall's
        col = sorted(columns[r], key=lambda i: C[i][2])
        zc = None
        for a, b in zip(col, col[1:]):
            fa, fb = nTotal[a] / packed, nTotal[b] / packed
            if fa >= 0.5 > fb:
                zc = C[a][2] + (0.5 - fa) / (fb - fa) * (C[b][2] - C[a][2])
                break
        off.append(float("inf") if zc is None else zc - zBalance)
    if any(math.isinf(o) for o in off):
        print("t = %5.1f s: a column has no surface" % tv)
        ok = False
        continue
    mean = sum(o * r for o, r in zip(off, rs)) / sum(rs[:-1])
    slope = (max(off) - min(off)) / (rs[-2] - rs[0])
    print("t = %5.1f s: volume balance z = %.4f m; mean surface %+.5f m from it (%.2f cells);"
          " crater %+.4f..%+.4f m, slope %.1f deg"
          % (tv, zBalance, mean, mean / dz, min(off), max(off), math.degrees(math.atan(slope))))
    ok = ok and abs(mean) < 0.5 * dz and slope < math.tan(math.radians(25))
sys.exit(0 if ok else 1)
