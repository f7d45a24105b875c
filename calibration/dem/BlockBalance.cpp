#include "BlockBalance.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sdf::dem
{

double wallSeconds()
{
#ifdef _OPENMP
    return omp_get_wtime();
#else
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
#endif
}

void BlockBalance::reset(int nBlocks)
{
    share.assign(nBlocks, 1.0/nBlocks);
    work.assign(nBlocks, 0.0);
    busy.assign(nBlocks, 0.0);
    totalBusy.assign(nBlocks, 0.0);
    totalWall = 0;
}

void BlockBalance::update()
{
    const int nBlocks = int(share.size());
    bool measured = nBlocks > 1;
    for (int b = 0; b < nBlocks; ++b)
    {
        totalBusy[b] += busy[b];
        measured = measured && busy[b] > 0 && work[b] > 0;
    }
    if (measured)
    {
        std::vector<double> speed(nBlocks);
        double speedSum = 0;
        for (int b = 0; b < nBlocks; ++b)
        {
            speed[b] = work[b]/busy[b];
            speedSum += speed[b];
        }
        for (int b = 0; b < nBlocks; ++b)
        {
            // halfway, and bounded, so that one disturbed interval cannot starve a block
            const double target = std::clamp(speed[b]/speedSum, 0.25/nBlocks, 1.75/nBlocks);
            share[b] = 0.5*(share[b] + target);
        }
    }
    busy.assign(nBlocks, 0.0);
}

std::vector<int> BlockBalance::splitParticles(int n, int align)
{
    const int nBlocks = int(share.size());
    std::vector<int> begin(nBlocks + 1, n);
    begin[0] = 0;
    double cumulative = 0;
    for (int b = 1; b < nBlocks; ++b)
    {
        cumulative += share[b - 1];
        const int aligned = align*int(std::lround(cumulative*n/align));
        begin[b] = std::clamp(aligned, begin[b - 1], n);
    }
    for (int b = 0; b < nBlocks; ++b) work[b] = begin[b + 1] - begin[b];
    return begin;
}

} // namespace sdf::dem
