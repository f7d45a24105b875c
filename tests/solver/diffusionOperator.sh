# shellcheck shell=bash
# The species' diffusion operator against OpenFOAM's own (sourced by
# tests/run; tests solver/diffusionOperator/*).

# On a non-orthogonal mesh (validation/gaussianDiffusion's case on a 2-D
# parallelogram of 24 x 24 cells sheared by 26.6 degrees, walls all round),
# a Gaussian pulse of a tracer in a bulk of 0.6 diffuses with constant D
# (Euler, 25 steps, laplacian(D,n) Gauss linear corrected, Gauss linear
# gradients). The species' Laplacian (speciesAdvection: implicit part
# uncorrected, the explicit non-orthogonal correction from each species'
# gradient) must be OpenFOAM's corrected one: n.tracer equals
# scalarTransportFoam's T on the same mesh, schemes and steps to 1e-10
# (solvers at 1e-13), and the species' sum stays 0.6 to 1e-12 (the
# corrections of the species add up to the total's, which is uniform)
test_species_laplacian_matches_openfoam()
{
    local dir="$workRoot/laplacianSkewed" sdf stf
    sdf="$dir/species"; stf="$dir/scalarTransport"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/gaussianDiffusion" "$sdf"
    (cd "$sdf" && ./Allclean > /dev/null)
    python3 - "$sdf/system/blockMeshDict" <<'PY' || return 1
import re, sys
path = sys.argv[1]
text = open(path).read()
head = text[:text.index("scale")]
body = """scale   1;
vertices
(
    (0 0 0) (1 0 0) (1.5 1 0) (0.5 1 0)
    (0 0 0.1) (1 0 0.1) (1.5 1 0.1) (0.5 1 0.1)
);
blocks ( hex (0 1 2 3 4 5 6 7) (24 24 1) simpleGrading (1 1 1) );
edges ();
boundary
(
    left  { type wall; faces ((0 4 7 3) (0 1 5 4)); }
    right { type wall; faces ((1 2 6 5) (3 7 6 2)); }
    sides { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
mergePatchPairs ();
"""
open(path, "w").write(head + body)
PY
    cat > "$sdf/system/caseParameters" <<'EOF'
deltaT 0.002;
endTime 0.05;
writeInterval 0.05;
EOF
    echo "ddtSchemes { default Euler; }" > "$sdf/system/fvSchemesParameters"
    blockMesh -case "$sdf" > "$sdf/log.blockMesh" 2>&1 || { cat "$sdf/log.blockMesh"; return 1; }
    checkMesh -case "$sdf" > "$sdf/log.checkMesh" 2>&1 || { cat "$sdf/log.checkMesh"; return 1; }
    # The initial pulse: n.tracer = 0.01 + 0.29 exp(-r^2/(2 0.1^2)) around
    # (0.75, 0.5), n.bulk = 0.6 - n.tracer; T = n.tracer (the background
    # keeps every species above 1e-6 of the solids, below which
    # speciesAdvection scales the correction down)
    mkdir -p "$stf/0" "$stf/constant" "$stf/system"
    cp -r "$sdf/constant/polyMesh" "$stf/constant/"
    python3 - "$sdf" "$stf" <<'PY' || return 1
import math, os, re, sys
from sdfoam import foamcase
sdf, stf = sys.argv[1:3]
C = foamcase.cellCentres(sdf)
tracer = [0.01 + 0.29 * math.exp(-((c[0] - 0.75)**2 + (c[1] - 0.5)**2) / (2 * 0.1**2)) for c in C]
def field(values):
    return "internalField   nonuniform List<scalar>\n%d\n(\n%s\n)\n;" % (len(values), "\n".join("%.17g" % v for v in values))
os.makedirs(sdf + "/0", exist_ok=True)
for name, vals in (("n.tracer", tracer), ("n.bulk", [0.6 - v for v in tracer])):
    text = open(sdf + "/0.orig/" + name).read()
    open(sdf + "/0/" + name, "w").write(re.sub(r"internalField\s+uniform\s+[^;]*;", field(vals), text))
T = open(sdf + "/0.orig/n.tracer").read().replace("object      n.tracer;", "object      T;")
open(stf + "/0/T", "w").write(re.sub(r"internalField\s+uniform\s+[^;]*;", field(tracer), T))
PY
    cp "$sdf/0.orig/U" "$sdf/0/"
    cp "$sdf/0.orig/U" "$stf/0/"
    local header='FoamFile { version 2.0; format ascii; class dictionary; object'
    echo "$header transportProperties; } DT 0.01;" > "$stf/constant/transportProperties"
    cat > "$stf/system/controlDict" <<EOF
$header controlDict; }
application scalarTransportFoam;
startFrom startTime; startTime 0; stopAt endTime; endTime 0.05; deltaT 0.002;
writeControl runTime; writeInterval 0.05; writeFormat ascii; writePrecision 17;
timeFormat general; timePrecision 8; runTimeModifiable false;
EOF
    cat > "$stf/system/fvSchemes" <<EOF
$header fvSchemes; }
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default none; div(phi,T) Gauss linear; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
EOF
    cat > "$stf/system/fvSolution" <<EOF
$header fvSolution; }
solvers { T { solver PBiCGStab; preconditioner DILU; tolerance 1e-13; relTol 0; } }
SIMPLE { nNonOrthogonalCorrectors 0; }
EOF
    foamDictionary -case "$sdf" -entry writePrecision -set 17 "$sdf/system/controlDict" > /dev/null || return 1
    segregationDegradationFoam -case "$sdf" > "$sdf/log.solver" 2>&1 || { tail -30 "$sdf/log.solver"; return 1; }
    scalarTransportFoam -case "$stf" > "$stf/log.solver" 2>&1 || { tail -30 "$stf/log.solver"; return 1; }
    python3 - "$sdf" "$stf" <<'PY'
import re, sys
from sdfoam import foamcase
sdf, stf = sys.argv[1:3]
nonOrth = float(re.search(r"non-orthogonality Max: (\S+)", open(sdf + "/log.checkMesh").read()).group(1))
t = "0.05"
tracer = foamcase.readScalarField(sdf, t, "n.tracer")
bulk = foamcase.readScalarField(sdf, t, "n.bulk")
T = foamcase.readScalarField(stf, t, "T")
T0 = foamcase.readScalarField(stf, "0", "T")
diff = max(abs(a - b) for a, b in zip(tracer, T))
spread = max(abs(a - b) for a, b in zip(T, T0))
total = max(abs(a + b - 0.6) for a, b in zip(tracer, bulk))
print("non-orthogonality max %.1f deg; after 25 steps the pulse changed by up to %.3e; "
      "|n.tracer - T (scalarTransportFoam)| max %.2e; |n.tracer + n.bulk - 0.6| max %.2e"
      % (nonOrth, spread, diff, total))
sys.exit(0 if nonOrth > 20 and spread > 1e-2 and diff < 1e-10 and total < 1e-12 else 1)
PY
}

# The operator the species share (speciesAdvection::correctOperator,
# sharedOperator): on silo2D's hopper mesh (non-orthogonal up to 29 deg, so
# each species carries its own explicit correction; harmonic face
# diffusivity), with a fixed inflow value that differs between the species
# (different boundary coefficients), the debug switch makes the solver
# assemble every species' matrix also on its own, ddt + fvmDiv -
# fvmLaplacian, and compare diagonal, off-diagonals, boundary coefficients
# (each patch against its own largest) and source: fatal above 1e-12.
# Three runs: Euler and vanLeer01 (shared limited weights) on 2 ranks
# (processor patches); Crank-Nicolson (ddt assembled per species) with
# upwind (unlimited weights), serial; linearUpwind (explicit correction:
# no shared operator, so no check line, and the run goes on). Measured:
# boundary coefficients and sources identical; diagonal within 1.6e-16 (its
# sums in another order)
shared_operator_case()
{
    local dir="$1"
    silo2D_case "$dir" 0.02 0.02 || return 1
    foamDictionary -entry boundaryField.top -set '{ type fixedValue; value uniform 0.1; }' "$dir/0/n.fine" > /dev/null || return 1
    foamDictionary -entry boundaryField.top -set '{ type fixedValue; value uniform 0.35; }' "$dir/0/n.coarse" > /dev/null || return 1
    foamDictionary -entry DebugSwitches -set '{ speciesAdvection 1; }' "$dir/system/controlDict" > /dev/null || return 1
    checkMesh -case "$dir" > "$dir/log.checkMesh" 2>&1 || { tail -20 "$dir/log.checkMesh"; return 1; }
}

# shared_operator_check DIR CHECKS_PER_STEP: the checks' count and largest
# difference in DIR/log.solver
shared_operator_check()
{
    python3 - "$1" "$2" <<'PY'
import re, sys
case, perStep = sys.argv[1], int(sys.argv[2])
nonOrth = float(re.search(r"non-orthogonality Max: (\S+)", open(case + "/log.checkMesh").read()).group(1))
log = open(case + "/log.solver").read()
steps = len(re.findall(r"^Time = ", log, re.M))
checks = re.findall(r"shared operator of (\S+) against its own assembly: "
                    r"relative difference (\S+) \(matrix (\S+), boundary (\S+)\), source (\S+)", log)
worst = max((max(float(v) for v in c[1:]) for c in checks), default=0.0)
print("%s: non-orthogonality max %.1f deg; %d steps; %d species matrices checked; "
      "largest relative difference %.3g" % (case.split("/")[-1], nonOrth, steps, len(checks), worst))
ok = nonOrth > 20 and steps >= 5 and len(checks) == perStep * steps and worst <= 1e-12
sys.exit(0 if ok else 1)
PY
}

test_shared_operator_equals_own_assembly()
{
    local dir="$workRoot/sharedOperator"
    shared_operator_case "$dir" || return 1
    decomposePar -case "$dir" > "$dir/log.decomposePar" 2>&1 || { tail -20 "$dir/log.decomposePar"; return 1; }
    mpirun -np 2 segregationDegradationFoam -parallel -case "$dir" > "$dir/log.solver" 2>&1 || { tail -30 "$dir/log.solver"; return 1; }
    shared_operator_check "$dir" 2 || return 1

    dir="$workRoot/sharedOperatorCrankNicolson"
    shared_operator_case "$dir" || return 1
    foamDictionary -entry ddtSchemes/default -set "CrankNicolson 0.9" "$dir/system/fvSchemes" > /dev/null || return 1
    foamDictionary -entry "divSchemes/div(phi,n)" -set "Gauss upwind" "$dir/system/fvSchemes" > /dev/null || return 1
    segregationDegradationFoam -case "$dir" > "$dir/log.solver" 2>&1 || { tail -30 "$dir/log.solver"; return 1; }
    shared_operator_check "$dir" 2 || return 1

    dir="$workRoot/sharedOperatorLinearUpwind"
    shared_operator_case "$dir" || return 1
    foamDictionary -entry "divSchemes/div(phi,n)" -set "Gauss linearUpwind grad(n)" "$dir/system/fvSchemes" > /dev/null || return 1
    segregationDegradationFoam -case "$dir" > "$dir/log.solver" 2>&1 || { tail -30 "$dir/log.solver"; return 1; }
    shared_operator_check "$dir" 0
}
