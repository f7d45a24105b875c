/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "granularTemperatureModel.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::granularTemperatureModel>
Foam::granularTemperatureModel::New
(
    const dictionary& dict,
    const granularMixture& mixture
)
{
    const word modelType(dict.get<word>("model"));

    Info<< "Selecting granularTemperature model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "granularTemperature model",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<granularTemperatureModel>(cstrIter()(dict, mixture));
}


// ************************************************************************* //
