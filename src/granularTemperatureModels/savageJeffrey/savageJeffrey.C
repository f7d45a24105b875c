/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "savageJeffrey.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoeffs.H"

namespace Foam
{
namespace granularTemperatureModels
{
    defineTypeNameAndDebug(savageJeffrey, 0);
    addToRunTimeSelectionTable
    (
        granularTemperatureModel,
        savageJeffrey,
        dictionary
    );
}
}


Foam::granularTemperatureModels::savageJeffrey::savageJeffrey
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    granularTemperatureModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, {"R"}),
        mixture
    ),
    R_(coeffs_.get<scalar>("R"))
{
    if (!(R_ > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Savage-Jeffrey parameter 'R " << R_ << "' must be > 0" << nl
            << exit(FatalIOError);
    }
}


void Foam::granularTemperatureModels::savageJeffrey::correct
(
    const bulkFlowModel& bulkFlow
)
{
    gammaDot_ = bulkFlow.gammaDot();
    T_ = 3*sqr(mixture_.dMean()*gammaDot_/R_);
}


// ************************************************************************* //
