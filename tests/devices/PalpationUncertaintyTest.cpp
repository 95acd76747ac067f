// Whether the uncertainty a press reading states is honest: across many
// simulated sessions (each its own noise, its zero taken by a tare at its
// own moment while the probe is lifted), the readings scatter about the
// simulated specimen's true stiffness as their stated uncertainty says.
// The truth is the simulator's, not the code's: ±1u and ±2u must cover it
// in 68 % and 95 % of the readings within binomial limits — for each
// press's kₒ, the session's kₒ (its presses share the zero) and each press's
// slope of kₒ against depth (true slope 0) — while the noise's standard
// error alone, which leaves out the zero, covers far less.
#include "core/SampleBlock.h"
#include "core/compliance/CombinedPresses.h"
#include "core/compliance/LivePalpation.h"
#include "devices/simulator/PalpationScenario.h"
#include "support/Coverage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
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

TEST(PalpationUncertainty, TheStatedUncertaintiesCoverTheTruthAsTheySay)
{
    std::mt19937 tareMoments(5);
    tactiscope::testing::Coverage press, session, slope;
    std::size_t coveredByNoiseAlone = 0;
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
        devices::simulator::PalpationParameters p;
        p.objectStiffness_n_per_m = kTruth_n_per_m;
        p.pause_s = 2.0;  // lifted for the first 2 s: room for a tare anywhere in [1, 2) s
        p.seed = seed;
        devices::simulator::PalpationScenario scenario(p);
        core::SampleBlock all(3, static_cast<std::size_t>(16.0 * kRate_hz), 0.0, 1.0 / kRate_hz);
        scenario.generate(all);
        core::compliance::LivePalpation live(scenario.channels(), kRate_hz,
                                             {p.high, p.low, p.adc, p.bridge, {0.01, 100}, {}, {}, {}, {}, {}}, 1.0);
        // The tare's window is the half second before its own moment.
        const auto tareAt =
            static_cast<std::size_t>(std::uniform_real_distribution<double>(1.05, 1.95)(tareMoments) * kRate_hz);
        feed(live, all, 0, tareAt);
        ASSERT_FALSE(live.tare().has_value()) << "seed " << seed << ": the probe is lifted and still";
        feed(live, all, tareAt, all.sampleCount());
        const auto readings = live.takeReadings();
        for (const auto& reading : readings) {
            ASSERT_EQ(reading.status, core::compliance::PressStatus::Ok);
            ASSERT_TRUE(reading.zeroUncertainty_n_per_m.has_value());
            const double error = reading.stiffness.objectStiffness_n_per_m - kTruth_n_per_m;
            press.add(error, reading.uncertainty_n_per_m());
            if (std::abs(error) <= 2.0 * reading.standardError_n_per_m) ++coveredByNoiseAlone;
            // Nothing in the simulated specimen depends on depth: the slope's truth is 0.
            slope.add(reading.displacementSlope_n_per_m_per_m, reading.displacementSlopeStandardError);
        }
        // The session's reading: its presses share this zero.
        const auto combined = core::compliance::combinePresses(
            core::sensors::CompliancePair(core::sensors::CantileverBeam(p.high), core::sensors::CantileverBeam(p.low)),
            readings);
        ASSERT_TRUE(combined);
        session.add(combined->stiffness_n_per_m - kTruth_n_per_m, combined->uncertainty_n_per_m());
    }
    std::printf("coverage: press kₒ %s; session kₒ %s; depth slope %s\n", press.summary().c_str(),
                session.summary().c_str(), slope.summary().c_str());
    EXPECT_TRUE(press.isGaussian()) << "a press's kₒ ± u";
    EXPECT_TRUE(session.isGaussian()) << "the session's kₒ ± u";
    EXPECT_TRUE(slope.isGaussian()) << "a press's depth slope ± its standard error";
    EXPECT_LT(static_cast<double>(coveredByNoiseAlone) / static_cast<double>(press.runs()), 0.85)
        << "the zero's part matters: without it the readings scatter beyond their error";
}
