"""balance.py LOG OUTLETDIR GRANULARPROPERTIES: the solids balance of a pipeBend run of
segregationDegradationFoam: inflow (outletComposition inlet.dat) = outflow
(outlet.dat) + held up + dust (the last "Solids:" line of the log, 15
digits), to 1e-10 of the inflow (of the solids present when nothing flows
in); and per class, initial + in - out + breakage gain = held (the log's
per-class volume and gain, the cumulative flows per class), to 1e-10 of
the class's largest term. Also the volume the finer classes (all but the
coarsest) hold. Exit status 1 if a balance fails or nothing flowed in or
was present."""
import re
import sys

log, base, props = sys.argv[1], sys.argv[2], sys.argv[3]
rho = {m.group(1): float(m.group(2)) for m in re.finditer(
    r"(\w+)\s*\{\s*d\s+\S+;\s*rho\s+(\S+);", open(props).read())}
text = open(log).read()
initialLine = re.search(r"^Initial solids: total volume (\S+)(.*)$", text, re.M)
initial = float(initialLine.group(1))
initialPer = {k: float(v) for k, v in re.findall(r"n\.(\S+) volume (\S+)", initialLine.group(2))}
last = re.findall(r"^Solids: total volume (\S+)\s+dust volume (\S+)(.*)$", text, re.M)[-1]
held, dust = float(last[0]), float(last[1])
volumes = {k: float(v) for k, v in re.findall(r"n\.(\S+) volume (\S+)", last[2])}
gains = {k: float(v) for k, v in re.findall(r"n\.(\S+) volume \S+ min/max \S+ breakage gain (\S+)", last[2])}


def cumulative(patch):
    """Per class, the volume that crossed the patch (positive leaving)."""
    lines = open(base + patch + ".dat").read().splitlines()
    header = [l for l in lines if l.startswith("# time")][0][1:].split()
    row = dict(zip(header, map(float, [l for l in lines if not l.startswith("#")][-1].split())))
    return {k[len("cumulativeMass."):-len("[kg]")]: v / rho[k[len("cumulativeMass."):-len("[kg]")]]
            for k, v in row.items() if k.startswith("cumulativeMass.")}


into, out = cumulative("inlet"), cumulative("outlet")
inflow, outflow = -sum(into.values()), sum(out.values())
scale = max(inflow, initial, held)
if not scale > 0:
    print("nothing flowed in and nothing was present")
    sys.exit(1)
error = abs(initial + inflow - outflow - held - dust) / scale
# The finer classes: all but the coarsest of granularProperties
d = {m.group(1): float(m.group(2)) for m in re.finditer(
    r"(\w+)\s*\{\s*d\s+(\S+);", open(props).read())}
coarsest = max(d, key=d.get)
fines = sum(v for k, v in volumes.items() if k != coarsest)
print("in %.6e out %.6e held %.6e dust %.6e: balance %.2e of the inflow;"
      " finer classes held %.3e (%.3e of the held solids)"
      % (inflow, outflow, held, dust, error, fines, fines / held if held > 0 else 0.0))
worstClass = 0.0
# With breakage, every class must have its gain on the log's line: a check
# that found none would otherwise pass on the total alone
propsText = open(props).read()
breaking = re.search(r"\bbreakage\s*\{\s*model\s+(\w+)\s*;", propsText)
if breaking and breaking.group(1) != "none" and set(gains) != set(volumes):
    print("breakage %s, but the log's Solids line has a breakage gain for %s of the classes %s"
          % (breaking.group(1), sorted(gains), sorted(volumes)))
    sys.exit(1)
if gains:
    for c in volumes:
        terms = (initialPer.get(c, 0.0), -into[c], out[c], gains[c], volumes[c])
        classScale = max(abs(t) for t in terms)
        if classScale > 0:
            e = abs(terms[0] + terms[1] - terms[2] + terms[3] - terms[4]) / classScale
            worstClass = max(worstClass, e)
            print("  %-8s initial %.6e in %.6e out %.6e breakage gain %+.6e held %.6e: balance %.2e"
                  % ((c,) + terms[:1] + (terms[1], terms[2], terms[3], terms[4], e)))
sys.exit(0 if error < 1e-10 and worstClass < 1e-10 and dust >= 0 else 1)
