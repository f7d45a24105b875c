#include "correlation/MeanSquareDisplacement.hpp"
#include "correlation/detail/FrameRange.hpp"
#include "correlation/detail/PaddedFft.hpp"

#include <gsl/gsl_fit.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace sdf::correlation
{

Eigen::MatrixX3d meanSquareDisplacement
(
    const VectorFrames& frames,
    std::size_t maxLag,
    std::size_t begin,
    std::size_t end
)
{
    std::vector<double> spectrum, products, squares;
    const detail::FrameSums s = detail::sumOverParticles
    (
        frames, maxLag, begin, end, "meanSquareDisplacement",
        [&](detail::PaddedFft& fft, auto x, std::vector<double>& sums)
        {
            const std::size_t n = fft.seriesLength();
            // S2: the lagged products sum_t x(t) x(t+k).
            products.assign(maxLag + 1, 0.0);
            fft.spectrum(x, spectrum);
            fft.addLaggedSums(spectrum, spectrum, products);
            // S1: sum_{t=0}^{n-1-k} x(t)^2 + sum_{t=k}^{n-1} x(t)^2, built by
            // removing one end point per lag from the full sum.
            squares.resize(n);
            double total = 0.0;
            for (std::size_t t = 0; t < n; ++t)
            {
                squares[t] = x(t) * x(t);
                total += squares[t];
            }
            double head = total;   // sum_{t=0}^{n-1-k}
            double tail = total;   // sum_{t=k}^{n-1}
            for (std::size_t k = 0; k <= maxLag; ++k)
            {
                if (k > 0)
                {
                    head -= squares[n - k];
                    tail -= squares[k - 1];
                }
                sums[k] += head + tail - 2.0 * products[k];
            }
        }
    );
    Eigen::MatrixX3d result(maxLag + 1, 3);
    for (std::size_t k = 0; k <= maxLag; ++k)
    {
        result.row(k) = s.sums.row(k)
            / (static_cast<double>(s.length - k) * static_cast<double>(s.particles));
    }
    // Lag 0 is exactly zero; remove the FFT round-off there.
    result.row(0).setZero();
    return result;
}

Eigen::MatrixX3d meanSquareDisplacement(const VectorFrames& frames, std::size_t maxLag)
{
    return meanSquareDisplacement(frames, maxLag, 0, frames.size());
}

EinsteinFit fitEinsteinSlope
(
    const std::vector<double>& times,
    const std::vector<double>& msd,
    const EinsteinWindow& window
)
{
    const auto [fitStart, fitEnd, dimensions] = window;
    if (times.size() != msd.size())
    {
        throw std::invalid_argument("fitEinsteinSlope: times and msd differ in length");
    }
    if (dimensions < 1 || dimensions > 3)
    {
        throw std::invalid_argument("fitEinsteinSlope: dimensions must be 1, 2 or 3");
    }
    std::vector<double> t, y;
    for (std::size_t k = 0; k < times.size(); ++k)
    {
        if (times[k] >= fitStart && times[k] <= fitEnd)
        {
            t.push_back(times[k]);
            y.push_back(msd[k]);
        }
    }
    if (t.size() < 3)
    {
        throw std::invalid_argument
        (
            "fitEinsteinSlope: fewer than 3 points in the window ["
          + std::to_string(fitStart) + ", " + std::to_string(fitEnd) + "]"
        );
    }
    double intercept, slope, cov00, cov01, cov11, residualSquares;
    gsl_fit_linear
    (
        t.data(), 1, y.data(), 1, t.size(),
        &intercept, &slope, &cov00, &cov01, &cov11, &residualSquares
    );
    EinsteinFit fit;
    const double factor = 1.0 / (2.0 * dimensions);
    fit.slope = slope;
    fit.intercept = intercept;
    fit.diffusivity = factor * slope;
    fit.fitStandardError = factor * std::sqrt(cov11);
    fit.points = t.size();
    return fit;
}

EinsteinResult einsteinDiffusivity
(
    const std::vector<double>& times,
    const std::vector<std::vector<double>>& blockMsd,
    const EinsteinWindow& window
)
{
    if (blockMsd.size() < 2)
    {
        throw std::invalid_argument("einsteinDiffusivity: needs >= 2 blocks or replicas");
    }
    EinsteinResult result;
    result.meanMsd.assign(times.size(), 0.0);
    std::vector<double> perBlock;
    for (const std::vector<double>& msd : blockMsd)
    {
        if (msd.size() != times.size())
        {
            throw std::invalid_argument("einsteinDiffusivity: a block's MSD does not match the time grid");
        }
        perBlock.push_back(fitEinsteinSlope(times, msd, window).diffusivity);
        for (std::size_t k = 0; k < times.size(); ++k)
        {
            result.meanMsd[k] += msd[k] / static_cast<double>(blockMsd.size());
        }
    }
    result.diffusivity = meanAndStandardError(perBlock);
    result.blockDiffusivities = perBlock;
    result.fitOfMean = fitEinsteinSlope(times, result.meanMsd, window);
    return result;
}

} // namespace sdf::correlation
