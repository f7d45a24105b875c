/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "breakageModel.H"
#include "modelCoeffs.H"

namespace Foam
{
    defineTypeNameAndDebug(breakageModel, 0);
    defineRunTimeSelectionTable(breakageModel, dictionary);
}


Foam::breakageModel::breakageModel
(
    const word& type,
    const dictionary& dict,
    const granularMixture& mixture
)
:
    mixture_(mixture),
    coeffs_(modelCoeffs::coeffsDict(dict, type))
{}


// ************************************************************************* //
