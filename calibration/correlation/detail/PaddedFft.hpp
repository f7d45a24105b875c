// Internal: raw lagged sums r(k) = sum_t a(t) b(t+k) by zero-padded radix-2
// real FFTs (GSL), reusing one workspace for many series of equal length.
#ifndef sdf_correlation_detail_PaddedFft_hpp
#define sdf_correlation_detail_PaddedFft_hpp

#include <cstddef>
#include <vector>

namespace sdf::correlation::detail
{

class PaddedFft
{
public:
    //- Series of seriesLength samples, lags 0 .. maxLag (maxLag < seriesLength).
    PaddedFft(std::size_t seriesLength, std::size_t maxLag);

    std::size_t seriesLength() const { return seriesLength_; }
    std::size_t maxLag() const { return maxLag_; }

    //- Half-complex spectrum of a series given through a strided accessor:
    //  value(t) for t = 0 .. seriesLength-1.
    template<class Accessor>
    const std::vector<double>& spectrum(Accessor value, std::vector<double>& out) const
    {
        out.assign(paddedLength_, 0.0);
        for (std::size_t t = 0; t < seriesLength_; ++t)
        {
            out[t] = value(t);
        }
        forward(out);
        return out;
    }

    //- Adds r(k) = sum_t a(t) b(t+k), k = 0 .. maxLag, to sums, from the
    //  spectra of a and b (b may be the same object as a).
    void addLaggedSums
    (
        const std::vector<double>& spectrumA,
        const std::vector<double>& spectrumB,
        std::vector<double>& sums
    );

private:
    void forward(std::vector<double>& data) const;

    std::size_t seriesLength_;
    std::size_t maxLag_;
    std::size_t paddedLength_;
    std::vector<double> product_;
};

} // namespace sdf::correlation::detail

#endif
