#ifndef sdf_dem_BlockBalance_hpp
#define sdf_dem_BlockBalance_hpp

// Thread balancing: each phase of a step (drift, force pass up to its barrier, cross
// contacts + finish after it) gives every thread one contiguous range of particles; the
// ranges follow the measured busy times. The boundaries never change a result (every
// particle sums its pairs in a fixed order whatever the ranges).

#include <vector>

namespace sdf::dem
{

//- Wall-clock seconds (OpenMP's clock when there is one) for the busy times.
double wallSeconds();

//- One phase's split of the work among threads: shares of a work model that follow the
//  measured busy times (work per busy second) halfway at each update.
struct BlockBalance
{
    std::vector<double> share;   // fraction of the work model per block
    std::vector<double> work;    // work-model units per block at the last split
    std::vector<double> busy;    // busy seconds per block since the last split
    std::vector<double> totalBusy;   // busy seconds per block up to the last split
    double totalWall = 0;            // wall-clock seconds of the phase since the start
                                     // (force pass: up to the barrier and after it)
    //- Busy seconds of block b since the start.
    double busySeconds(int b) const { return totalBusy[b] + busy[b]; }

    void reset(int nBlocks);
    void update();
    //- Contiguous particle ranges (begin of each block, then n) by share; particles cost 1.
    //  Boundaries are multiples of align (but the last).
    std::vector<int> splitParticles(int n, int align = 1);
};

} // namespace sdf::dem

#endif
