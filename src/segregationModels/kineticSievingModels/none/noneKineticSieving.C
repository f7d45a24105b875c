/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "noneKineticSieving.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace kineticSievingModels
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(kineticSievingModel, none, dictionary);
}
}


// ************************************************************************* //
