/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "daughterSizeDistributionModel.H"
#include "modelCoeffs.H"
#include "SortableList.H"

namespace Foam
{
    defineTypeNameAndDebug(daughterSizeDistributionModel, 0);
    defineRunTimeSelectionTable(daughterSizeDistributionModel, dictionary);
}


Foam::daughterSizeDistributionModel::daughterSizeDistributionModel
(
    const word& type,
    const dictionary& dict,
    const granularMixture& mixture
)
:
    mixture_(mixture),
    coeffs_(modelCoeffs::coeffsDict(dict, type))
{}


Foam::scalar Foam::daughterSizeDistributionModel::volumeFraction
(
    const scalar,
    const scalar,
    const scalar
) const
{
    NotImplemented;
    return 0;
}


Foam::scalar Foam::daughterSizeDistributionModel::number
(
    const scalar,
    const scalar,
    const scalar
) const
{
    NotImplemented;
    return 0;
}


Foam::labelList Foam::daughterSizeDistributionModel::classGrid
(
    const granularMixture& mixture,
    const label parent
)
{
    const scalar rhoParent = mixture.rho(parent);
    const scalar dParent = mixture.d(parent);

    DynamicList<label> members;
    DynamicList<scalar> sizes;
    forAll(mixture.names(), i)
    {
        if (mag(mixture.rho(i) - rhoParent) > 1e-9*rhoParent)
        {
            continue;
        }
        // Pivots closer than this make the fixed-pivot hat functions
        // (divided by x_(i+1) - x_i) lose their digits
        if (i != parent && mag(mixture.d(i) - dParent) <= 1e-6*dParent)
        {
            FatalIOErrorInFunction(mixture)
                << "Species " << mixture.names()[i] << " and "
                << mixture.names()[parent] << " in " << mixture.objectPath()
                << " have the same material (rho " << rhoParent
                << ") and the same size (d " << mixture.d(i) << ", "
                << dParent << ", within 1e-6): breakage needs one class per"
                << " size" << nl << exit(FatalIOError);
        }
        if (mixture.d(i) <= dParent)
        {
            members.append(i);
            sizes.append(mixture.d(i));
        }
    }

    SortableList<scalar> sorted(sizes);
    labelList grid(members.size());
    forAll(grid, g)
    {
        grid[g] = members[sorted.indices()[g]];
    }
    return grid;
}


Foam::breakageWeights Foam::daughterSizeDistributionModel::weights
(
    const label parent,
    const labelList& grid,
    const bool dustSink
) const
{
    breakageWeights w;
    w.volume.setSize(mixture_.size(), Zero);
    w.number.setSize(mixture_.size(), Zero);

    scalarList x(grid.size());
    forAll(grid, g)
    {
        x[g] = mixture_.particleVolume(grid[g]);
    }
    const label m = grid.size() - 1;
    const scalar u = x[m];

    w.fragmentsPerEvent = number(0, u, u);

    // Fixed pivot: the hat functions of the pivots, integrated exactly
    // against the number distribution b(v|u):
    //   int_a^c (v - a)/(c - a) b dv = (u V(a,c) - a N(a,c))/(c - a)
    //   int_a^c (c - v)/(c - a) b dv = (c N(a,c) - u V(a,c))/(c - a)
    // with N the number and V the volume fraction in (a, c]
    for (label g = 0; g < m; ++g)
    {
        const scalar a = x[g];
        const scalar c = x[g + 1];
        const scalar N = number(a, c, u);
        const scalar V = volumeFraction(a, c, u);
        const scalar toUpper = (u*V - a*N)/(c - a);
        const scalar toLower = (c*N - u*V)/(c - a);
        w.number[grid[g]] += toLower;
        w.number[grid[g + 1]] += toUpper;
    }

    // Fragments finer than the finest pivot
    const scalar finesVolume = volumeFraction(0, x[0], u);
    if (dustSink)
    {
        w.dustVolume = finesVolume;
        w.dustNumber = (finesVolume > 0 ? number(0, x[0], u) : 0);
    }
    else
    {
        // Volume kept, counted as particles of the finest class
        w.number[grid[0]] += finesVolume*u/x[0];
    }

    forAll(grid, g)
    {
        w.volume[grid[g]] = w.number[grid[g]]*x[g]/u;
    }

    return w;
}


// ************************************************************************* //
