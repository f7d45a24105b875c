#include "correlation/FftCorrelator.hpp"
#include "correlation/detail/FrameRange.hpp"
#include "correlation/detail/PaddedFft.hpp"
#include "correlation/Statistics.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_fft_halfcomplex.h>
#include <gsl/gsl_fft_real.h>

#include <stdexcept>
#include <string>

namespace sdf::correlation
{

namespace detail
{

PaddedFft::PaddedFft(std::size_t seriesLength, std::size_t maxLag)
:
    seriesLength_(seriesLength),
    maxLag_(maxLag),
    paddedLength_(2)
{
    if (seriesLength == 0 || maxLag >= seriesLength)
    {
        throw std::invalid_argument
        (
            "correlation: maxLag " + std::to_string(maxLag)
          + " must be smaller than the series length "
          + std::to_string(seriesLength)
        );
    }
    // Padding to >= N + maxLag keeps lags 0..maxLag free of circular wrap.
    while (paddedLength_ < seriesLength + maxLag)
    {
        paddedLength_ *= 2;
    }
    product_.resize(paddedLength_);
}

void PaddedFft::forward(std::vector<double>& data) const
{
    if (gsl_fft_real_radix2_transform(data.data(), 1, data.size()) != GSL_SUCCESS)
    {
        throw std::runtime_error("correlation: GSL real FFT failed");
    }
}

void PaddedFft::addLaggedSums
(
    const std::vector<double>& a,
    const std::vector<double>& b,
    std::vector<double>& sums
)
{
    const std::size_t n = paddedLength_;
    const std::size_t half = n / 2;
    // conj(A) B in GSL half-complex storage: [0] real, [k] Re_k, [n-k] Im_k.
    product_[0] = a[0] * b[0];
    product_[half] = a[half] * b[half];
    for (std::size_t k = 1; k < half; ++k)
    {
        const double ar = a[k], ai = a[n - k];
        const double br = b[k], bi = b[n - k];
        product_[k] = ar * br + ai * bi;
        product_[n - k] = ar * bi - ai * br;
    }
    if (gsl_fft_halfcomplex_radix2_inverse(product_.data(), 1, n) != GSL_SUCCESS)
    {
        throw std::runtime_error("correlation: GSL inverse FFT failed");
    }
    sums.resize(maxLag_ + 1, 0.0);
    for (std::size_t k = 0; k <= maxLag_; ++k)
    {
        sums[k] += product_[k];
    }
}

} // namespace detail


namespace
{

void requireEqualLengths(const std::vector<double>& a, const std::vector<double>& b)
{
    if (a.size() != b.size())
    {
        throw std::invalid_argument
        (
            "crossCorrelation: series lengths differ ("
          + std::to_string(a.size()) + " and " + std::to_string(b.size()) + ")"
        );
    }
}

// Divide raw lagged sums by the number of time origins N-k.
void normaliseByOrigins(std::vector<double>& sums, std::size_t seriesLength, double extraFactor)
{
    for (std::size_t k = 0; k < sums.size(); ++k)
    {
        sums[k] *= extraFactor / static_cast<double>(seriesLength - k);
    }
}

} // namespace


std::vector<double> crossCorrelation
(
    const std::vector<double>& a,
    const std::vector<double>& b,
    std::size_t maxLag
)
{
    requireEqualLengths(a, b);
    detail::PaddedFft fft(a.size(), maxLag);
    std::vector<double> spectrumA, spectrumB, sums;
    fft.spectrum([&](std::size_t t) { return a[t]; }, spectrumA);
    fft.spectrum([&](std::size_t t) { return b[t]; }, spectrumB);
    fft.addLaggedSums(spectrumA, spectrumB, sums);
    normaliseByOrigins(sums, a.size(), 1.0);
    return sums;
}

std::vector<double> autocorrelation(const std::vector<double>& a, std::size_t maxLag)
{
    detail::PaddedFft fft(a.size(), maxLag);
    std::vector<double> spectrum, sums;
    fft.spectrum([&](std::size_t t) { return a[t]; }, spectrum);
    fft.addLaggedSums(spectrum, spectrum, sums);
    normaliseByOrigins(sums, a.size(), 1.0);
    return sums;
}

std::vector<double> crossCorrelationDirect
(
    const std::vector<double>& a,
    const std::vector<double>& b,
    std::size_t maxLag
)
{
    requireEqualLengths(a, b);
    if (maxLag >= a.size())
    {
        throw std::invalid_argument("crossCorrelationDirect: maxLag >= series length");
    }
    std::vector<double> result(maxLag + 1, 0.0);
    for (std::size_t k = 0; k <= maxLag; ++k)
    {
        double sum = 0.0;
        for (std::size_t t = 0; t + k < a.size(); ++t)
        {
            sum += a[t] * b[t + k];
        }
        result[k] = sum / static_cast<double>(a.size() - k);
    }
    return result;
}

Eigen::MatrixX3d vectorAutocorrelation
(
    const VectorFrames& frames,
    std::size_t maxLag,
    std::size_t begin,
    std::size_t end
)
{
    std::vector<double> spectrum;
    const detail::FrameSums s = detail::sumOverParticles
    (
        frames, maxLag, begin, end, "vectorAutocorrelation",
        [&](detail::PaddedFft& fft, auto x, std::vector<double>& sums)
        {
            fft.spectrum(x, spectrum);
            fft.addLaggedSums(spectrum, spectrum, sums);
        }
    );
    const double perParticle = 1.0 / static_cast<double>(s.particles);
    Eigen::MatrixX3d result(maxLag + 1, 3);
    for (std::size_t k = 0; k <= maxLag; ++k)
    {
        // per time origin (N - k of them) and per particle
        result.row(k) = s.sums.row(k) * (perParticle / static_cast<double>(s.length - k));
    }
    return result;
}

Eigen::MatrixX3d vectorAutocorrelation(const VectorFrames& frames, std::size_t maxLag)
{
    return vectorAutocorrelation(frames, maxLag, 0, frames.size());
}

std::vector<Eigen::MatrixX3d> blockEstimates
(
    FrameRangeEstimator estimate,
    const VectorFrames& frames,
    std::size_t maxLag,
    std::size_t blockCount
)
{
    return forEachBlock
    (
        frames.size(),
        blockCount,
        [&](std::size_t begin, std::size_t end)
        {
            return estimate(frames, maxLag, begin, end);
        }
    );
}

std::vector<std::vector<double>> componentSeries
(
    const std::vector<Eigen::MatrixX3d>& blocks,
    int component
)
{
    if (component < -1 || component > 2)
    {
        throw std::invalid_argument
        (
            "componentSeries: component " + std::to_string(component)
          + " is not -1 (mean of x, y, z), 0, 1 or 2"
        );
    }
    std::vector<std::vector<double>> result;
    result.reserve(blocks.size());
    for (const Eigen::MatrixX3d& block : blocks)
    {
        std::vector<double> column(static_cast<std::size_t>(block.rows()));
        for (Eigen::Index k = 0; k < block.rows(); ++k)
        {
            column[k] = component < 0 ? block.row(k).mean() : block(k, component);
        }
        result.push_back(std::move(column));
    }
    return result;
}


SeriesProductCorrelations::SeriesProductCorrelations
(
    std::size_t seriesCount,
    std::size_t lagCount
)
:
    seriesCount_(seriesCount),
    lagCount_(lagCount),
    products_(seriesCount * seriesCount, std::vector<double>(lagCount, 0.0))
{}

const std::vector<double>& SeriesProductCorrelations::operator()
(
    std::size_t i,
    std::size_t j
) const
{
    if (i >= seriesCount_ || j >= seriesCount_)
    {
        throw std::out_of_range("SeriesProductCorrelations: index out of range");
    }
    return products_[i * seriesCount_ + j];
}

std::vector<double>& SeriesProductCorrelations::operator()(std::size_t i, std::size_t j)
{
    const auto& self = *this;
    return const_cast<std::vector<double>&>(self(i, j));
}

std::vector<double> SeriesProductCorrelations::total() const
{
    std::vector<double> sum(lagCount_, 0.0);
    for (const std::vector<double>& product : products_)
    {
        for (std::size_t k = 0; k < lagCount_; ++k)
        {
            sum[k] += product[k];
        }
    }
    return sum;
}

SeriesProductCorrelations seriesProductCorrelations
(
    const std::vector<std::vector<double>>& series,
    std::size_t maxLag
)
{
    if (series.empty())
    {
        throw std::invalid_argument("seriesProductCorrelations: no series");
    }
    for (const std::vector<double>& s : series)
    {
        requireEqualLengths(series.front(), s);
    }
    const std::size_t length = series.front().size();
    detail::PaddedFft fft(length, maxLag);
    std::vector<std::vector<double>> spectra(series.size());
    for (std::size_t i = 0; i < series.size(); ++i)
    {
        fft.spectrum([&](std::size_t t) { return series[i][t]; }, spectra[i]);
    }
    SeriesProductCorrelations result(series.size(), maxLag + 1);
    for (std::size_t i = 0; i < series.size(); ++i)
    {
        for (std::size_t j = 0; j < series.size(); ++j)
        {
            std::vector<double> sums(maxLag + 1, 0.0);
            fft.addLaggedSums(spectra[i], spectra[j], sums);
            normaliseByOrigins(sums, length, 1.0);
            result(i, j) = std::move(sums);
        }
    }
    return result;
}

} // namespace sdf::correlation
