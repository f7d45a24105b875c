/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "percolationModel.H"
#include "modelCoeffs.H"

namespace Foam
{
    defineTypeNameAndDebug(percolationModel, 0);
    defineRunTimeSelectionTable(percolationModel, dictionary);
}


Foam::percolationModel::percolationModel
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
