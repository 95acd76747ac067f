// Whether the uncertainty a press reading states is honest: across many
// simulated sessions (each its own noise, its zero taken by a tare at its
// own moment while the probe is lifted), the readings scatter about the
// simulated specimen's true stiffness as their stated uncertainty says.
// The truth is the simulator's, not the code's: coverage of ±2u must lie
// between 90 % and 99 % (95 % for a Gaussian), while the noise's standard
// error alone — which leaves out the zero — covers far less.
#include "core/SampleBlock.h"
#include "core/compliance/LivePalpation.h"
#include "devices/simulator/PalpationScenario.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace tactiscope;

namespace {

constexpr double kRate_hz = 1000.0;
constexpr double kTruth_n_per_m = 117.0;

// Feeds `all` from sample `first` up to `end` in blocks of 100.
void feed(core::compliance::LivePalpation& live, const core::SampleBlock& all, std::size_t first, std::size_t end)
{
    for (std::size_t s = first; s < end; s += 100) {
        const std::size_t n = std::min<std::size_t>(100, end - s);
        core::SampleBlock block(3, n, all.timeAt_s(s), all.dt_s(), s);
        for (std::size_t c = 0; c < 3; ++c)
            std::copy_n(all.channel(c).begin() + static_cast<std::ptrdiff_t>(s), n, block.channel(c).begin());
        live.consume(block);
    }
}

}  // namespace

TEST(PalpationUncertainty, TheStatedUncertaintyCoversTheScatterAboutTheTruth)
{
    std::mt19937 tareMoments(5);
    std::size_t readings = 0, covered = 0, coveredByNoiseAlone = 0;
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
        devices::simulator::PalpationParameters p;
        p.objectStiffness_n_per_m = kTruth_n_per_m;
        p.pause_s = 2.0;  // lifted for the first 2 s: room for a tare anywhere in [1, 2) s
        p.seed = seed;
        devices::simulator::PalpationScenario scenario(p);
        core::SampleBlock all(3, static_cast<std::size_t>(16.0 * kRate_hz), 0.0, 1.0 / kRate_hz);
        scenario.generate(all);
        core::compliance::LivePalpation live(scenario.channels(), kRate_hz,
                                             {p.high, p.low, p.adc, p.bridge, {0.01, 100}, {}, {}}, 1.0);
        // The tare's window is the half second before its own moment.
        const auto tareAt =
            static_cast<std::size_t>(std::uniform_real_distribution<double>(1.05, 1.95)(tareMoments) * kRate_hz);
        feed(live, all, 0, tareAt);
        ASSERT_FALSE(live.tare().has_value()) << "seed " << seed << ": the probe is lifted and still";
        feed(live, all, tareAt, all.sampleCount());
        for (const auto& press : live.takeReadings()) {
            ASSERT_EQ(press.stiffness.range, core::sensors::ComplianceRange::InRange);
            ASSERT_TRUE(press.zeroUncertainty_n_per_m.has_value());
            const double error = std::abs(press.stiffness.objectStiffness_n_per_m - kTruth_n_per_m);
            ++readings;
            if (error <= 2.0 * press.uncertainty_n_per_m()) ++covered;
            if (error <= 2.0 * press.standardError_n_per_m) ++coveredByNoiseAlone;
        }
    }
    ASSERT_GE(readings, 80u);
    const double coverage = static_cast<double>(covered) / static_cast<double>(readings);
    EXPECT_GE(coverage, 0.90) << covered << " of " << readings;
    EXPECT_LE(coverage, 0.99) << covered << " of " << readings << ": the uncertainty is overstated";
    EXPECT_LT(static_cast<double>(coveredByNoiseAlone) / static_cast<double>(readings), 0.85)
        << "the zero's part matters: without it the readings scatter beyond their error";
}
