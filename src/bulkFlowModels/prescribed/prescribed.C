/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "prescribed.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoeffs.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bulkFlowModels
{
    defineTypeNameAndDebug(prescribed, 0);
    addToRunTimeSelectionTable(bulkFlowModel, prescribed, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bulkFlowModels::prescribed::prescribed
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    bulkFlowModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, {"scale"}),
        mixture,
        true
    ),
    U0_("U0", U_)
{
    // Optional, no default: without it U stays as read from 0/U
    if (coeffs_.found("scale"))
    {
        scale_ = Function1<scalar>::New("scale", coeffs_);
    }
    correct();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bulkFlowModels::prescribed::correct()
{
    if (scale_.valid())
    {
        const scalar s = scale_->value(mixture_.mesh().time().value());
        U_ == s*U0_;
    }
    updateFluxFromU();
}


// ************************************************************************* //
