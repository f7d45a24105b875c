#include "NeighbourList.hpp"
#include "ThreadTeam.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sdf::dem
{

void NeighbourList::build(const Particles& p, const PeriodicBox& box, double skin, int threads)
{
    const int n = int(p.size());
    double rMax = 0;
    for (int i = 0; i < n; ++i) rMax = std::max(rMax, p.radius[i]);
    cutoff_ = 2*rMax + skin;
    if (box.lx < 2*cutoff_ || box.ly < 2*cutoff_ || box.lz < 2*cutoff_)
    {
        throw std::invalid_argument
        (
            "periodic box " + std::to_string(box.lx) + " x " + std::to_string(box.ly)
          + " x " + std::to_string(box.lz) + " is thinner than 2 (2 R_max + skin) = "
          + std::to_string(2*cutoff_) + ": use more particles or a smaller size ratio"
        );
    }
    const int ncx = std::max(1, int(box.lx/cutoff_));
    const int ncy = std::max(1, int(box.ly/cutoff_));
    const int ncz = std::max(1, int(box.lz/cutoff_));
    const double wx = box.lx/ncx, wy = box.ly/ncy, wz = box.lz/ncz;
    const int nCells = ncx*ncy*ncz;

    // counting sort of particles into cells (keeps particle order within a cell)
    particleCell_.resize(n);
    cellStart_.assign(nCells + 1, 0);
    for (int i = 0; i < n; ++i)
    {
        const int cx = std::min(ncx - 1, int(p.x[i]/wx));
        const int cy = std::min(ncy - 1, int(p.y[i]/wy));
        const int cz = std::min(ncz - 1, int(p.z[i]/wz));
        particleCell_[i] = (cz*ncy + cy)*ncx + cx;
        ++cellStart_[particleCell_[i] + 1];
    }
    for (int c = 0; c < nCells; ++c) cellStart_[c + 1] += cellStart_[c];
    cellParticles_.resize(n);
    {
        std::vector<int> fill(cellStart_.begin(), cellStart_.end() - 1);
        for (int i = 0; i < n; ++i) cellParticles_[fill[particleCell_[i]]++] = i;
    }

    const int shiftCells = int(std::floor(box.offset/wx));

    // each cell's neighbour cells (Lees-Edwards: the rows across the y boundary are shifted
    // by the offset), once per cell rather than once per particle
    stencilStart_.assign(nCells + 1, 0);
    stencilCells_.clear();
    {
        std::vector<int> cells;
        cells.reserve(64);
        for (int c = 0; c < nCells; ++c)
        {
            const int cx = c % ncx, cy = (c/ncx) % ncy, cz = c/(ncx*ncy);
            cells.clear();
            for (int dz = -1; dz <= 1; ++dz)
            {
                const int zz = ((cz + dz) % ncz + ncz) % ncz;
                for (int dy = -1; dy <= 1; ++dy)
                {
                    int yy = cy + dy;
                    int dxLo = -1, dxHi = 1;
                    if (yy >= ncy) { dxLo = -2 - shiftCells; dxHi = 1 - shiftCells; }
                    else if (yy < 0) { dxLo = -1 + shiftCells; dxHi = 2 + shiftCells; }
                    yy = (yy % ncy + ncy) % ncy;
                    for (int dx = dxLo; dx <= dxHi; ++dx)
                    {
                        const int xx = (((cx + dx) % ncx) + ncx) % ncx;
                        cells.push_back((zz*ncy + yy)*ncx + xx);
                    }
                }
            }
            std::sort(cells.begin(), cells.end());
            cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
            stencilCells_.insert(stencilCells_.end(), cells.begin(), cells.end());
            stencilStart_[c + 1] = int(stencilCells_.size());
        }
    }

    // positions and radii in cell order: the candidate loop reads them contiguously
    cellPosition_.resize(n);
    for (int k = 0; k < n; ++k)
    {
        const int j = cellParticles_[k];
        cellPosition_[k] = {p.x[j], p.y[j], p.z[j], p.radius[j]};
    }

    int nThreads = 1;
#ifdef _OPENMP
    nThreads = threads > 0 ? threads : omp_get_max_threads();
#else
    (void)threads;
#endif
    // per-thread pair lists, kept between builds (no reallocation as they grow)
    if (int(firstLocal_.size()) != nThreads)
    {
        firstLocal_.assign(nThreads, {});
        secondLocal_.assign(nThreads, {});
    }

    // contiguous ranges of i in thread order (the lists are joined in that order), split
    // by the pairs each particle had in the last list plus one: the particles at the
    // bottom of a y-numbered cell scan the wrapped top row too (all of higher index), so
    // equal particle counts gave the first thread ~1.5 x the work
    std::vector<int> rangeBegin(nThreads + 1, n);
    rangeBegin[0] = 0;
    {
        std::vector<int> pairsOf(n, 0);
        for (const int i : first_) if (i < n) ++pairsOf[i];
        const double total = double(first_.size()) + n;
        double done = 0;
        int t = 1;
        for (int i = 0; i < n && t < nThreads; ++i)
        {
            while (t < nThreads && done >= total*t/nThreads) rangeBegin[t++] = i;
            done += pairsOf[i] + 1;
        }
    }

    onThreads(nThreads, [&](int tid, int /*team*/)
    {
        std::vector<int>& fl = firstLocal_[tid];
        std::vector<int>& sl = secondLocal_[tid];
        fl.clear();
        sl.clear();
        std::vector<int> partners;

        for (int i = rangeBegin[tid]; i < rangeBegin[tid + 1]; ++i)
        {
            const int c = particleCell_[i];
            partners.clear();
            const double xi = p.x[i], yi = p.y[i], zi = p.z[i], ri = p.radius[i];
            for (int s = stencilStart_[c]; s < stencilStart_[c + 1]; ++s)
            {
                const int cell = stencilCells_[s];
                // a cell lists its particles in increasing index: start after i
                const int* begin = cellParticles_.data() + cellStart_[cell];
                const int* end = cellParticles_.data() + cellStart_[cell + 1];
                const int* k = std::upper_bound(begin, end, i);
                for (; k != end; ++k)
                {
                    const std::array<double, 4>& q = cellPosition_[k - cellParticles_.data()];
                    double dx = xi - q[0], dy = yi - q[1], dz = zi - q[2], dvx = 0;
                    box.minimumImage(dx, dy, dz, dvx);
                    const double reach = ri + q[3] + skin;
                    if (dx*dx + dy*dy + dz*dz < reach*reach) partners.push_back(*k);
                }
            }
            std::sort(partners.begin(), partners.end());
            for (const int j : partners) { fl.push_back(i); sl.push_back(j); }
        }
    });

    first_.clear();
    second_.clear();
    for (int t = 0; t < nThreads; ++t)
    {
        first_.insert(first_.end(), firstLocal_[t].begin(), firstLocal_[t].end());
        second_.insert(second_.end(), secondLocal_[t].begin(), secondLocal_[t].end());
    }

    ++builds_;
}

} // namespace sdf::dem
