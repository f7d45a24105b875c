#!/usr/bin/env python3
"""Write the OpenFOAM v1912 reactingMultiphaseEulerFoam pure-breakage case.

Port of the OpenFOAM Foundation verification case
test/multiphase/reactingMultiphaseEulerFoam/populationBalanceModeling/breakup
(OpenFOAM-6/7) to the dictionary syntax of OpenFOAM v1912 (openfoam.com,
Debian's package): one 1 m^3 cell, no flow, no gravity, size classes with
particle volumes v_i = r^(i-(n-1)) m^3 (the largest is 1 m^3), all particles
initially in the largest class (dispersed volume fraction alpha0), breakup
'powerLaw' (S = v^power) with the 'uniformBinary' daughter distribution.

Default (no options) = the Foundation case: 29 classes, r = 1.5, power 2,
end time 10, deltaT 0.1, alpha0 = 0.05, the classes split over three
dispersed phases air1 (classes 0-19), air2 (20-24), air3 (25-28) as in the
Foundation case.  --split single puts all classes in one phase 'air'.

Usage: makeCase.py CASEDIR [--classes N] [--ratio R] [--power P]
                   [--end T] [--dt DT] [--write W] [--alpha0 A]
                   [--split foundation|single] [--cells C]
Python 3 standard library only.
"""
import argparse
import os
import sys

HEADER = """\
/*--------------------------------*- C++ -*----------------------------------*\\
| =========                 |                                                 |
| \\\\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox           |
|  \\\\    /   O peration     | Version:  v1912                                 |
|   \\\\  /    A nd           | Website:  www.openfoam.com                      |
|    \\\\/     M anipulation  |                                                 |
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    location    "%s";
    object      %s;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

"""
FOOTER = "\n// ************************************************************************* //\n"


def write(case, rel, cls, body):
    path = os.path.join(case, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    loc, obj = os.path.split(rel)
    with open(path, "w") as f:
        f.write(HEADER % (cls, loc, obj))
        f.write(body)
        f.write(FOOTER)


def vol_field(value, dims="[0 0 0 0 0 0 0]", bc="zeroGradient"):
    # One closed cell whose six faces form one wall patch 'walls'.  (The
    # Foundation case has no patches: blockMesh then puts the six faces in
    # an 'empty' defaultFaces patch, and v1912's solver stops with a
    # floating point exception (0/0) in fvc::average called by
    # MomentumTransferPhaseSystem::ddtCorrByAs, since no face has area.)
    extra = ""
    if bc in ("calculated", "fixedFluxPressure"):
        extra = "\n        value           $internalField;"
    return ("dimensions      %s;\n\ninternalField   uniform %s;\n\n"
            "boundaryField\n{\n    walls\n    {\n        type            %s;%s\n"
            "    }\n}\n" % (dims, value, bc, extra))


def phase_split(n, split):
    """List of (phase name, [class indices]); the first listed class of
    every phase that starts empty carries the f = 1 needed by v1912's
    velocityGroup check (the f of a phase sum to 1 even where alpha = 0)."""
    if split == "single":
        return [("air", list(range(n)))]
    if n != 29:
        sys.exit("--split foundation needs --classes 29")
    return [("air1", list(range(0, 20))),
            ("air2", list(range(20, 25))),
            ("air3", list(range(25, 29)))]


THERMO_AIR = """\
thermoType
{
    type            heRhoThermo;
    mixture         pureMixture;
    transport       const;
    thermo          hConst;
    equationOfState perfectGas;
    specie          specie;
    energy          sensibleInternalEnergy;
}

mixture
{
    specie
    {
        molWeight   28.9;
    }
    thermodynamics
    {
        Cp          1007;
        Hf          0;
    }
    transport
    {
        mu          1.84e-05;
        Pr          0.7;
    }
}
"""

THERMO_WATER = """\
thermoType
{
    type            heRhoThermo;
    mixture         pureMixture;
    transport       const;
    thermo          eConst;
    equationOfState rhoConst;
    specie          specie;
    energy          sensibleInternalEnergy;
}

mixture
{
    specie
    {
        molWeight   18;
    }
    equationOfState
    {
        rho         998.2;
    }
    thermodynamics
    {
        Cv          4195;
        Hf          0;
    }
    transport
    {
        mu          3.645e-4;
        Pr          2.289;
    }
}
"""


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("--classes", type=int, default=29)
    ap.add_argument("--ratio", type=float, default=1.5)
    ap.add_argument("--power", type=float, default=2.0)
    ap.add_argument("--end", type=float, default=10.0)
    ap.add_argument("--dt", type=float, default=0.1)
    ap.add_argument("--write", type=float, default=1.0,
                    help="write interval (s)")
    ap.add_argument("--alpha0", type=float, default=0.05)
    ap.add_argument("--split", choices=["foundation", "single"],
                    default="foundation")
    ap.add_argument("--cells", type=int, default=1,
                    help="cells per direction of the 1 m^3 box (default 1; "
                         "more only to time the cost per cell)")
    a = ap.parse_args()

    n = a.classes
    if n < 3:
        sys.exit("v1912's populationBalanceModel needs at least 3 sizeGroups")
    case = a.case
    os.makedirs(case, exist_ok=True)
    phases = phase_split(n, a.split)
    last = phases[-1][0]

    # ---------------------------------------------------------------- 0/
    for ph, idx in phases:
        alpha = a.alpha0 if ph == last else 0.0
        write(case, "0/alpha.%s" % ph, "volScalarField", vol_field(repr(alpha)))
        write(case, "0/U.%s" % ph, "volVectorField",
              vol_field("(0 0 0)", "[0 1 -1 0 0 0 0]", "noSlip"))
        write(case, "0/T.%s" % ph, "volScalarField",
              vol_field("300", "[0 0 0 1 0 0 0]"))
        # velocityGroup reads f.<phase>.<populationBalance> (MUST_READ);
        # its boundary types are copied to the size-group fields.
        write(case, "0/f.%s.bubbles" % ph, "volScalarField", vol_field("1.0"))
    write(case, "0/alpha.water", "volScalarField",
          vol_field(repr(1.0 - a.alpha0)))
    write(case, "0/U.water", "volVectorField",
          vol_field("(0 0 0)", "[0 1 -1 0 0 0 0]", "noSlip"))
    write(case, "0/T.water", "volScalarField",
          vol_field("300", "[0 0 0 1 0 0 0]"))
    write(case, "0/p", "volScalarField", vol_field("1e5", "[1 -1 -2 0 0 0 0]", "calculated"))
    write(case, "0/p_rgh", "volScalarField",
          vol_field("1e5", "[1 -1 -2 0 0 0 0]", "fixedFluxPressure"))

    # ---------------------------------------------------------- constant/
    write(case, "constant/g", "uniformDimensionedVectorField",
          "dimensions      [0 1 -2 0 0 0 0];\nvalue           (0 0 0);\n")
    for ph, _ in phases:
        write(case, "constant/thermophysicalProperties.%s" % ph, "dictionary",
              THERMO_AIR)
        write(case, "constant/turbulenceProperties.%s" % ph, "dictionary",
              "simulationType  laminar;\n")
    write(case, "constant/thermophysicalProperties.water", "dictionary",
          THERMO_WATER)
    write(case, "constant/turbulenceProperties.water", "dictionary",
          "simulationType  laminar;\n")

    pp = ["type populationBalanceMultiphaseSystem;\n",
          "phases (%s water);\n" % " ".join(p for p, _ in phases),
          "populationBalances (bubbles);\n"]
    for pi, (ph, idx) in enumerate(phases):
        # f = 1 in the largest class of the phase that holds the particles,
        # in the first class of the other (empty) phases (as the Foundation
        # case; only the sum matters there, alpha = 0).
        if ph == last or pi == 0:
            one = idx[-1]
        else:
            one = idx[0]
        groups = []
        for i in idx:
            # formFactor 1: x = d^3 is the particle volume, v_i = r^(i-(n-1))
            d = a.ratio ** ((i - (n - 1)) / 3.0)
            if i == n - 1:
                d = 1.0
            groups.append("            f%-3d{d %.17g; value %s;}"
                          % (i, d, "1.0" if i == one else "0.0"))
        pp.append("""%s
{
    type            pureIsothermalPhaseModel;
    diameterModel   velocityGroup;
    velocityGroupCoeffs
    {
        populationBalance    bubbles;

        formFactor      1;

        sizeGroups
        (
%s
        );
    }

    residualAlpha   1e-6;
}
""" % (ph, "\n".join(groups)))
    pp.append("""water
{
    type            pureIsothermalPhaseModel;
    diameterModel   constant;
    constantCoeffs
    {
        d               1e-4;
    }

    residualAlpha   1e-6;
}

populationBalanceCoeffs
{
    bubbles
    {
        continuousPhase water;

        coalescenceModels
        ();

        binaryBreakupModels
        ();

        breakupModels
        (
            powerLaw
            {
                power   %r;
                daughterSizeDistributionModel uniformBinary;
            }
        );

        driftModels
        ();

        nucleationModels
        ();
    }
}

blending
{
    default
    {
        type            none;
        continuousPhase water;
    }
}

surfaceTension
();

interfaceCompression
();

aspectRatio
();

drag
();

virtualMass
();

heatTransfer
();

phaseTransfer
();

lift
();

wallLubrication
();

turbulentDispersion
();

// Minimum allowable pressure
pMin            10000;
""" % a.power)
    write(case, "constant/phaseProperties", "dictionary", "\n".join(pp))

    # ------------------------------------------------------------ system/
    write(case, "system/blockMeshDict", "dictionary", """\
convertToMeters 1;

vertices
(
    (0 0 0)
    (1 0 0)
    (1 1 0)
    (0 1 0)
    (0 0 1)
    (1 0 1)
    (1 1 1)
    (0 1 1)
);

blocks
(
    hex (0 1 2 3 4 5 6 7) (%d %d %d) simpleGrading (1 1 1)
);

edges
(
);

boundary
(
    walls
    {
        type wall;
        faces
        (
            (0 3 2 1)
            (4 5 6 7)
            (0 4 7 3)
            (1 2 6 5)
            (0 1 5 4)
            (3 7 6 2)
        );
    }
);

mergePatchPairs
(
);
""" % (a.cells, a.cells, a.cells))
    write(case, "system/controlDict", "dictionary", """\
application     reactingMultiphaseEulerFoam;

startFrom       startTime;

startTime       0;

stopAt          endTime;

endTime         %r;

deltaT          %r;

writeControl    runTime;

writeInterval   %r;

purgeWrite      0;

writeFormat     ascii;

writePrecision  12;

writeCompression off;

timeFormat      general;

timePrecision   6;

runTimeModifiable no;

adjustTimeStep  no;

maxCo           0.5;

maxDeltaT       1;

functions
{
    numberDensity
    {
        type                sizeDistribution;
        libs                ("libreactingEulerFoamFunctionObjects.so");
        writeControl        writeTime;
        log                 yes;
        functionType        numberDensity;
        abszissaType        volume;
        selectionMode       all;
        populationBalance   bubbles;
    }
}
""" % (a.end, a.dt, a.write))
    write(case, "system/fvSchemes", "dictionary", """\
ddtSchemes
{
    default         Euler;
}

gradSchemes
{
    default         Gauss linear;
}

divSchemes
{
    default                         none;

    "div\\(phi,alpha.*\\)"            Gauss vanLeer;
    "div\\(phir,alpha.*,alpha.*\\)"   Gauss vanLeer;
    "div\\(phir,alpha.*\\)"           Gauss vanLeer;

    "div\\(alphaRhoPhi.*,U.*\\)"      Gauss limitedLinearV 1;
    "div\\(phi.*,U.*\\)"              Gauss limitedLinearV 1;

    "div\\(alphaRhoPhi.*,(h|e|k|epsilon|omega|f).*\\)"  Gauss limitedLinear 1;
    "div\\(alphaPhi.*,p\\)"           Gauss limitedLinear 1;
    "div\\(phi.*,K.*\\)"              Gauss limitedLinear 1;

    "div\\(\\(\\(\\(alpha.*\\*thermo:rho.*\\)\\*nuEff.*\\)\\*dev2\\(T\\(grad\\(U.*\\)\\)\\)\\)\\)" Gauss linear;
}

laplacianSchemes
{
    default         Gauss linear uncorrected;
}

interpolationSchemes
{
    default         linear;
}

snGradSchemes
{
    default         uncorrected;
}
""")
    write(case, "system/fvSolution", "dictionary", """\
solvers
{
    "alpha.*"
    {
        nAlphaCorr      1;
        nAlphaSubCycles 1;
    }

    bubbles
    {
        nCorr           1;
        tolerance       1e-4;
        renormalize     false;
    }

    p_rgh
    {
        solver          PCG;
        preconditioner  none;
        tolerance       1e-8;
        relTol          0;
    }

    p_rghFinal
    {
        $p_rgh;
        relTol          0;
    }

    "U.*"
    {
        solver          PBiCG;
        preconditioner  DILU;
        tolerance       1e-8;
        relTol          0;
    }

    "(e|h).*"
    {
        solver          PBiCG;
        preconditioner  DILU;
        tolerance       1e-8;
        relTol          0;
    }

    "f.*"
    {
        solver          PBiCG;
        preconditioner  DILU;
        tolerance       1e-12;
        relTol          0;
    }
}

PIMPLE
{
    nOuterCorrectors 2;
    nCorrectors      1;
    nNonOrthogonalCorrectors 0;
    pRefCell         0;
    pRefValue        1e5;
}

relaxationFactors
{
    equations
    {
        ".*"            1;
    }
}
""")
    print("wrote %s: %d classes (ratio %g, power %g), phases %s, end %g, dt %g"
          % (case, n, a.ratio, a.power, [p for p, _ in phases], a.end, a.dt))


if __name__ == "__main__":
    main()
