#!/usr/bin/env bash
#------------------------------------------------------------------------------
# benchmarks/demTransport/run.sh
#
# Elastic frictionless monodisperse gas (validation.md items 11 and 12): Green-Kubo
# self-diffusion (multiple-tau VACF, block errors) and the Einstein MSD slope against
# Chapman-Enskog D_E = sigma sqrt(pi T1) / (16 phi g0), and the collision frequency
# against omega_E = 4 n sigma^2 g0 sqrt(pi T1), for a list of solids fractions.
# The spring is stiffened with density so that t_c omega_E stays 1 % (hard-sphere
# limit); runs last `collisions` mean free times.
#
#   benchmarks/demTransport/run.sh [N] [collisions] [phi ...]
#------------------------------------------------------------------------------
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
out="$root/build/benchmarks/demTransport"
cli="$root/build/calibration/apps/periodicDEM-cli"
mkdir -p "$out"
N=${1:-300}
collisions=${2:-200}
shift 2 || true
phis=("$@")
[ ${#phis[@]} -gt 0 ] || phis=(0.05 0.1 0.2 0.3 0.4 0.5)

sigma=0.001; rho=2500; T=0.03
report="$out/report.txt"
printf "%-6s %-12s %-10s %-12s %-10s %-12s %-8s %-8s %-8s\n" phi D_GK err D_MSD err D_E GK/E MSD/E coll/E > "$report"
for phi in "${phis[@]}"
do
    read -r kn dt tsample tequil every <<<"$(awk -v phi=$phi -v s=$sigma -v rho=$rho -v T=$T 'BEGIN{
        pi = 3.141592653589793; T1 = T/3
        g0 = (1 - phi/2)/(1 - phi)^3; n = 6*phi/(pi*s^3)
        omega = 4*n*s*s*g0*sqrt(pi*T1)
        m = rho*pi*s^3/6; meff = m/2
        tc = 0.01/omega; kn = meff*(pi/tc)^2
        dt = 0.95*tc/50
        printf "%.6g %.6g %.6g %.6g %d", kn, dt, '"$collisions"'/omega, 5/omega, int(tc/dt*50/200 + 1)*4 }')"
    log="$out/phi$phi.log"
    "$root/build/calibration/apps/periodicDEM-cli" /dev/null \
        "species = glass:$sigma:$rho" particles=$N solidsFraction=$phi mode=nve \
        temperature=$T restitution=1 friction=0 normalStiffness=$kn timeStep=$dt \
        equilibrationTime=$tequil samplingTime=$tsample sampleEvery=$every blocks=8 \
        threads=1 seed=3 output="$out/phi$phi.h5" > "$log"
    python3 - "$log" "$phi" "$sigma" "$N" >> "$report" <<'PY'
import re, sys, math
text = open(sys.argv[1]).read(); phi = float(sys.argv[2]); s = float(sys.argv[3]); N = int(sys.argv[4])
T = float(re.search(r"  T = ([0-9.eE+-]+)", text).group(1)); T1 = T/3
m = re.search(r"D_GK = ([0-9.eE+-]+) \+- ([0-9.eE+-]+) m2/s.*D_MSD = ([0-9.eE+-]+) \+- ([0-9.eE+-]+)", text)
gk, gke, msd, msde = map(float, m.groups())
coll = float(re.search(r"per glass particle ([0-9.eE+-]+)", text).group(1))
g0 = (1 - phi/2)/(1 - phi)**3
DE = s*math.sqrt(math.pi*T1)/(16*phi*g0)
n = 6*phi/(math.pi*s**3)
omegaE = 4*n*s*s*g0*math.sqrt(math.pi*T1)
print(f"{phi:<6} {gk:<12.5g} {gke:<10.2g} {msd:<12.5g} {msde:<10.2g} {DE:<12.5g} {gk/DE:<8.4f} {msd/DE:<8.4f} {coll/omegaE:<8.4f}")
PY
    tail -1 "$report"
done
cat "$report"
