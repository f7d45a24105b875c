// Green-Kubo = MSD over a small envelope of driven DEM cells, judged as the
// calibration's envelopes are (benchmarks/demDriving/run gkMsd, docs/validation.md):
// z = (D_GK - D_MSD)/sigma per cell, sigma the cell's error of the difference (paired
// over its blocks), and over the cells (1) chi2 inside its 99 % interval, (2) mean z
// within 3 of its standard errors, (3) no cell beyond the multiplicity-corrected
// threshold. The cells are the seed's binary mixture (1 and 2 mm glass, linear
// contacts kn 2e3 N/m, e 0.9, mu 0.3) under the stochastic driving, small and short
// (N 150, 0.8 s: about 15 s of CPU each) at phi 0.5 and T 0.02, where the VACF
// decays within a block (at phi 0.35 and T 0.02 the plateau needs longer blocks, and
// a cell without one reads Green-Kubo before the tail by construction). The fines
// only: 150 particles hold 5-12 coarse ones, too few for their block errors. The same
// envelope with Green-Kubo 5 % high must fail.
#include "CellRun.hpp"
#include "TestCells.hpp"

#include "correlation/Statistics.hpp"

#include <gtest/gtest.h>

#include <iostream>

using namespace sdf::dem;
using sdf::correlation::AgreementOverCells;
using sdf::correlation::agreementOverCells;

namespace
{

CellRunSettings cell(double phi, double coarseShare, std::uint64_t seed)
{
    CellRunSettings s;
    s.species = test::binary();
    s.volumeFractions = {1 - coarseShare, coarseShare};
    s.particles = 150;
    s.solidsFraction = phi;
    s.simulation = test::softContacts(0.9, 0.3);
    s.simulation.mode = CellMode::stochastic;
    s.simulation.targetTemperature = 0.02;
    s.simulation.thermostatTime = 0.02;
    s.simulation.threads = 1;
    s.equilibrationTime = 0.05;
    s.maxEquilibrationTime = 0.1;
    s.samplingTime = 0.8;
    s.sampleEvery = 10;
    s.blocks = 8;
    s.seed = seed;
    return s;
}

struct Difference
{
    std::string name;
    double gk, difference, sigma;
};

} // namespace


TEST(GreenKuboMsdEnvelope, DenseHotCellsAgreeAndABiasedGreenKuboFails)
{
    std::vector<Difference> cells;
    for (const double x : {0.2, 0.4})
    {
        for (const std::uint64_t seed : {1, 2, 3})
        {
            const CellRunResult r = runCell(cell(0.5, x, seed));
            const SpeciesTransport& st = r.species.at(0);
            const auto& d = st.diffusiveRegime.greenKuboMinusMsd;
            ASSERT_GT(d.standardError, 0);
            const std::string name = "x " + std::to_string(x) + " seed " + std::to_string(seed);
            std::cout << name << ": D_GK " << st.greenKubo.integral.value << " D_MSD "
                      << st.diffusivityMsd.value << " z " << d.value/d.standardError << " ("
                      << st.diffusiveRegime.verdict() << ")\n";
            cells.push_back({name, st.greenKubo.integral.value, d.value, d.standardError});
        }
    }
    const auto zOf = [&](double gkFactor)
    {
        std::vector<double> z;
        for (const Difference& c : cells)
        {
            z.push_back((c.difference + (gkFactor - 1)*c.gk)/c.sigma);
        }
        return z;
    };
    const AgreementOverCells a = agreementOverCells(zOf(1.0));
    std::cout << "Green-Kubo - MSD: " << a.summary() << '\n';
    EXPECT_TRUE(a.chiSquareInside()) << a.summary();
    EXPECT_TRUE(a.meanWithin()) << a.summary();
    EXPECT_TRUE(a.flagged.empty()) << a.summary();

    // the envelope can tell: Green-Kubo 5 % high fails (on items 1 and 3: with six
    // cells the mean's own error is wide, +2.0 +- 0.7 at 5 %)
    const AgreementOverCells biased = agreementOverCells(zOf(1.05));
    std::cout << "Green-Kubo +5 %:  " << biased.summary() << '\n';
    EXPECT_FALSE(biased.passes()) << biased.summary();
}
