#ifndef sdf_dem_Measurement_hpp
#define sdf_dem_Measurement_hpp

// What a cell run measures while it samples, one object per measurement with one interface:
// built before the sampling (start), sampled every sampling interval, told when a block of
// the block errors closes, saved in and restored from a checkpoint, and finished into its
// part of the CellRunResult (written to HDF5 by writeCellRun, one section per measurement).
// The run calls every measurement once per sample, never inside the step.
//
// A new measurement: a class derived from Measurement (Measurements.hpp/.cpp), its result
// fields in CellRunResult (CellRun.hpp), its HDF5 section (CellRunHdf5.cpp), its summary
// line (CellRunOutput.cpp) and one line in makeMeasurements (CellRun.cpp).

#include "CellRun.hpp"

#include "io/Checkpoint.hpp"

#include <memory>
#include <string>
#include <vector>

namespace sdf::dem
{

//- When a cell samples: every sampleEvery steps, samplesPerBlock samples per block.
struct SamplingPlan
{
    long totalSteps = 0;
    long samples = 0;
    long samplesPerBlock = 0;
    double sampleInterval = 0;     // [s]
    int blocks = 0;
    //- Component of the diffusivity: -1 isotropic mean (homogeneous cells), 1 = y (sheared)
    int diffusionComponent = -1;

    SamplingPlan(const CellRunSettings& settings, double timeStep);
};

class Measurement
{
public:
    virtual ~Measurement() = default;

    //- One sample of the state; index counts the samples of the run from 0.
    virtual void sample(const Simulation& simulation, long index) = 0;
    //- The sample that completes a block of the block errors has been taken.
    virtual void closeBlock() {}

    //- Its state as checkpoint entries (names prefixed "cellRun_"), and back.
    virtual void save(io::Checkpoint& checkpoint) const = 0;
    virtual void load(const io::Checkpoint& checkpoint, const std::string& source) = 0;

    //- Its results into result (result.species holds name and count of each species);
    //  samples: the samples taken in the whole run.
    virtual void finish(CellRunResult& result, long samples) const = 0;
};

using Measurements = std::vector<std::unique_ptr<Measurement>>;

} // namespace sdf::dem

#endif
