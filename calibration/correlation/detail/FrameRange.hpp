// The check every estimator over a range of particle frames starts with
// (correlators, MSD): a non-empty range inside the frames, the same particles
// in every frame, and at least one particle.
#ifndef sdf_correlation_detail_FrameRange_hpp
#define sdf_correlation_detail_FrameRange_hpp

#include "correlation/FftCorrelator.hpp"

#include <stdexcept>
#include <string>

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

} // namespace sdf::correlation::detail

#endif
