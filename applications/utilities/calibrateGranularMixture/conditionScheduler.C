/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "conditionScheduler.H"
#include "numberText.H"
#include "Pstream.H"

#include "store/Store.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <thread>

#include <omp.h>

using namespace Foam;
using numberText::fmt;

namespace
{

//- A DEM condition finished by a worker thread, handed to the main thread
//  (the only one that calls HDF5 and writes to Info)
struct FinishedCondition
{
    label index = -1;                    // in the list of all conditions
    sdf::dem::CellRunResult result;
    //- a sheared cell under gravity's
    sdf::dem::GravityShearRunResult segregation;
    std::string error;                   // the engine's message if it stopped
    double seconds = 0;
};

} // End anonymous namespace


std::string Foam::calibrationCondition::text() const
{
    if (rheology())
    {
        return
            "rheology I " + fmt(inertialNumber) + " p " + fmt(pressure)
          + " seed " + std::to_string(seed);
    }
    if (segregation())
    {
        return
            "segregation sigma_N " + fmt(normalStress) + " x " + fmt(x)
          + " seed " + std::to_string(seed);
    }
    return
        "phi " + fmt(phi) + " x " + fmt(x)
      + (sheared() ? " gammaDot " + fmt(gammaDot) : " T " + fmt(T))
      + " seed " + std::to_string(seed)
      + (particles > 0 ? " N " + std::to_string(particles) : std::string());
}


sdf::store::ConditionInputs Foam::calibrationCondition::inputs() const
{
    sdf::store::ConditionInputs in;
    in.name = name;
    in.phi = phi;
    in.x = x;
    in.seed = seed;
    if (rheology())
    {
        in.inertialNumber = inertialNumber;
    }
    if (segregation())
    {
        in.normalStress = normalStress;
    }
    if (sheared())
    {
        in.gammaDot = gammaDot;
    }
    else
    {
        in.targetT = T;
    }
    return in;
}


std::vector<Foam::calibrationCondition> Foam::envelopeConditions
(
    const calibrationSettings::envelopeAxes& envelope,
    const labelList& replicas,
    const labelList& particles
)
{
    const bool sheared = !envelope.gammaDot.empty();
    // One cell size (0: the settings') unless finiteSize gives several
    const labelList sizes(particles.empty() ? labelList({0}) : particles);
    std::vector<calibrationCondition> conds;
    for (const scalar phi : envelope.phi)
    {
        for (const scalar x : envelope.x)
        {
            for (const scalar rate : envelope.rates())
            {
                for (const label seed : replicas)
                {
                    const std::string point =
                        sheared
                      ? sdf::store::shearedConditionName(phi, x, rate, seed)
                      : sdf::store::conditionName(phi, x, rate, seed);
                    for (const label n : sizes)
                    {
                        calibrationCondition c;
                        c.phi = phi;
                        c.x = x;
                        c.T = sheared ? 0 : rate;
                        c.gammaDot = sheared ? rate : 0;
                        c.seed = seed;
                        c.particles = n;
                        c.pointName = point;
                        c.name =
                            n > 0
                          ? sdf::store::sizedConditionName(point, n)
                          : point;
                        conds.push_back(c);
                    }
                }
            }
        }
    }
    return conds;
}


std::vector<Foam::calibrationCondition> Foam::rheologyConditions
(
    const calibrationSettings& settings
)
{
    std::vector<calibrationCondition> conds;
    if (!settings.calibratesRheology())
    {
        return conds;
    }
    const calibrationSettings::rheologyEnvelope& r = settings.rheology();
    for (const scalar I : r.inertialNumber)
    {
        for (const label seed : settings.replicas())
        {
            calibrationCondition c;
            c.phi = r.phi;
            c.x = r.x;
            c.T = 0;
            c.gammaDot =
                settings.rheologyCellSettings(I, seed, "").simulation.shearRate;
            c.seed = seed;
            c.particles = 0;
            c.inertialNumber = I;
            c.pressure = r.pressure;
            c.pointName =
                sdf::store::rheologyConditionName(I, r.pressure, r.x, seed);
            c.name = c.pointName;
            conds.push_back(c);
        }
    }
    return conds;
}


std::vector<Foam::calibrationCondition> Foam::segregationConditions
(
    const calibrationSettings& settings
)
{
    std::vector<calibrationCondition> conds;
    if (!settings.calibratesSegregation())
    {
        return conds;
    }
    const calibrationSettings::segregationEnvelope& e = settings.segregation();
    for (const scalar sigma : e.normalStress)
    {
        for (const label seed : settings.replicas())
        {
            calibrationCondition c;
            c.phi = e.phi;
            c.x = e.x;
            c.T = 0;
            c.gammaDot = 0;
            c.seed = seed;
            c.particles = 0;
            c.normalStress = sigma;
            c.pointName =
                sdf::store::segregationConditionName(sigma, e.x, seed);
            c.name = c.pointName;
            conds.push_back(c);
        }
    }
    return conds;
}


sdf::dem::CellRunSettings Foam::cellSettings
(
    const calibrationCondition& c,
    const calibrationSettings& settings
)
{
    if (c.segregation())
    {
        return settings.segregationCellSettings(c.normalStress, c.seed, c.name).cell;
    }
    if (c.rheology())
    {
        return settings.rheologyCellSettings(c.inertialNumber, c.seed, c.name);
    }
    return settings.conditionSettings
    (
        c.phi, c.x, c.rate(), c.seed, c.name, c.particles
    );
}


std::string Foam::settingsKeyOf
(
    const calibrationCondition& c,
    const calibrationSettings& settings
)
{
    if (c.segregation())
    {
        return settings.segregationSettingsKey();
    }
    return
        c.rheology()
      ? settings.rheologySettingsKey()
      : settings.settingsKey(c.particles);
}


std::vector<Foam::label> Foam::conditionsOfThisRank
(
    const std::vector<calibrationCondition>& conds,
    const std::vector<label>& todo
)
{
    // Dealt by envelope point: the cells of one point (its sizes, with
    // finiteSize) go to one rank, so that every rank gets the same mix of
    // small and large cells (round-robin by cell would give one rank every
    // small and another every large one)
    std::vector<label> mine;
    label point = -1;
    for (std::size_t j = 0; j < todo.size(); ++j)
    {
        if (j == 0 || conds[todo[j]].pointName != conds[todo[j - 1]].pointName)
        {
            ++point;
        }
        if (label(point % Pstream::nProcs()) == Pstream::myProcNo())
        {
            mine.push_back(todo[j]);
        }
    }
    return mine;
}


double Foam::expectedCost
(
    const calibrationCondition& c,
    const calibrationSettings& settings
)
{
    const sdf::dem::CellRunSettings s = cellSettings(c, settings);
    return
        double(s.particles)*(s.equilibrationTime + s.samplingTime)
       *(1 + 4*c.phi*c.phi);
}


std::vector<Foam::label> Foam::longestFirst
(
    const std::vector<calibrationCondition>& conds,
    std::vector<label> todo,
    const calibrationSettings& settings
)
{
    std::vector<double> cost(conds.size(), 0);
    for (const label i : todo)
    {
        cost[i] = expectedCost(conds[i], settings);
    }
    std::stable_sort
    (
        todo.begin(), todo.end(),
        [&](label a, label b) { return cost[a] > cost[b]; }
    );
    return todo;
}


Foam::label Foam::conditionWorkers
(
    const calibrationSettings& settings,
    const label conditions,
    OSstream& progress
)
{
    const label threadsPerCell =
        settings.base().simulation.threads > 0
      ? label(settings.base().simulation.threads)
      : label(omp_get_max_threads());
    const label hardwareThreads =
        max(label(1), label(std::thread::hardware_concurrency()));
    label workers = settings.concurrentConditions();
    if (workers == 0)
    {
        workers =
            Pstream::parRun()
          ? 1
          : max(label(1), hardwareThreads/threadsPerCell);
    }
    workers = max(label(1), min(workers, conditions));

    if (conditions > 0)
    {
        progress
            << conditions << " conditions to run, " << workers
            << " at once (longest expected first; " << threadsPerCell
            << " threads per cell, "
            << hardwareThreads << " hardware threads"
            << (
                   Pstream::parRun()
                 ? ", rank " + std::to_string(Pstream::myProcNo()) + " of "
                 + std::to_string(Pstream::nProcs())
                 : std::string()
               ).c_str()
            << ")" << endl;
    }
    return workers;
}


Foam::label Foam::runConditions
(
    const std::vector<calibrationCondition>& conds,
    const std::vector<label>& todo,
    const calibrationSettings& settings,
    const label workers,
    const fileName& store,
    OSstream& progress
)
{
    std::mutex mutex;
    std::condition_variable finishedOne;
    std::deque<FinishedCondition> finished;
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    label running = workers;
    // when each running condition started: the ETA credits their work so far
    std::map<label, std::chrono::steady_clock::time_point> started;

    auto work = [&]()
    {
        for (;;)
        {
            const std::size_t j = next++;
            if (stop || j >= todo.size())
            {
                break;
            }
            FinishedCondition f;
            f.index = todo[j];
            const auto t0 = std::chrono::steady_clock::now();
            {
                std::lock_guard<std::mutex> lock(mutex);
                started[f.index] = t0;
            }
            try
            {
                const calibrationCondition& c = conds[f.index];
                if (c.segregation())
                {
                    f.segregation = sdf::dem::runGravityShearCell
                    (
                        settings.segregationCellSettings
                        (
                            c.normalStress, c.seed, c.name
                        )
                    );
                }
                else
                {
                    f.result = sdf::dem::runCell(cellSettings(c, settings));
                }
            }
            catch (const std::exception& err)
            {
                f.error = err.what();
            }
            f.seconds = std::chrono::duration<double>
                (std::chrono::steady_clock::now() - t0).count();
            {
                std::lock_guard<std::mutex> lock(mutex);
                started.erase(f.index);
                finished.push_back(std::move(f));
            }
            finishedOne.notify_one();
        }
        {
            std::lock_guard<std::mutex> lock(mutex);
            --running;
        }
        finishedOne.notify_one();
    };

    std::vector<std::thread> pool;
    for (label w = 0; w < workers; ++w)
    {
        pool.emplace_back(work);
    }

    label ran = 0;
    // the ETA: the worker-seconds per unit of expected cost so far, times the
    // expected cost left, over the workers (the dearest conditions run first,
    // so a plain count of conditions would overestimate it); a running
    // condition's cost left is its expected cost less its seconds so far at
    // that rate (at least 0)
    std::vector<double> cost(conds.size(), 0);
    double totalCost = 0, doneCost = 0, doneSeconds = 0;
    for (const label i : todo)
    {
        cost[i] = expectedCost(conds[i], settings);
        totalCost += cost[i];
    }
    std::string firstError;
    std::unique_lock<std::mutex> lock(mutex);
    for (;;)
    {
        finishedOne.wait
        (
            lock, [&]{ return !finished.empty() || running == 0; }
        );
        if (finished.empty())
        {
            break;
        }
        FinishedCondition f(std::move(finished.front()));
        finished.pop_front();
        lock.unlock();

        const calibrationCondition& c = conds[f.index];
        const std::string where =
            "condition " + std::to_string(f.index + 1) + "/"
          + std::to_string(conds.size())
          + " (" + c.text() + ")";
        // a rheology cell that is not a steady dense flow, a sheared cell
        // under gravity not at its condition, or either refused by the
        // engine: reported, never stored (the fit leaves it out)
        std::string leftOutReason;
        if (c.rheology() || c.segregation())
        {
            const sdf::dem::RheologyResult& h = f.result.rheology;
            if (!f.error.empty())
            {
                leftOutReason = "refused by the DEM engine: " + f.error;
            }
            else if (c.segregation())
            {
                leftOutReason = f.segregation.segregation.unreachedState();
            }
            else if (!h.denseSteadyFlow())
            {
                leftOutReason =
                    (h.steady ? "" : "not steady: " + h.steadyCheck + "; ")
                  + "regime " + h.regime + ": " + h.regimeReason;
            }
        }
        if (!leftOutReason.empty())
        {
            progress << where.c_str() << " done in " << fmt(f.seconds).c_str()
                << " s: left out of the "
                << (c.segregation() ? "segregation" : "rheology")
                << " fit, not stored (" << leftOutReason.c_str() << ")" << endl;
            doneCost += cost[f.index];
            doneSeconds += f.seconds;
        }
        else if (!f.error.empty())
        {
            stop = true;
            if (firstError.empty())
            {
                firstError =
                    "The DEM engine stopped " + where + ":\n    " + f.error;
            }
        }
        else
        {
            try
            {
                if (c.segregation())
                {
                    settings.appendToStore(store, c.inputs(), f.segregation);
                }
                else
                {
                    settings.appendToStore(store, c.inputs(), f.result);
                }
                ++ran;
                doneCost += cost[f.index];
                doneSeconds += f.seconds;
                // over the workers still busy at the end: no more than the
                // conditions left
                const label busy = std::max
                (
                    label(1), std::min(workers, label(todo.size()) - ran)
                );
                double costLeft = totalCost - doneCost;
                if (doneSeconds > 0)
                {
                    const auto now = std::chrono::steady_clock::now();
                    std::lock_guard<std::mutex> guard(mutex);
                    for (const auto& run : started)
                    {
                        const double seconds =
                            std::chrono::duration<double>(now - run.second).count();
                        costLeft -= std::min
                        (
                            cost[run.first], seconds*doneCost/doneSeconds
                        );
                    }
                    // finished, waiting to be stored: no work left
                    for (const FinishedCondition& waiting : finished)
                    {
                        costLeft -= cost[waiting.index];
                    }
                }
                // (a cost left of round-off is none)
                const double eta =
                    doneCost > 0 && ran < label(todo.size())
                 && costLeft > 1e-9*totalCost
                  ? std::max(0.0, doneSeconds/doneCost*costLeft/busy)
                  : 0;
                const sdf::dem::CellRunResult& r = f.result;
                const sdf::dem::RheologyResult& h = r.rheology;
                // what the cell measured: a rheology cell's I, mu, phi and
                // sigma_yy; a transport cell's T and D of the fines
                const sdf::dem::SegregationMeasurement& m =
                    f.segregation.segregation;
                const std::string measured =
                    c.segregation()
                  ? "p* = " + fmt(m.pressureNumber) + ", I = "
                  + fmt(m.inertialNumber) + ", S = "
                  + fmt(m.balance.value) + " +- " + fmt(m.balance.standardError)
                  + " m (balance), " + fmt(m.early.value) + " +- "
                  + fmt(m.early.standardError) + " m (early), C = "
                  + fmt(m.shearRateDiffusivity.value)
                  : c.rheology()
                  ? "I = " + fmt(h.inertialNumber.value) + ", mu = "
                  + fmt(h.stressRatio.value) + " +- "
                  + fmt(h.stressRatio.standardError) + ", phi = "
                  + fmt(h.solidsFraction.value) + " +- "
                  + fmt(h.solidsFraction.standardError) + ", sigma_yy = "
                  + fmt(h.pressure.value) + " Pa"
                  : "T = " + fmt(r.temperature) + ", D_" + settings.fine().name
                  + " = " + fmt(r.species[0].greenKubo.integral.value) + " +- "
                  + fmt(r.species[0].greenKubo.integral.standardError) + " m2/s"
                  + (
                        c.sheared()
                      ? " (yy, across the shear), R = " + fmt(r.savageJeffreyR)
                      : std::string()
                    );
                progress << where.c_str() << " done in " << fmt(f.seconds).c_str()
                    << " s, ETA " << fmt(eta).c_str() << " s ("
                    << measured.c_str() << ")" << endl;
                if
                (
                    !c.rheology() && !c.segregation()
                 && !r.species[0].diffusiveRegime.converged()
                )
                {
                    progress
                        << "    not in the diffusive regime (stored as not"
                        << " converged, weighted down in the fit): "
                        << r.species[0].diffusiveRegime.verdict().c_str()
                        << endl;
                }
            }
            catch (const std::exception& err)
            {
                stop = true;
                if (firstError.empty())
                {
                    firstError =
                        "Storing " + where + " in " + std::string(store)
                      + " failed:\n    " + err.what();
                }
            }
        }
        lock.lock();
    }
    lock.unlock();
    for (std::thread& t : pool)
    {
        t.join();
    }
    if (!firstError.empty())
    {
        FatalErrorInFunction
            << firstError.c_str() << nl
            << "    Every condition finished before is stored in " << store
            << nl << exit(FatalError);
    }
    return ran;
}


// ************************************************************************* //
