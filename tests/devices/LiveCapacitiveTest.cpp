// The live capacitive readout on the simulated weights protocol, fed block
// by block: the zero taken half a second into the stream and at a tare is
// the 0.5 s running mean worked out here by hand; every displayed force and
// displacement is ΔC over the sensitivity; the settled force of each weight
// is the weight within 5 % once the simulated baseline drift is added; a stored calibration record gives the readout's
// sensitivities.
#include "core/capacitive/LiveCapacitive.h"

#include "core/SampleBlock.h"
#include "devices/simulator/CapacitiveWeightsScenario.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>

using namespace tactiscope;
using core::capacitive::CapacitiveSensitivity;
using core::capacitive::LiveCapacitive;

namespace {

struct Stream {
    std::vector<double> t, c;                // the input
    core::LiveChunk shown;                   // the display buffer's F and w
    std::optional<std::string> tareRefusal;  // what the tare answered
};

// Feeds the whole protocol in blocks of 7 samples; tares before block
// `tareBlock` when given; each capacitance as the device sends it
// (`sent`: in farads, or a board's counts).
Stream feed(
    LiveCapacitive& live, const devices::simulator::CapacitiveWeightsScenario& scenario,
    std::optional<std::size_t> tareBlock = std::nullopt,
    const std::function<double(double)>& sent = [](double c_f) { return c_f; })
{
    devices::simulator::CapacitiveWeightsScenario copy(scenario.parameters());
    const double rate = copy.sampleRate_hz();
    core::SampleBlock all(1, static_cast<std::size_t>(copy.duration_s() * rate), 0.0, 1.0 / rate);
    copy.generate(all);
    Stream run;
    for (std::size_t s = 0, b = 0; s < all.sampleCount(); s += 7, ++b) {
        const std::size_t n = std::min<std::size_t>(7, all.sampleCount() - s);
        core::SampleBlock block(1, n, all.timeAt_s(s), all.dt_s(), s);
        for (std::size_t i = 0; i < n; ++i) {
            block.channel(0)[i] = sent(all.value(0, s + i));
            run.t.push_back(all.timeAt_s(s + i));
            run.c.push_back(all.value(0, s + i));
        }
        if (tareBlock && b == *tareBlock) run.tareRefusal = live.tare();
        live.consume(block);
    }
    core::LiveCursor cursor;
    live.output()->readNew(cursor, run.shown);
    return run;
}

}  // namespace

TEST(LiveCapacitive, ZeroesHalfASecondInAndShowsDeltaCOverTheSensitivity)
{
    const devices::simulator::CapacitiveWeightsScenario scenario;
    const auto sensitivity = CapacitiveSensitivity::fromModel(scenario.beam());
    LiveCapacitive live(scenario.channels(), scenario.sampleRate_hz(), sensitivity, {}, 400.0);
    const Stream run = feed(live, scenario);
    ASSERT_EQ(run.shown.sampleCount(), run.c.size());
    // At 10 Hz, the first 0.5 s is samples 0 to 4, and steady (the beam
    // unloaded): the zero is their mean, from sample 5 on.
    double c0 = 0.0;
    for (std::size_t i = 0; i < 5; ++i) c0 += run.c[i] / 5.0;
    for (std::size_t i = 5; i < run.c.size(); ++i) {
        ASSERT_NEAR(run.shown.values[0][i], (run.c[i] - c0) / sensitivity.perNewton_f, 1e-12) << i;
        ASSERT_NEAR(run.shown.values[1][i], (run.c[i] - c0) / sensitivity.perMetre_f, 1e-12) << i;
    }
    const auto latest = live.latest();
    ASSERT_TRUE(latest.has_value());
    EXPECT_DOUBLE_EQ(latest->c0_f, c0);
    EXPECT_DOUBLE_EQ(latest->relativeChange, (run.c.back() - c0) / c0);
}

// A stream that starts while a weight is lifted off (C falls 0.3 pF at
// 0.3 s): the start's C0 waits for a steady half second, the beam
// unloaded, where a C0 taken half a second in blended the two (51.62 pF
// between 51.74 and 51.44).
TEST(LiveCapacitive, TheStartsZeroWaitsForASteadySignal)
{
    const devices::simulator::CapacitiveWeightsScenario scenario;
    const auto sensitivity = CapacitiveSensitivity::fromModel(scenario.beam());
    LiveCapacitive live(scenario.channels(), 10.0, sensitivity, {}, 400.0);
    std::mt19937_64 random(5);
    std::normal_distribution<double> noise(0.0, 1e-15);
    core::SampleBlock block(1, 30, 0.0, 0.1, 0);
    for (std::size_t i = 0; i < 30; ++i) block.channel(0)[i] = (i < 3 ? 51.74e-12 : 51.44e-12) + noise(random);
    live.consume(block);
    const auto changes = live.takeBaselineChanges();
    ASSERT_EQ(changes.size(), 1u);
    EXPECT_EQ(changes[0].firstIndex, 8u);  // samples 3 to 7 are the first steady half second
    EXPECT_NEAR(changes[0].c0_f, 51.44e-12, 3e-15);
}

TEST(LiveCapacitive, ReadsEachSettledWeightWithinFivePercentPlusTheBaselineDrift)
{
    // Drift tracking cannot act while the beam stays loaded (the cumulative
    // protocol keeps it loaded for minutes), so the simulated linear drift
    // since the zero adds to every reading: 0.5 fF/s over the sensitivity.
    const devices::simulator::CapacitiveWeightsScenario scenario;
    const auto sensitivity = CapacitiveSensitivity::fromModel(scenario.beam());
    LiveCapacitive live(scenario.channels(), scenario.sampleRate_hz(), sensitivity, {}, 400.0);
    const Stream run = feed(live, scenario);
    const double drift_n_per_s = scenario.parameters().drift_f_per_s / sensitivity.perNewton_f;
    int checked = 0;
    for (const auto& step : scenario.schedule()) {
        if (step.force_n <= 0.0) continue;
        // The step's last second: settled, creep nearly done.
        double sum = 0.0;
        int n = 0;
        for (std::size_t i = 0; i < run.t.size(); ++i) {
            if (run.t[i] >= step.end_s - 1.0 && run.t[i] < step.end_s) {
                sum += run.shown.values[0][i];
                ++n;
            }
        }
        const double expected = step.force_n + drift_n_per_s * (step.end_s - 0.5 - 0.5);
        // 5 % for creep and hysteresis, 5 µN for the baseline's random walk.
        EXPECT_NEAR(sum / n, expected, 0.05 * step.force_n + 5e-6) << step.start_s << " s";
        ++checked;
    }
    EXPECT_GE(checked, 20);
}

TEST(LiveCapacitive, TareTakesTheLastHalfSecondsMeanWhenTheSignalIsSteady)
{
    const devices::simulator::CapacitiveWeightsScenario scenario;
    ASSERT_GT(scenario.schedule().front().start_s, 8.0);  // unloaded until then
    LiveCapacitive live(scenario.channels(), scenario.sampleRate_hz(),
                        CapacitiveSensitivity::fromModel(scenario.beam()), {}, 400.0);
    const Stream run = feed(live, scenario, 10);  // before sample 70, 7 s in
    EXPECT_FALSE(run.tareRefusal.has_value()) << *run.tareRefusal;
    // At 10 Hz the last half second is samples 65 to 69.
    double c0 = 0.0;
    for (std::size_t i = 65; i < 70; ++i) c0 += run.c[i] / 5.0;
    const auto sensitivity = CapacitiveSensitivity::fromModel(scenario.beam());
    EXPECT_NEAR(run.shown.values[0][70], (run.c[70] - c0) / sensitivity.perNewton_f, 1e-9);
}

TEST(LiveCapacitive, TareIsRefusedWhileTheCapacitanceStepsAndTakenOnceItSettles)
{
    const devices::simulator::CapacitiveWeightsScenario scenario;
    const auto sensitivity = CapacitiveSensitivity::fromModel(scenario.beam());
    LiveCapacitive live(scenario.channels(), 100.0, sensitivity, {}, 10.0);
    std::uint64_t index = 0;
    // Samples at `c_pf` with ±1 fF of alternating noise, in blocks of 10.
    const auto feedAt = [&](double c_pf, std::size_t samples) {
        for (std::size_t done = 0; done < samples; done += 10) {
            core::SampleBlock block(1, 10, static_cast<double>(index) / 100.0, 0.01, index);
            for (std::size_t i = 0; i < 10; ++i)
                block.channel(0)[i] = (c_pf + ((index + i) % 2 ? 1e-3 : -1e-3)) * 1e-12;
            index += 10;
            live.consume(block);
        }
    };
    feedAt(50.0, 100);
    feedAt(51.0, 20);  // a weight goes on: the last half second holds the step
    const auto refusal = live.tare();
    ASSERT_TRUE(refusal.has_value());
    EXPECT_NE(refusal->find("changing"), std::string::npos) << *refusal;
    feedAt(51.0, 10);
    EXPECT_NEAR(live.latest()->c0_f, 50.0e-12, 2e-15);  // the start's zero stays
    feedAt(51.0, 60);                                   // settled
    EXPECT_FALSE(live.tare().has_value());
    feedAt(51.0, 10);
    EXPECT_NEAR(live.latest()->c0_f, 51.0e-12, 1e-16);  // the mean of the last half second
}

TEST(LiveCapacitive, TakesItsSensitivitiesFromAStoredCalibrationRecord)
{
    const devices::simulator::CapacitiveWeightsScenario scenario;
    core::calibration::CalibrationRecord record;
    record.kind = "capacitive";
    record.values = {{"c0_pf", 51.5}, {"baseline_sigma_pf", 0.004}, {"sensitivity_pf_per_mn", 2.0}};
    const auto stored = core::capacitive::capacitiveCalibrationOf(record, scenario.beam());
    EXPECT_DOUBLE_EQ(stored.sensitivity.c0_f, 51.5e-12);
    EXPECT_DOUBLE_EQ(stored.sensitivity.perNewton_f, 2.0e-12 / 1e-3);
    // ΔC per metre = ΔC per newton × k_s (F = k_s·w).
    EXPECT_DOUBLE_EQ(stored.sensitivity.perMetre_f, 2.0e-9 * scenario.beam().stiffness_n_per_m());
    EXPECT_DOUBLE_EQ(stored.noiseSigma_f, 0.004e-12);

    record.values = {{"c0_pf", 51.5}};
    EXPECT_THROW(core::capacitive::capacitiveCalibrationOf(record, scenario.beam()), std::invalid_argument);
    record.kind = "gauge_factor";
    EXPECT_THROW(core::capacitive::capacitiveCalibrationOf(record, scenario.beam()), std::invalid_argument);
}

TEST(LiveCapacitive, RefusesAProbeWithoutACapacitanceChannel)
{
    const devices::simulator::CapacitiveWeightsScenario scenario;
    const std::vector<core::ChannelDescriptor> channels{{"a", "", core::ChannelKind::Strain}};
    EXPECT_THROW(LiveCapacitive(channels, 10.0, CapacitiveSensitivity::fromModel(scenario.beam()), {}, 10.0),
                 std::invalid_argument);
}

// A board that prints its converter's counts (an AD7746's: 2,048,000 a
// picofarad, zero at 8,388,608) is read through its profile's scale: every
// force and deflection shown is the one the same capacitance in farads
// gives; the samples' counts themselves are not farads.
TEST(LiveCapacitive, ABoardsCountsAreReadThroughItsProfilesScaleAsTheirCapacitance)
{
    const devices::simulator::CapacitiveWeightsScenario scenario;
    const auto sensitivity = CapacitiveSensitivity::fromModel(scenario.beam());
    const double rate = scenario.sampleRate_hz();
    LiveCapacitive inFarads(scenario.channels(), rate, sensitivity, {}, 600.0);
    const std::vector<core::ChannelDescriptor> counts{
        {"c", "counts", core::ChannelKind::Other, core::ChannelRole::Capacitance}};
    const core::sensors::ChannelScales scales{{"c", {"pF", 2048000.0, std::nullopt, 8388608.0}}};
    LiveCapacitive inCounts(counts, rate, sensitivity, {}, 600.0, scales);
    const auto farads = feed(inFarads, scenario);
    const auto board = feed(inCounts, scenario, std::nullopt, [](double c_f) {
        return std::round(c_f * 1e12 * 2048000.0) + 8388608.0;  // what the converter reads
    });
    ASSERT_EQ(board.shown.sampleCount(), farads.shown.sampleCount());
    // A count is 0.49 aF: the forces agree to that over the sensitivity.
    const double countForce_n = 1e-12 / 2048000.0 / sensitivity.perNewton_f;
    for (std::size_t s = 0; s < farads.shown.sampleCount(); s += 97)
        ASSERT_NEAR(board.shown.values[0][s], farads.shown.values[0][s], 4.0 * countForce_n) << s;

    // Counts without a capacitance scale are refused, naming the channel.
    try {
        LiveCapacitive unscaled(counts, rate, sensitivity, {}, 600.0);
        ADD_FAILURE() << "counts were read as farads";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "the capacitance c is in counts and the sensor profile gives it no "
                                         "capacitance scale (\"channels\": {\"c\": {\"unit\": \"pF\", "
                                         "\"counts_per_unit\": …, \"offset\": …}})");
    }
}
