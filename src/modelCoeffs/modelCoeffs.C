/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "modelCoeffs.H"
#include "ITstream.H"

#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The check of checkKeys and checked; alsoValid decides the keys
// that are allowed beyond validKeys
template<class AlsoValid>
void checkKeysImpl
(
    const Foam::dictionary& dict,
    const Foam::wordList& validKeys,
    const AlsoValid& alsoValid
)
{
    using namespace Foam;

    for (const entry& e : dict)
    {
        const word& key = e.keyword();
        if (!validKeys.found(key) && !alsoValid(key))
        {
            FatalIOErrorIn("Foam::modelCoeffs::checkKeys", dict)
                << "Unknown entry '" << key << "' in dictionary "
                << dict.name() << nl
                << "    Valid entries: " << validKeys << nl
                << exit(FatalIOError);
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

const Foam::dictionary& Foam::modelCoeffs::coeffsDict
(
    const dictionary& mechanismDict,
    const word& modelType
)
{
    return mechanismDict.optionalSubDict(modelType + "Coeffs");
}


void Foam::modelCoeffs::checkKeys
(
    const dictionary& dict,
    const wordList& validKeys
)
{
    checkKeysImpl(dict, validKeys, [](const word&) { return false; });
}


const Foam::dictionary& Foam::modelCoeffs::checked
(
    const dictionary& mechanismDict,
    const word& modelType,
    const wordList& validKeys
)
{
    const word coeffsName(modelType + "Coeffs");
    if (mechanismDict.isDict(coeffsName))
    {
        checkKeys(mechanismDict.subDict(coeffsName), validKeys);
        return mechanismDict;
    }

    // No <model>Coeffs: the coefficients sit in the mechanism dictionary,
    // beside the model selection and other models' blocks
    checkKeysImpl
    (
        mechanismDict,
        validKeys,
        [](const word& key)
        {
            return
                key == "model"
             || (key.size() > 6 && key.compare(key.size() - 6, 6, "Coeffs") == 0);
        }
    );
    return mechanismDict;
}


Foam::dimensionedScalar Foam::modelCoeffs::get
(
    const dictionary& dict,
    const word& key,
    const dimensionSet& dims
)
{
    // A missing entry: FatalIOError naming the key and the dictionary
    const ITstream& is = dict.lookup(key, keyType::LITERAL);

    bool hasDimensions = false;
    for (const token& tok : is)
    {
        if (tok.isPunctuation() && tok.pToken() == token::BEGIN_SQR)
        {
            hasDimensions = true;
        }
    }

    // Read without the dimension check of dimensioned<Type>, whose error
    // names neither the entry nor the dictionary
    const dimensionedScalar value(key, dict);
    if (hasDimensions && value.dimensions() != dims)
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' in dictionary " << dict.name()
            << " has dimensions " << value.dimensions() << "; expected "
            << dims << nl
            << "    Give '" << key << " " << dims << " <value>;' or a bare"
            << " number in those units" << nl << exit(FatalIOError);
    }
    return dimensionedScalar(key, dims, value.value());
}


Foam::dimensionedScalar Foam::modelCoeffs::getOrDefault
(
    const dictionary& dict,
    const word& key,
    const dimensionSet& dims,
    const scalar deflt
)
{
    if (!dict.found(key, keyType::LITERAL))
    {
        return dimensionedScalar(key, dims, deflt);
    }
    return get(dict, key, dims);
}


const char* Foam::modelCoeffs::libraryHint(const word& modelType)
{
    if (modelType == "calibrated")
    {
        return
            "\nThe calibrated models are in libcalibratedModels.so: add\n"
            "    libs (\"libcalibratedModels.so\");\n"
            "to system/controlDict\n";
    }
    return "";
}


void Foam::modelCoeffs::checkNonNegative
(
    const dictionary& dict,
    const word& key,
    const scalar value,
    const char* what
)
{
    if (!(value >= 0) || !std::isfinite(value))
    {
        FatalIOErrorInFunction(dict)
            << what << " coefficient '" << key << " " << value
            << "' in " << dict.name() << " must be finite and >= 0" << nl
            << exit(FatalIOError);
    }
}


// ************************************************************************* //
