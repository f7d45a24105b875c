// What every per-component estimator over a range of particle frames shares
// (velocity autocorrelation, MSD): the check of the range (non-empty, inside
// the frames, the same particles in every frame, at least one particle) and
// the pass over components and particles that sums their lagged terms.
#ifndef sdf_correlation_detail_FrameRange_hpp
#define sdf_correlation_detail_FrameRange_hpp

#include "correlation/FftCorrelator.hpp"
#include "correlation/detail/PaddedFft.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace sdf::correlation::detail
{

//- Throws std::invalid_argument, naming `estimator`, unless [begin, end) is a
//  non-empty range of `frames` whose frames all hold the same number (> 0)
//  of particles. Returns that number.
inline Eigen::Index checkFrameRange
(
    const VectorFrames& frames,
    std::size_t begin,
    std::size_t end,
    const std::string& estimator
)
{
    if (begin >= end || end > frames.size())
    {
        throw std::invalid_argument
        (
            estimator + ": bad frame range [" + std::to_string(begin)
          + ", " + std::to_string(end) + ") of " + std::to_string(frames.size())
        );
    }
    const Eigen::Index particles = frames[begin].rows();
    for (std::size_t t = begin; t < end; ++t)
    {
        if (frames[t].rows() != particles)
        {
            throw std::invalid_argument
            (
                estimator + ": frame " + std::to_string(t) + " has "
              + std::to_string(frames[t].rows()) + " particles, frame "
              + std::to_string(begin) + " has " + std::to_string(particles)
            );
        }
    }
    if (particles == 0)
    {
        throw std::invalid_argument(estimator + ": frames hold no particles");
    }
    return particles;
}

//- Raw lagged sums of frames [begin, end), per component, summed over the
//  particles; the estimator divides them by its number of terms.
struct FrameSums
{
    Eigen::MatrixX3d sums;          // (maxLag+1) x 3
    Eigen::Index particles = 0;
    std::size_t length = 0;         // frames in the range
};

//- Checks the range (checkFrameRange, naming estimator), then for each
//  component c and particle p calls addParticle(fft, x, sums): it adds the
//  particle's lagged terms to sums (maxLag + 1 entries, of component c), where
//  x(t), t = 0 .. length-1, is the particle's component c at frame begin + t
//  and fft is sized for the range and maxLag.
template<class AddParticle>
FrameSums sumOverParticles
(
    const VectorFrames& frames,
    std::size_t maxLag,
    std::size_t begin,
    std::size_t end,
    const std::string& estimator,
    AddParticle addParticle
)
{
    FrameSums result;
    result.particles = checkFrameRange(frames, begin, end, estimator);
    result.length = end - begin;
    PaddedFft fft(result.length, maxLag);
    result.sums.resize(maxLag + 1, 3);
    std::vector<double> sums;
    for (int c = 0; c < 3; ++c)
    {
        sums.assign(maxLag + 1, 0.0);
        for (Eigen::Index p = 0; p < result.particles; ++p)
        {
            addParticle
            (
                fft,
                [&](std::size_t t) { return frames[begin + t](p, c); },
                sums
            );
        }
        for (std::size_t k = 0; k <= maxLag; ++k)
        {
            result.sums(k, c) = sums[k];
        }
    }
    return result;
}

} // namespace sdf::correlation::detail

#endif
