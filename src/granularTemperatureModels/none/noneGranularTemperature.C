/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "noneGranularTemperature.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace granularTemperatureModels
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(granularTemperatureModel, none, dictionary);
}
}


void Foam::granularTemperatureModels::none::correct
(
    const bulkFlowModel& bulkFlow
)
{
    if (mixture_.writeField("gammaDot"))
    {
        gammaDot_ = bulkFlow.gammaDot();
    }
}


// ************************************************************************* //
