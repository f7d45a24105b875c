/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "outletComposition.H"
#include "Time.H"
#include "OSspecific.H"

Foam::outletComposition::outletComposition(const granularMixture& mixture)
:
    mixture_(mixture)
{
    const fvMesh& mesh = mixture.mesh();

    DynamicList<label> patches;
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& p = mesh.boundary()[patchi];
        if (!p.coupled() && p.type() == "patch")
        {
            patches.append(patchi);
        }
    }
    patches_.transfer(patches);

    cumulative_.setSize(patches_.size(), scalarList(mixture.size(), Zero));

    if (Pstream::master())
    {
        const fileName dir
        (
            mesh.time().globalPath()/"postProcessing"/"outletComposition"
           /mesh.time().timeName()
        );
        mkDir(dir);
        files_.setSize(patches_.size());
        forAll(patches_, pi)
        {
            files_.set
            (
                pi,
                new OFstream(dir/mesh.boundary()[patches_[pi]].name() + ".dat")
            );
            OFstream& os = files_[pi];
            os.precision(10);
            os  << "# Flow through patch " << mesh.boundary()[patches_[pi]].name()
                << " (positive leaving the domain)" << nl
                << "# time[s] Q[m3/s] massFlow[kg/s]";
            for (const word& s : mixture.names())
            {
                os << " massFlow." << s << "[kg/s]";
            }
            for (const word& s : mixture.names())
            {
                os << " massFraction." << s;
            }
            for (const word& s : mixture.names())
            {
                os << " cumulativeMass." << s << "[kg]";
            }
            os << endl;
        }
    }
}


void Foam::outletComposition::write(const surfaceScalarField& phi)
{
    const scalar t = mixture_.mesh().time().value();
    const scalar dt = mixture_.mesh().time().deltaTValue();

    forAll(patches_, pi)
    {
        const label patchi = patches_[pi];
        const scalarField& phip = phi.boundaryField()[patchi];

        const scalar Q = gSum(phip);
        scalarList massFlow(mixture_.size());
        scalar total = 0;
        forAll(massFlow, k)
        {
            massFlow[k] =
                mixture_.rho(k)
               *gSum(phip*mixture_.n()[k].boundaryField()[patchi]);
            total += massFlow[k];
            cumulative_[pi][k] += massFlow[k]*dt;
        }

        if (Pstream::master())
        {
            OFstream& os = files_[pi];
            os  << t << ' ' << Q << ' ' << total;
            forAll(massFlow, k)
            {
                os << ' ' << massFlow[k];
            }
            forAll(massFlow, k)
            {
                os << ' ' << (mag(total) > VSMALL ? massFlow[k]/total : 0);
            }
            forAll(massFlow, k)
            {
                os << ' ' << cumulative_[pi][k];
            }
            os << endl;
        }
    }
}


// ************************************************************************* //
