/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    segregationDegradationFoam

Group
    grpMultiphaseSolvers

Description
    Transient solver for the segregation and degradation of a granular
    mixture carried by a bulk flow. For every species i
    (docs/developer/equations.md, seed eq 4):

        ddt(n_i) + div(phi n_i) + div(J_D,i + J_S,i + J_P,i) = B_i

    phi and U from the bulkFlow model, J_D = -D grad n_i with the mixture
    diffusivity (implicit), J_S (kinetic sieving) and J_P (percolation) as
    explicit, bounded pairwise exchange fluxes, B_i the breakage source
    (breakageSource; the species are solved coarse to fine).
    Every mechanism is a run-time selected model in
    constant/granularProperties; `none` assembles nothing. The outlet
    composition is the outletComposition function object of
    system/controlDict (also with -postProcess).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "granularMixture.H"
#include "bulkFlowModel.H"
#include "granularTemperatureModel.H"
#include "diffusivityModel.H"
#include "kineticSievingModel.H"
#include "percolationModel.H"
#include "breakageSource.H"
#include "segregationFlux.H"
#include "speciesAdvection.H"
#include "wallFvPatch.H"
#include "polyMeshTools.H"
#include "unitConversion.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Transient solver for segregation and degradation of granular"
        " mixtures (one n.<species> field per species)."
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "createControls.H"
    #include "createFields.H"
    #include "meshQualityWarning.H"

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readControls.H"

        // Drift fluxes of the segregation mechanisms for the current state
        // (after the previous step's solve): the segregation Courant number,
        // and so the time step, depend on them
        segregation.correctDrift();

        #include "courantNumbers.H"
        #include "setDeltaT.H"

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        #include "updateTransport.H"
        #include "nEqns.H"

        #include "writeDerivedFields.H"

        runTime.write();

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
