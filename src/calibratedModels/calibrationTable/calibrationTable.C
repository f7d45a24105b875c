/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "calibrationTable.H"
#include "numberText.H"

#include "store/Store.hpp"
#include "fit/SievingNormalisation.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <vector>

const Foam::Enum<Foam::calibrationTable::interpolationType>
Foam::calibrationTable::interpolationTypeNames
({
    { interpolationType::linear, "linear" },
    { interpolationType::steffen, "steffen" },
});


namespace
{

//- Relative tolerance under which two stored axis values are one grid value
//  (the utility stores the dictionary's values; names use %.6g)
const Foam::scalar sameValueTolerance = 1e-9;

bool sameValue(const Foam::scalar a, const Foam::scalar b)
{
    return
        std::abs(a - b)
     <= sameValueTolerance*Foam::max(std::abs(a), std::abs(b));
}


//- Distinct sorted values
Foam::scalarList distinctSorted(std::vector<Foam::scalar> values)
{
    std::sort(values.begin(), values.end());
    Foam::DynamicList<Foam::scalar> out;
    for (const Foam::scalar v : values)
    {
        if (out.empty() || !sameValue(out.last(), v))
        {
            out.append(v);
        }
    }
    return Foam::scalarList(out);
}


Foam::label indexOf(const Foam::scalarList& axis, const Foam::scalar v)
{
    forAll(axis, i)
    {
        if (sameValue(axis[i], v))
        {
            return i;
        }
    }
    return -1;
}


using Foam::numberText::fmt;


//- One stored condition (one replica)
struct storedCondition
{
    std::string name;
    double phi, x, targetT, T;
    double value;
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::calibrationTable::calibrationTable
(
    const granularMixture& mixture,
    const dictionary& modelDict,
    const word& coefficient
)
:
    dict_(modelDict),
    file_
    (
        mixture.mesh().time().globalPath()
       /mixture.mesh().time().constant()
       /modelDict.getOrDefault<fileName>("calibrationFile", "calibration.h5")
    ),
    coefficient_(coefficient),
    fineName_(),
    coarseName_(),
    dFine_(0),
    rhoFine_(0),
    dCoarse_(0),
    rhoCoarse_(0),
    interpolation_
    (
        interpolationTypeNames.getOrDefault
        (
            "interpolation",
            modelDict,
            interpolationType::linear
        )
    ),
    logValues_(true),
    conditions_(0)
{
    if (coefficient_ != "D" && coefficient_ != "eta")
    {
        FatalErrorInFunction
            << "Coefficient '" << coefficient_ << "' is not tabulated;"
            << " valid: (D eta)" << exit(FatalError);
    }

    read();

    // Species of the file must be species of the mixture: the eta
    // conversion needs their d and rho, and D is the fines'
    const label finei = mixture.names().find(fineName_);
    const label coarsei = mixture.names().find(coarseName_);
    if (finei < 0 || coarsei < 0)
    {
        FatalIOErrorInFunction(dict_)
            << "Calibration table " << file_ << " is for the species ("
            << fineName_ << ' ' << coarseName_ << "), the mixture has "
            << mixture.names() << nl << exit(FatalIOError);
    }
    dFine_ = mixture.d(finei);
    rhoFine_ = mixture.rho(finei);
    dCoarse_ = mixture.d(coarsei);
    rhoCoarse_ = mixture.rho(coarsei);

    // eta depends on the species' d and rho: read again with them
    if (coefficient_ == "eta")
    {
        read();
    }

    Info<< "    calibrated " << coefficient_ << ": tabulated from " << file_
        << " (" << conditions_ << " conditions on a " << phi_.size()
        << " phi x " << x_.size() << " x x " << T_.size() << " T grid, "
        << interpolationTypeNames[interpolation_] << " in ln(phi), x, ln(T)"
        << " of " << (logValues_ ? "ln(" + coefficient_ + ")" : coefficient_)
        << ')' << nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::calibrationTable::read()
{
    std::vector<storedCondition> stored;
    const bool isD = coefficient_ == "D";
    const bool haveSpecies = dFine_ > 0;

    try
    {
        const sdf::store::StoreContents contents = sdf::store::readStore(file_);
        fineName_ = contents.fineSpecies;
        coarseName_ = contents.coarseSpecies;

        // Per condition name without a cell-size suffix: its particles and
        // the first record seen
        std::map<std::string, std::pair<std::int64_t, std::string>> sizeAtPoint;
        for (const sdf::store::ConditionRecord& record : contents.conditions)
        {
            if (record.rheology || record.segregation)
            {
                // a rheology cell or a sheared cell under gravity of the
                // same store: not a transport condition (fitted apart,
                // calibrateGranularMixture)
                continue;
            }
            if (record.gammaDot)
            {
                // A sheared cell's T is an output: its conditions do not lie
                // on a T grid the table could interpolate along
                throw std::runtime_error
                (
                    "condition " + record.name + " is a sheared cell (gammaDot "
                  + fmt(*record.gammaDot) + " 1/s): a sheared"
                    " calibration is used through its fitted laws (mode law),"
                    " not as a table"
                );
            }
            // Cells of several sizes at one grid point (a finite-size
            // calibration's) would be averaged as replicas; conditions run
            // with different particles at different points are a table
            const auto size = sizeAtPoint.emplace
            (
                record.name.substr(0, record.name.rfind("_N")),
                std::make_pair(record.particles, record.name)
            );
            if (!size.second && size.first->second.first != record.particles)
            {
                throw std::runtime_error
                (
                    "conditions " + size.first->second.second + " and "
                  + record.name + " are one condition run with "
                  + std::to_string(size.first->second.first) + " and "
                  + std::to_string(record.particles) + " particles (a"
                    " finite-size calibration): it is used through its"
                    " fitted laws (mode law), not as a table"
                );
            }
            storedCondition c;
            c.name = record.name;
            c.phi = record.phi;
            c.x = record.x;
            c.targetT = record.targetT;
            c.T = record.T;
            if (isD)
            {
                c.value = record.fine.D;
                if (record.fine.DConverged && !*record.fine.DConverged)
                {
                    // Interpolated as stored: a table has no errors to
                    // weight by (the fit does: docs/user/calibration.md)
                    WarningInFunction
                        << "Calibration table " << file_ << ": D of condition "
                        << record.name.c_str() << " is not in the diffusive"
                        << " regime (" << record.fine.DVerdict.c_str()
                        << "); it is interpolated as stored" << endl;
                }
            }
            else
            {
                if (!record.coarse.eta)
                {
                    throw std::runtime_error
                    (
                        "condition " + record.name + " has no kinetic sieving"
                        " coefficient eta of the coarse species "
                      + coarseName_
                    );
                }
                const double etaEngine = *record.coarse.eta;
                // Before the species are known the value is not used
                c.value =
                    haveSpecies
                  ? sdf::fit::kinematicSievingCoefficient
                    (
                        etaEngine, c.phi, c.x, c.T,
                        {dFine_, rhoFine_},
                        {dCoarse_, rhoCoarse_}
                    )
                  : etaEngine;
            }
            if
            (
                !std::isfinite(c.phi) || !std::isfinite(c.x)
             || !std::isfinite(c.targetT) || !std::isfinite(c.value)
             || !(c.phi > 0) || !(c.targetT > 0)
            )
            {
                throw std::runtime_error
                (
                    "condition " + c.name + " has a non-finite or"
                    " non-positive phi, targetT or " + coefficient_
                );
            }
            stored.push_back(c);
        }
    }
    catch (const sdf::store::StoreError& err)
    {
        FatalIOErrorInFunction(dict_)
            << "Cannot use " << file_ << " as the calibration table of "
            << coefficient_ << ":" << nl << "    " << err.message().c_str() << nl
            << "    (calibrationFile: a constant/calibration.h5 written by"
            << " calibrateGranularMixture)" << nl << exit(FatalIOError);
    }
    catch (const std::exception& err)
    {
        FatalIOErrorInFunction(dict_)
            << "Cannot use " << file_ << " as the calibration table of "
            << coefficient_ << ":" << nl << "    " << err.what() << nl
            << "    (calibrationFile: a constant/calibration.h5 written by"
            << " calibrateGranularMixture)" << nl << exit(FatalIOError);
    }

    if (stored.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "Calibration table " << file_ << " holds no conditions" << nl
            << exit(FatalIOError);
    }

    // Grid axes
    {
        std::vector<scalar> phis, xs, Ts;
        for (const storedCondition& c : stored)
        {
            phis.push_back(c.phi);
            xs.push_back(c.x);
            Ts.push_back(c.targetT);
        }
        phi_ = distinctSorted(phis);
        x_ = distinctSorted(xs);
        T_ = distinctSorted(Ts);
    }
    lnPhi_.setSize(phi_.size());
    forAll(phi_, i)
    {
        lnPhi_[i] = Foam::log(phi_[i]);
    }
    lnT_.setSize(T_.size());
    forAll(T_, i)
    {
        lnT_[i] = Foam::log(T_[i]);
    }

    // Replica average per grid point
    const label nx = x_.size(), nT = T_.size();
    scalarList sum(phi_.size()*nx*nT, Zero);
    labelList count(sum.size(), Zero);
    for (const storedCondition& c : stored)
    {
        const label k =
            (indexOf(phi_, c.phi)*nx + indexOf(x_, c.x))*nT
          + indexOf(T_, c.targetT);
        sum[k] += c.value;
        ++count[k];
    }

    forAll(count, k)
    {
        if (count[k] == 0)
        {
            const label i = k/(nx*nT);
            const label j = (k/nT) % nx;
            const label l = k % nT;
            FatalIOErrorInFunction(dict_)
                << "Calibration table " << file_ << " is not a complete grid:"
                << " condition phi" << fmt(phi_[i]).c_str()
                << "_x" << fmt(x_[j]).c_str() << "_T" << fmt(T_[l]).c_str()
                << " (any seed) is missing (grid " << phi_ << " x " << x_
                << " x " << T_ << ")" << nl
                << "    Run calibrateGranularMixture over the full envelope"
                << nl << exit(FatalIOError);
        }
    }

    values_ = sum;
    logValues_ = true;
    forAll(values_, k)
    {
        values_[k] /= count[k];
        logValues_ = logValues_ && values_[k] > 0;
    }
    if (logValues_)
    {
        for (scalar& v : values_)
        {
            v = Foam::log(v);
        }
    }
    conditions_ = label(stored.size());

    prepareInterpolation();
}


Foam::Tuple2<Foam::scalar, Foam::scalar>
Foam::calibrationTable::phiRange() const
{
    return Tuple2<scalar, scalar>(phi_.first(), phi_.last());
}


Foam::Tuple2<Foam::scalar, Foam::scalar>
Foam::calibrationTable::xRange() const
{
    return Tuple2<scalar, scalar>(x_.first(), x_.last());
}


Foam::Tuple2<Foam::scalar, Foam::scalar>
Foam::calibrationTable::TRange() const
{
    return Tuple2<scalar, scalar>(T_.first(), T_.last());
}


const gsl_interp_type* Foam::calibrationTable::interpType(const label n) const
{
    return
        interpolation_ == interpolationType::steffen && n >= 3
      ? gsl_interp_steffen
      : gsl_interp_linear;
}


void Foam::calibrationTable::prepareInterpolation()
{
    const label nPhi = phi_.size(), nx = x_.size(), nT = T_.size();

    TLines_.clear();
    if (nT >= 2)
    {
        for (label line = 0; line < nPhi*nx; ++line)
        {
            TLines_.emplace_back(gsl_interp_alloc(interpType(nT), nT));
            gsl_interp_init
            (
                TLines_.back().get(),
                lnT_.cdata(),
                values_.cdata() + line*nT,
                nT
            );
        }
    }
    xWork_.reset(nx >= 2 ? gsl_interp_alloc(interpType(nx), nx) : nullptr);
    phiWork_.reset
    (
        nPhi >= 2 ? gsl_interp_alloc(interpType(nPhi), nPhi) : nullptr
    );
    alongX_.setSize(nx);
    alongPhi_.setSize(nPhi);
}


Foam::scalar Foam::calibrationTable::interpolate1
(
    const scalar* axis,
    const scalar* values,
    const label n,
    const scalar q,
    gsl_interp* interp,
    const bool init
)
{
    if (n == 1)
    {
        return values[0];
    }

    // Outside the axis: the end interval's straight line. GSL refuses
    // (its error handler would abort) rather than extrapolate.
    if (q <= axis[0] || q >= axis[n - 1])
    {
        const label a = q <= axis[0] ? 0 : n - 2;
        return
            values[a]
          + (q - axis[a])*(values[a + 1] - values[a])/(axis[a + 1] - axis[a]);
    }

    if (init)
    {
        gsl_interp_init(interp, axis, values, n);
    }
    return gsl_interp_eval(interp, axis, values, q, nullptr);
}


Foam::scalar Foam::calibrationTable::value
(
    const scalar phi,
    const scalar x,
    const scalar T
) const
{
    if (!(T > 0) || !(phi > 0))
    {
        return 0;
    }
    const scalar lnPhi = Foam::log(phi);
    const scalar lnT = Foam::log(T);

    const label nPhi = phi_.size(), nx = x_.size(), nT = T_.size();
    for (label i = 0; i < nPhi; ++i)
    {
        for (label j = 0; j < nx; ++j)
        {
            const label line = i*nx + j;
            alongX_[j] = interpolate1
            (
                lnT_.cdata(),
                values_.cdata() + line*nT,
                nT,
                lnT,
                nT >= 2 ? TLines_[line].get() : nullptr,
                false
            );
        }
        alongPhi_[i] = interpolate1
        (
            x_.cdata(), alongX_.cdata(), nx, x, xWork_.get(), true
        );
    }
    const scalar v = interpolate1
    (
        lnPhi_.cdata(), alongPhi_.cdata(), nPhi, lnPhi, phiWork_.get(), true
    );
    return logValues_ ? Foam::exp(v) : v;
}


// ************************************************************************* //
