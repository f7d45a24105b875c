/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Description
    The project's cloud models, added to the selection tables of OpenFOAM's
    kinematic colliding cloud (the cloud of icoUncoupledKinematicParcelFoam
    and DPMFoam): load with `libs ("libsegregationDegradationLagrangian.so");`
    in system/controlDict. Only the *Type macros: the tables themselves live
    in liblagrangianIntermediate.

\*---------------------------------------------------------------------------*/

#include "basicKinematicCollidingCloud.H"
#include "CloudFunctionObject.H"
#include "PatchInteractionModel.H"
#include "ParticlePass.H"
#include "BreakingRebound.H"

makeCloudFunctionObjectType(ParticlePass, basicKinematicCollidingCloud);
makePatchInteractionModelType(BreakingRebound, basicKinematicCollidingCloud);

// ************************************************************************* //
