/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "kineticSievingModel.H"

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
    coeffs_(dict.optionalSubDict(type + "Coeffs"))
{}


// ************************************************************************* //
