/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "kineticSievingModel.H"
#include "modelCoeffs.H"

Foam::autoPtr<Foam::kineticSievingModel> Foam::kineticSievingModel::New
(
    const dictionary& dict,
    const granularMixture& mixture,
    const bulkFlowModel& bulkFlow
)
{
    const word modelType(dict.get<word>("model"));

    Info<< "Selecting kineticSieving model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "kineticSieving model",
            modelType,
            *dictionaryConstructorTablePtr_
        )   << modelCoeffs::libraryHint(modelType)
            << exit(FatalIOError);
    }

    return autoPtr<kineticSievingModel>(cstrIter()(dict, mixture, bulkFlow));
}


// ************************************************************************* //
