/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "percolationModel.H"
#include "modelCoeffs.H"

Foam::autoPtr<Foam::percolationModel> Foam::percolationModel::New
(
    const dictionary& dict,
    const granularMixture& mixture,
    const bulkFlowModel& bulkFlow
)
{
    const word modelType(dict.get<word>("model"));

    Info<< "Selecting percolation model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "percolation model",
            modelType,
            *dictionaryConstructorTablePtr_
        )   << modelCoeffs::libraryHint(modelType)
            << exit(FatalIOError);
    }

    return autoPtr<percolationModel>(cstrIter()(dict, mixture, bulkFlow));
}


// ************************************************************************* //
