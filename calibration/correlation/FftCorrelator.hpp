// Exact multiple-time-origin correlation functions of stored series, by FFT
// (GSL radix-2 real transforms with zero padding, so there is no wrap-around).
//
// Convention everywhere in sdf::correlation: for series a, b sampled at
// t = 0 .. N-1,
//     C_ab(k) = 1/(N-k) * sum_{t=0}^{N-1-k} a(t) b(t+k),    k = 0 .. maxLag,
// i.e. <a(0) b(k)> averaged over every available time origin (unbiased
// estimator; its noise grows as k -> N, so keep maxLag well below N).
#ifndef sdf_correlation_FftCorrelator_hpp
#define sdf_correlation_FftCorrelator_hpp

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

namespace sdf::correlation
{

//- One sample of a per-particle vector quantity: row p = particle p,
//  columns x, y, z (e.g. the velocities of one species at one sample time).
using VectorFrame = Eigen::MatrixX3d;

//- A stored trajectory: frames[t] for t = 0 .. N-1, all with the same rows.
using VectorFrames = std::vector<VectorFrame>;

//- C_ab(k) for k = 0 .. maxLag (requires maxLag < N, equal lengths).
std::vector<double> crossCorrelation
(
    const std::vector<double>& a,
    const std::vector<double>& b,
    std::size_t maxLag
);

//- C_aa(k) for k = 0 .. maxLag.
std::vector<double> autocorrelation(const std::vector<double>& a, std::size_t maxLag);

//- The same definition by the direct O(N maxLag) double sum: the reference
//  for tests, and fine for short series.
std::vector<double> crossCorrelationDirect
(
    const std::vector<double>& a,
    const std::vector<double>& b,
    std::size_t maxLag
);

//- Per-component autocorrelation of a per-particle vector series, averaged
//  over particles and time origins, using frames [begin, end):
//  row k, column c = < v_pc(t) v_pc(t+k) >_{p,t}. Returns (maxLag+1) x 3.
//  The velocity autocorrelation <v(0).v(t)> is the row sum; the isotropic
//  Green-Kubo diffusivity integrates the row mean.
Eigen::MatrixX3d vectorAutocorrelation
(
    const VectorFrames& frames,
    std::size_t maxLag,
    std::size_t begin,
    std::size_t end
);

//- vectorAutocorrelation over all frames.
Eigen::MatrixX3d vectorAutocorrelation(const VectorFrames& frames, std::size_t maxLag);

//- An estimator of a per-component function of the lag from frames
//  [begin, end) of a trajectory: vectorAutocorrelation, meanSquareDisplacement.
using FrameRangeEstimator = Eigen::MatrixX3d (*)
(
    const VectorFrames& frames,
    std::size_t maxLag,
    std::size_t begin,
    std::size_t end
);

//- estimate on each of blockCount contiguous, equal blocks of the trajectory
//  (Statistics.hpp blockRange): the independent estimates that the errors of
//  Green-Kubo and Einstein diffusivities come from.
std::vector<Eigen::MatrixX3d> blockEstimates
(
    FrameRangeEstimator estimate,
    const VectorFrames& frames,
    std::size_t maxLag,
    std::size_t blockCount
);

//- Column c (0, 1, 2) of each block's correlation, or with component = -1
//  the mean of the three columns (isotropic: <v(0).v(t)>/3).
std::vector<std::vector<double>> componentSeries
(
    const std::vector<Eigen::MatrixX3d>& blocks,
    int component
);

//- All products of S scalar series s_0 .. s_{S-1} (e.g. the shear stress
//  parts J^1, J^2, J^12): (i, j) = C_{s_i s_j}(k) = <s_i(0) s_j(k)>.
//  The autocorrelation of the total sum_i s_i is the sum of all S*S entries
//  (to round-off), so products (i == j) and cross terms (i != j) can be
//  compared on the same footing.
class SeriesProductCorrelations
{
public:
    SeriesProductCorrelations() = default;
    SeriesProductCorrelations(std::size_t seriesCount, std::size_t lagCount);

    std::size_t seriesCount() const { return seriesCount_; }
    std::size_t lagCount() const { return lagCount_; }

    const std::vector<double>& operator()(std::size_t i, std::size_t j) const;
    std::vector<double>& operator()(std::size_t i, std::size_t j);

    //- Sum over all (i, j): the autocorrelation of the total series.
    std::vector<double> total() const;

private:
    std::size_t seriesCount_ = 0;
    std::size_t lagCount_ = 0;
    std::vector<std::vector<double>> products_;   // row-major (i, j)
};

//- All S*S product correlations of the given equal-length series.
SeriesProductCorrelations seriesProductCorrelations
(
    const std::vector<std::vector<double>>& series,
    std::size_t maxLag
);

} // namespace sdf::correlation

#endif
