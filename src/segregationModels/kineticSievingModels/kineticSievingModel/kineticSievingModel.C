/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "kineticSievingModel.H"
#include "modelCoeffs.H"
#include "fvcSnGrad.H"

namespace Foam
{
    defineTypeNameAndDebug(kineticSievingModel, 0);
    defineRunTimeSelectionTable(kineticSievingModel, dictionary);
}


Foam::kineticSievingModel::kineticSievingModel
(
    const word& type,
    const dictionary& dict,
    const granularMixture& mixture
)
:
    mixture_(mixture),
    coeffs_(modelCoeffs::coeffsDict(dict, type))
{}


Foam::tmp<Foam::surfaceScalarField> Foam::kineticSievingModel::gradLnUSf
(
    const bulkFlowModel& bulkFlow,
    const scalar Umin
)
{
    const fvMesh& mesh = bulkFlow.U().mesh();
    const volScalarField lnU
    (
        log
        (
            max(mag(bulkFlow.U()), dimensionedScalar("Umin", dimVelocity, Umin))
           /dimensionedScalar("one", dimVelocity, 1)
        )
    );
    tmp<surfaceScalarField> tgrad(fvc::snGrad(lnU)*mesh.magSf());
    zeroUncoupledPatches(tgrad.ref());
    return tgrad;
}


// ************************************************************************* //
