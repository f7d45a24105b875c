/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "breakageModel.H"

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
    coeffs_(dict.optionalSubDict(type + "Coeffs"))
{}


Foam::autoPtr<Foam::breakageModel> Foam::breakageModel::New
(
    const dictionary& dict,
    const granularMixture& mixture
)
{
    const word modelType(dict.get<word>("model"));

    Info<< "Selecting breakage model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "breakage model",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<breakageModel>(cstrIter()(dict, mixture));
}


// ************************************************************************* //
