#ifndef sdf_dem_ThreadTeam_hpp
#define sdf_dem_ThreadTeam_hpp

// Running a step's loops on the engine's threads. On one thread the body is called
// directly: an OpenMP team of one still ends with libgomp's futex wake-ups (about two
// system calls per parallel region), which cost a 500-particle cell 7.5 % of its step
// on a virtual machine, where system calls are expensive.

#include <algorithm>
#include <array>
#include <cstdint>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sdf::dem
{

//- Calls body(thread, teamSize) on each of nThreads threads (directly when nThreads <= 1);
//  returns the element-wise maximum of what the calls leave in their std::array<double, K>
//  (each call's array starts at `initial`). The maximum does not depend on the order in
//  which the threads merge, so the result is bitwise reproducible.
template<std::size_t K, class Body>
std::array<double, K> maxOverThreads(int nThreads, double initial, Body&& body)
{
    std::array<double, K> result;
    result.fill(initial);
    if (nThreads <= 1)
    {
        body(0, 1, result);
        return result;
    }
    #pragma omp parallel num_threads(nThreads)
    {
        int thread = 0, team = 1;
#ifdef _OPENMP
        thread = omp_get_thread_num();
        team = omp_get_num_threads();
#endif
        std::array<double, K> local;
        local.fill(initial);
        body(thread, team, local);
        #pragma omp critical(sdf_dem_maxOverThreads)
        for (std::size_t k = 0; k < K; ++k) result[k] = std::max(result[k], local[k]);
    }
    return result;
}

//- Calls body(thread, teamSize) on each of nThreads threads (directly when nThreads <= 1).
template<class Body>
void onThreads(int nThreads, Body&& body)
{
    maxOverThreads<0>(nThreads, 0.0, [&](int thread, int team, std::array<double, 0>&)
    {
        body(thread, team);
    });
}

//- Calls body(i) for every i in [0, n), the range split into one contiguous piece per
//  thread as schedule(static) splits it (directly when nThreads <= 1). For loops whose
//  iterations are independent: the result does not depend on the split.
template<class Body>
void forEachIndex(int nThreads, int n, Body&& body)
{
    onThreads(nThreads, [&](int thread, int team)
    {
        const int begin = int(std::int64_t(n)*thread/team);
        const int end = int(std::int64_t(n)*(thread + 1)/team);
        for (int i = begin; i < end; ++i) body(i);
    });
}

} // namespace sdf::dem

#endif
