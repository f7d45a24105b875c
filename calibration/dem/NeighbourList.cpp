#include "NeighbourList.hpp"

#include <algorithm>
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

    int nThreads = 1;
#ifdef _OPENMP
    nThreads = threads > 0 ? threads : omp_get_max_threads();
#else
    (void)threads;
#endif
    std::vector<std::vector<int>> firstLocal(nThreads), secondLocal(nThreads);

    #pragma omp parallel num_threads(nThreads)
    {
        int tid = 0;
#ifdef _OPENMP
        tid = omp_get_thread_num();
#endif
        std::vector<int>& fl = firstLocal[tid];
        std::vector<int>& sl = secondLocal[tid];
        std::vector<int> cells;
        std::vector<int> partners;
        cells.reserve(64);

        // static schedule without chunk: contiguous blocks of i in thread order
        #pragma omp for schedule(static)
        for (int i = 0; i < n; ++i)
        {
            const int c = particleCell_[i];
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

            partners.clear();
            const double xi = p.x[i], yi = p.y[i], zi = p.z[i], ri = p.radius[i];
            for (const int cell : cells)
            {
                for (int k = cellStart_[cell]; k < cellStart_[cell + 1]; ++k)
                {
                    const int j = cellParticles_[k];
                    if (j <= i) continue;
                    double dx = xi - p.x[j], dy = yi - p.y[j], dz = zi - p.z[j], dvx = 0;
                    box.minimumImage(dx, dy, dz, dvx);
                    const double reach = ri + p.radius[j] + skin;
                    if (dx*dx + dy*dy + dz*dz < reach*reach) partners.push_back(j);
                }
            }
            std::sort(partners.begin(), partners.end());
            for (const int j : partners) { fl.push_back(i); sl.push_back(j); }
        }
    }

    first_.clear();
    second_.clear();
    for (int t = 0; t < nThreads; ++t)
    {
        first_.insert(first_.end(), firstLocal[t].begin(), firstLocal[t].end());
        second_.insert(second_.end(), secondLocal[t].begin(), secondLocal[t].end());
    }

    ++builds_;
}

} // namespace sdf::dem
