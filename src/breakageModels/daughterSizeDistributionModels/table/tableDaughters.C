/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "tableDaughters.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoeffs.H"
#include "OStringStream.H"

namespace Foam
{
namespace daughterSizeDistributionModels
{
    defineTypeNameAndDebug(table, 0);
    addToRunTimeSelectionTable(daughterSizeDistributionModel, table, dictionary);
}
}


Foam::daughterSizeDistributionModels::table::table
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    daughterSizeDistributionModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, mixture.names()),
        mixture
    )
{
    for (const entry& e : coeffs_)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(coeffs_)
                << "Entry '" << e.keyword() << "' in " << coeffs_.name()
                << " must be a dictionary of fragment volume fractions,"
                << " e.g. " << e.keyword() << " { fine 1; }" << nl
                << exit(FatalIOError);
        }
    }
}


Foam::breakageWeights Foam::daughterSizeDistributionModels::table::weights
(
    const label parent,
    const labelList& grid,
    const bool dustSink
) const
{
    breakageWeights w;
    w.volume.setSize(mixture_.size(), Zero);
    w.number.setSize(mixture_.size(), Zero);

    const word& parentName = mixture_.names()[parent];
    const scalar u = mixture_.particleVolume(parent);

    if (!coeffs_.isDict(parentName))
    {
        // Not listed: does not break
        w.volume[parent] = 1;
        w.number[parent] = 1;
        w.fragmentsPerEvent = 1;
        return w;
    }

    const dictionary& fractions = coeffs_.subDict(parentName);

    wordList valid;
    for (const label i : grid)
    {
        if (i != parent)
        {
            valid.append(mixture_.names()[i]);
        }
    }
    if (dustSink)
    {
        valid.append("dust");
    }

    scalar sum = 0;
    for (const entry& e : fractions)
    {
        const word& key = e.keyword();
        const label i = mixture_.names().find(key);
        if (!valid.found(key))
        {
            OStringStream why;
            if (key == "dust")
            {
                why << "dust needs 'fines dust;' in the breakage dictionary";
            }
            else if (i < 0)
            {
                why << "not a species";
            }
            else if (i == parent || mixture_.d(i) >= mixture_.d(parent))
            {
                why << "species " << key << " (d " << mixture_.d(i)
                    << ") is not finer than the parent " << parentName
                    << " (d " << mixture_.d(parent) << "): breakage moves"
                    << " material to finer classes only";
            }
            else
            {
                why << "species " << key << " is another material (rho "
                    << mixture_.rho(i) << ", parent " << mixture_.rho(parent)
                    << ")";
            }
            FatalIOErrorInFunction(fractions)
                << "Fragment entry '" << key << "' in " << fractions.name()
                << ": " << why.str().c_str() << nl << "    valid: " << valid
                << nl
                << exit(FatalIOError);
        }

        const scalar fraction = fractions.get<scalar>(key);
        if (!(fraction >= 0))
        {
            FatalIOErrorInFunction(fractions)
                << "Fragment volume fraction '" << key << " " << fraction
                << "' in " << fractions.name() << " must be >= 0" << nl
                << exit(FatalIOError);
        }
        sum += fraction;

        if (key == "dust")
        {
            w.dustVolume = fraction;
        }
        else
        {
            w.volume[i] = fraction;
            w.number[i] = fraction*u/mixture_.particleVolume(i);
        }
    }

    if (mag(sum - 1) > 1e-9)
    {
        FatalIOErrorInFunction(fractions)
            << "The fragment volume fractions of " << parentName << " in "
            << fractions.name() << " sum to " << sum << ": they must sum to"
            << " 1 (volume and mass conservation)" << nl
            << exit(FatalIOError);
    }

    w.fragmentsPerEvent = w.numberOnGrid();
    return w;
}


// ************************************************************************* //
