/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "diffusivityModel.H"
#include "modelCoeffs.H"

Foam::autoPtr<Foam::diffusivityModel> Foam::diffusivityModel::New
(
    const dictionary& dict,
    const granularMixture& mixture
)
{
    const word modelType(dict.get<word>("model"));

    Info<< "Selecting diffusivity model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "diffusivity model",
            modelType,
            *dictionaryConstructorTablePtr_
        )   << modelCoeffs::libraryHint(modelType)
            << exit(FatalIOError);
    }

    return autoPtr<diffusivityModel>(cstrIter()(dict, mixture));
}


// ************************************************************************* //
