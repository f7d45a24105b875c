"""balance.py LOG OUTLETDIR GRANULARPROPERTIES: the solids balance of a pipeBend run of
segregationDegradationFoam: inflow (outletComposition inlet.dat) = outflow
(outlet.dat) + held up + dust (the last "Solids:" line of the log, 12
digits), to 1e-10 of the inflow (of the solids present when nothing flows
in). Also the volume the finer classes hold. Exit
status 1 if the balance fails or nothing flowed in or was present."""
import re
import sys

log, base, props = sys.argv[1], sys.argv[2], sys.argv[3]
rho = {m.group(1): float(m.group(2)) for m in re.finditer(
    r"(\w+)\s*\{\s*d\s+\S+;\s*rho\s+(\S+);", open(props).read())}
text = open(log).read()
initial = float(re.search(r"Initial solids: total volume (\S+)", text).group(1))
last = re.findall(r"^Solids: total volume (\S+)\s+dust volume (\S+)(.*)$", text, re.M)[-1]
held, dust = float(last[0]), float(last[1])
volumes = dict(re.findall(r"n\.(\S+) volume (\S+)", last[2]))


def cumulative(patch):
    lines = open(base + patch + ".dat").read().splitlines()
    header = [l for l in lines if l.startswith("# time")][0][1:].split()
    row = dict(zip(header, map(float, [l for l in lines if not l.startswith("#")][-1].split())))
    return sum(v / rho[k[len("cumulativeMass."):-len("[kg]")]]
               for k, v in row.items() if k.startswith("cumulativeMass."))


inflow, outflow = -cumulative("inlet"), cumulative("outlet")
scale = max(inflow, initial, held)
if not scale > 0:
    print("nothing flowed in and nothing was present")
    sys.exit(1)
error = abs(initial + inflow - outflow - held - dust) / scale
# The finer classes: all but the coarsest of granularProperties
d = {m.group(1): float(m.group(2)) for m in re.finditer(
    r"(\w+)\s*\{\s*d\s+(\S+);", open(props).read())}
coarsest = max(d, key=d.get)
fines = sum(float(v) for k, v in volumes.items() if k != coarsest)
print("in %.6e out %.6e held %.6e dust %.6e: balance %.2e of the inflow;"
      " finer classes held %.3e (%.3e of the held solids)"
      % (inflow, outflow, held, dust, error, fines, fines / held if held > 0 else 0.0))
sys.exit(0 if error < 1e-10 and dust >= 0 else 1)
