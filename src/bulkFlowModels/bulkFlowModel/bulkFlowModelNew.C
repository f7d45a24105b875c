/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "bulkFlowModel.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::bulkFlowModel> Foam::bulkFlowModel::New
(
    const dictionary& dict,
    const granularMixture& mixture
)
{
    const word modelType(dict.get<word>("model"));

    Info<< "Selecting bulkFlow model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "bulkFlow model",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<bulkFlowModel>(cstrIter()(dict, mixture));
}


// ************************************************************************* //
