/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "uniformBinary.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoeffs.H"

namespace Foam
{
namespace daughterSizeDistributionModels
{
    defineTypeNameAndDebug(uniformBinary, 0);
    addToRunTimeSelectionTable
    (
        daughterSizeDistributionModel,
        uniformBinary,
        dictionary
    );
}
}


Foam::daughterSizeDistributionModels::uniformBinary::uniformBinary
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    daughterSizeDistributionModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, wordList()),
        mixture
    )
{}


// ************************************************************************* //
