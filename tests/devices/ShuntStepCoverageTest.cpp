// The shunt check's "measured ± u" as a statistic: over 400 seeds of the
// simulated panel probe at rest (white gauge noise, 0.5 µε), one second
// with the shunt off and one with it on, the measured step's ±1u and ±2u
// cover the bridge's true step (ShuntedBridges' own, from its resistances)
// in 68.3 % and 95.4 % of the runs, within three binomial standard
// deviations (n = 400: [61.3 %, 75.3 %] and [92.3 %, 98.5 %]).
#include "core/straingauge/ShuntCalibration.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/ShuntedBridges.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace tactiscope;

TEST(ShuntStepCoverage, OneAndTwoUncertaintiesCoverTheTrueStepAsOftenAsTheyShould)
{
    constexpr int kSeeds = 400;
    const double truth = devices::simulator::shuntedReading({});
    int withinOne = 0, withinTwo = 0;
    for (int seed = 1; seed <= kSeeds; ++seed) {
        auto scenario = devices::simulator::makeScenario(devices::simulator::kPanelRestScenario,
                                                         static_cast<std::uint64_t>(seed), std::nullopt);
        devices::simulator::ShuntedBridges bridges(scenario->channels());
        const auto window = [&](bool shunted) {
            core::SampleBlock block(scenario->channels().size(), 500, 0.0, 1.0 / scenario->sampleRate_hz());
            scenario->generate(block);
            bridges.set(0, shunted);
            bridges.apply(block);
            const auto a = block.channel(0);
            return std::vector<double>(a.begin(), a.end());
        };
        const auto off = window(false);
        const auto on = window(true);
        const auto step = core::straingauge::measureShuntStep(off, on);
        ASSERT_GT(step.uncertainty, 0.0);
        const double error = std::abs(step.step - truth);
        withinOne += error <= step.uncertainty ? 1 : 0;
        withinTwo += error <= 2.0 * step.uncertainty ? 1 : 0;
    }
    const auto bounds = [](double p) {
        const double sd = std::sqrt(p * (1.0 - p) / kSeeds);
        return std::pair{p - 3.0 * sd, p + 3.0 * sd};
    };
    const auto [lowOne, highOne] = bounds(0.6827);
    const auto [lowTwo, highTwo] = bounds(0.9545);
    EXPECT_GE(withinOne / double(kSeeds), lowOne);
    EXPECT_LE(withinOne / double(kSeeds), highOne);
    EXPECT_GE(withinTwo / double(kSeeds), lowTwo);
    EXPECT_LE(withinTwo / double(kSeeds), highTwo);
}
