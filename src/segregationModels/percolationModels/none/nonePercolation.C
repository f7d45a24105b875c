/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "nonePercolation.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace percolationModels
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(percolationModel, none, dictionary);
}
}


// ************************************************************************* //
