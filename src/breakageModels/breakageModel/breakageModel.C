/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "breakageModel.H"
#include "modelCoeffs.H"
#include "zeroGradientFvPatchFields.H"

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
    coeffs_(modelCoeffs::coeffsDict(dict, type))
{}


void Foam::breakageModel::checkNonNegative
(
    const word& key,
    const scalar value
) const
{
    modelCoeffs::checkNonNegative(coeffs_, key, value, "Breakage");
}


void Foam::breakageModel::correct
(
    const granularTemperatureModel& granularTemperature
)
{
    if (S_.empty())
    {
        S_.setSize(mixture_.size());
        forAll(S_, j)
        {
            S_.set
            (
                j,
                new volScalarField
                (
                    IOobject
                    (
                        "S." + mixture_.names()[j],
                        mixture_.mesh().time().timeName(),
                        mixture_.mesh(),
                        IOobject::NO_READ,
                        IOobject::NO_WRITE
                    ),
                    mixture_.mesh(),
                    dimensionedScalar("S", inv(dimTime), Zero),
                    zeroGradientFvPatchScalarField::typeName
                )
            );
        }
    }

    forAll(S_, j)
    {
        calcS(j, granularTemperature, S_[j]);
        S_[j].correctBoundaryConditions();

        const scalarField& Sj = S_[j].primitiveField();
        forAll(Sj, celli)
        {
            if (!std::isfinite(Sj[celli]) || Sj[celli] < 0)
            {
                FatalErrorInFunction
                    << "Breakage model " << coeffs_.name()
                    << " gave the selection rate " << Sj[celli]
                    << " for species " << mixture_.names()[j]
                    << " in cell " << celli << " (must be finite, >= 0)"
                    << exit(FatalError);
            }
        }
    }
}


const Foam::volScalarField& Foam::breakageModel::S(const label j) const
{
    if (S_.empty())
    {
        FatalErrorInFunction
            << "Selection rates requested before correct()"
            << exit(FatalError);
    }
    return S_[j];
}


// ************************************************************************* //
