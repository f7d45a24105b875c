/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "noneBreakage.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace breakageModels
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(breakageModel, none, dictionary);
}
}


// ************************************************************************* //
