"""Checks of a tutorials/silo3D run (tests/solver/silo3D.sh): usage
checkTutorial.py CASE. Exit status 1 on the first failed check.

- checkMesh: "Mesh OK." and polyhedral cells (snappyHexMesh's refinement
  transitions), the volume within 1 % of the silo's;
- the orifice the solver took from the mesh: D0 within 3 % of the 40 mm of
  the surface (a snapped circle of cells);
- the discharge: Q = C sqrt(g) (D0 - k d)^2.5 (tan 30 deg)^-0.35 by hand
  (C 0.58, k 1.5, d 1.2 mm) equals the solver's to 1e-9, and the outlet mass
  flow is rho_s phi_packed Q (2500 x 0.6) at every step to 1e-6 until the
  surface descends near the hopper;
- mass balance: solids lost from the silo = solids out through outlet and
  top, to 1e-6 relative;
- pictures: the two mid-plane PNGs exist, sized as rendered, not uniform.
"""
import math
import os
import re
import struct
import sys
import zlib

from sdfoam.beverloo import hopperRate

case = sys.argv[1]
failed = []


def check(ok, msg):
    print(("ok    " if ok else "FAIL  ") + msg)
    if not ok:
        failed.append(msg)


# Mesh
cm = open(os.path.join(case, "log.checkMesh")).read()
check("\nMesh OK." in cm, "checkMesh: Mesh OK.")
poly = int(re.search(r"polyhedra:\s+(\d+)", cm).group(1))
cells = int(re.search(r"cells:\s+(\d+)", cm).group(1))
volume = float(re.search(r"Total volume = (\S+?)\.?\s", cm).group(1))
R, Hc, r0 = 0.15, 0.5, 0.02
Hh = (R - r0) / math.tan(math.radians(30))
exact = math.pi * R**2 * Hc + math.pi * Hh * (R**2 + R * r0 + r0**2) / 3
check(poly > 0, "%d polyhedra among %d cells" % (poly, cells))
check(abs(volume / exact - 1) < 1e-2,
      "mesh volume %.6g m3 vs the silo's %.6g (%.2e)" % (volume, exact, volume / exact - 1))

# Orifice and rate
log = open(os.path.join(case, "log.segregationDegradationFoam")).read()
check("silo geometry threeD" in log, "geometry detected as threeD")
D0 = float(re.search(r"D0 = (\S+) m", log).group(1))
Q = float(re.search(r"Beverloo discharge rate Q = (\S+)", log).group(1))
check(abs(D0 / 0.04 - 1) < 0.03, "orifice D0 = %.5g m from the mesh (%.2e from 0.04)" % (D0, D0 / 0.04 - 1))
Qhand = hopperRate(D0, 1.2e-3, 30)
check(abs(Q / Qhand - 1) < 1e-9, "Q = %.9g m3/s vs %.9g by hand" % (Q, Qhand))
rows = [[float(v) for v in l.split()] for l in
        open(os.path.join(case, "postProcessing/outletComposition/0/outlet.dat"))
        if not l.startswith("#")]
worst = max(abs(r[2] / (2500 * 0.6 * Q) - 1) for r in rows)
check(worst < 1e-6, "outlet mass flow = 1500 Q at all %d steps (worst %.2e)" % (len(rows), worst))

# Mass balance
total = [float(m.group(1)) for m in re.finditer(r"Solids: total volume (\S+)", log)]
top = [[float(v) for v in l.split()] for l in
       open(os.path.join(case, "postProcessing/outletComposition/0/top.dat"))
       if not l.startswith("#")]
out = (sum(rows[-1][-2:]) + sum(top[-1][-2:])) / 2500
initial = total[0] + (sum(rows[0][-2:]) + sum(top[0][-2:])) / 2500
lost = initial - total[-1]
check(abs(lost - out) / lost < 1e-6,
      "solids lost %.9g m3, out %.9g m3 (relative %.2e)" % (lost, out, abs(lost - out) / lost))

# Pictures
for png in ("midPlane_solidsFraction.png", "midPlane_nCoarse.png"):
    path = os.path.join(case, "results", png)
    if not os.path.isfile(path):
        check(False, path + " written")
        continue
    data = open(path, "rb").read()
    w, h = struct.unpack(">II", data[16:24])
    idat = b"".join(data[i + 8:i + 8 + struct.unpack(">I", data[i:i + 4])[0]]
                    for i in [m.start() - 4 for m in re.finditer(b"IDAT", data)])
    distinct = len(set(zlib.decompress(idat)))
    check(w > 600 and h == 760 and distinct > 50,
          "%s: %d x %d pixels, %d distinct byte values" % (png, w, h, distinct))

sys.exit(1 if failed else 0)
