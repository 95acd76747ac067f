// Live palpation on the simulated compliance probe, fed block by block as
// the acquisition does: the forces and Q it displays are the chain's worked
// out here by hand; its press readings equal the
// whole-record reading of the same samples and the specimen's true
// stiffness within 5 %; a gap splits the press in progress, a tare drops it.
#include "core/compliance/LivePalpation.h"

#include "core/SampleBlock.h"
#include "devices/simulator/PalpationScenario.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace tactiscope;
using core::compliance::LivePalpation;
using core::compliance::PressReading;

namespace {

constexpr double kRate_hz = 1000.0;
constexpr double kTruth_n_per_m = 117.0;

struct Recording {
    core::SampleBlock samples;
    devices::simulator::PalpationScenario scenario;
};

Recording palpate(double seconds)
{
    devices::simulator::PalpationParameters p;
    p.objectStiffness_n_per_m = kTruth_n_per_m;
    p.seed = 11;
    Recording r{core::SampleBlock(3, static_cast<std::size_t>(seconds * kRate_hz), 0.0, 1.0 / kRate_hz),
                devices::simulator::PalpationScenario(p)};
    r.scenario.generate(r.samples);
    return r;
}

core::compliance::LivePalpationSettings settingsOf(const devices::simulator::PalpationScenario& scenario)
{
    const auto& p = scenario.parameters();
    return {p.high, p.low, p.adc, p.bridge, {0.01, 100}, {}, {}, {}, {}, {}};
}

// Samples [first, first + count) as a block numbered from `index`.
core::SampleBlock slice(const core::SampleBlock& all, std::size_t first, std::size_t count, std::uint64_t index)
{
    core::SampleBlock block(3, count, all.timeAt_s(first), all.dt_s(), index);
    for (std::size_t c = 0; c < 3; ++c)
        std::copy_n(all.channel(c).begin() + static_cast<std::ptrdiff_t>(first), count, block.channel(c).begin());
    return block;
}

// Feeds [first, end) in blocks of 53 samples, numbered from `index`.
void feed(LivePalpation& live, const core::SampleBlock& all, std::size_t first, std::size_t end, std::uint64_t index)
{
    for (std::size_t s = first; s < end; s += 53) {
        const std::size_t n = std::min<std::size_t>(53, end - s);
        live.consume(slice(all, s, n, index + (s - first)));
    }
}

// The readings of the whole record at once, with the zero of its first
// 0.5 s (the procedure of PalpationScenarioTest).
std::vector<PressReading> wholeRecordReadings(const Recording& r)
{
    auto high = r.scenario.chain(), low = r.scenario.chain();
    double zeroHigh = 0.0, zeroLow = 0.0;
    for (std::size_t i = 0; i < 500; ++i) {
        zeroHigh += r.samples.value(0, i);
        zeroLow += r.samples.value(1, i);
    }
    high.tare(zeroHigh / 500.0);
    low.tare(zeroLow / 500.0);
    const core::sensors::CantileverBeam highBeam(r.scenario.parameters().high), lowBeam(r.scenario.parameters().low);
    core::compliance::PressReader reader(core::sensors::CompliancePair(highBeam, lowBeam), {0.01, 100});
    std::vector<PressReading> readings;
    for (std::size_t i = 500; i < r.samples.sampleCount(); ++i) {
        const double fHigh = high.strain(r.samples.value(0, i)) / highBeam.rootStrainPerNewton();
        const double fLow = low.strain(r.samples.value(1, i)) / lowBeam.rootStrainPerNewton();
        if (auto reading = reader.push(r.samples.timeAt_s(i), r.samples.value(2, i), fHigh, fLow))
            readings.push_back(*reading);
    }
    return readings;
}

// The force of a beam's raw value on a zero, by the chain worked out here.
double forceOf(const Recording& r, bool highBeam, double zero, double raw)
{
    auto chain = r.scenario.chain();
    chain.tare(zero);
    const core::sensors::CantileverBeam beam(highBeam ? r.scenario.parameters().high : r.scenario.parameters().low);
    return chain.strain(raw) / beam.rootStrainPerNewton();
}

}  // namespace

TEST(LivePalpation, ReadsEachPressAsTheWholeRecordDoesAndWithinFivePercentOfTheTruth)
{
    const Recording r = palpate(18.0);
    LivePalpation live(r.scenario.channels(), kRate_hz, settingsOf(r.scenario), 20.0);
    feed(live, r.samples, 0, r.samples.sampleCount(), 0);
    const auto readings = live.takeReadings();
    const auto expected = wholeRecordReadings(r);
    ASSERT_GE(readings.size(), 4u);
    ASSERT_EQ(readings.size(), expected.size());
    for (std::size_t i = 0; i < readings.size(); ++i) {
        EXPECT_DOUBLE_EQ(readings[i].start_s, expected[i].start_s);
        EXPECT_NEAR(readings[i].stiffness.objectStiffness_n_per_m, expected[i].stiffness.objectStiffness_n_per_m,
                    1e-9 * kTruth_n_per_m);
        EXPECT_NEAR(readings[i].stiffness.objectStiffness_n_per_m, kTruth_n_per_m, 0.05 * kTruth_n_per_m);
        EXPECT_GT(readings[i].standardError_n_per_m, 0.0);
    }
    EXPECT_TRUE(live.takeReadings().empty());  // taken once
}

TEST(LivePalpation, ACalibratedGaugeFactorScalesItsBeamsForcesOnly)
{
    // Counts → strain divides by the gauge factor (x = GF·ε; the half
    // bridge is linear in x): a stiff beam calibrated at 2.14 instead of the
    // nominal 2.0 reads 2.0/2.14 of the nominal force; the soft beam keeps its.
    const Recording r = palpate(3.0);
    auto settings = settingsOf(r.scenario);
    LivePalpation nominal(r.scenario.channels(), kRate_hz, settings, 5.0);
    settings.highGaugeFactor = 2.14;
    LivePalpation calibrated(r.scenario.channels(), kRate_hz, settings, 5.0);
    EXPECT_EQ(calibrated.gaugeFactor(true), 2.14);
    EXPECT_EQ(calibrated.gaugeFactor(false), 2.0);
    feed(nominal, r.samples, 0, r.samples.sampleCount(), 0);
    feed(calibrated, r.samples, 0, r.samples.sampleCount(), 0);
    core::LiveCursor a, b;
    core::LiveChunk n, c;
    nominal.output()->readNew(a, n);
    calibrated.output()->readNew(b, c);
    std::size_t compared = 0;
    for (std::size_t i = 500; i < n.sampleCount(); ++i) {
        ASSERT_NEAR(c.values[0][i], n.values[0][i] * 2.0 / 2.14, 1e-12) << i;
        ASSERT_EQ(c.values[1][i], n.values[1][i]) << i;
        ++compared;
    }
    EXPECT_GT(compared, 2000u);
}

TEST(LivePalpation, DisplaysTheForcesAndQOfEachSample)
{
    const Recording r = palpate(6.0);
    LivePalpation live(r.scenario.channels(), kRate_hz, settingsOf(r.scenario), 10.0);
    feed(live, r.samples, 0, r.samples.sampleCount(), 0);
    core::LiveCursor cursor;
    core::LiveChunk chunk;
    ASSERT_EQ(live.output()->readNew(cursor, chunk), r.samples.sampleCount());
    // The zero is being taken: nothing to show yet.
    EXPECT_TRUE(std::isnan(chunk.values[0][499]));

    // By hand: counts → bridge volts → half-bridge strain → force.
    const auto& p = r.scenario.parameters();
    const double voltsPerCount = p.adc.reference_v / std::pow(2.0, p.adc.bits - 1) / p.adc.gain;
    const auto mean = [&](std::size_t c) {
        double sum = 0.0;
        for (std::size_t i = 0; i < 500; ++i) sum += r.samples.value(c, i);
        return sum / 500.0;
    };
    const double zeroHigh = mean(0), zeroLow = mean(1);
    const core::sensors::CantileverBeam high(p.high), low(p.low);
    const auto force = [&](double counts, double zero, const core::sensors::CantileverBeam& beam) {
        const double ratio = (counts - zero) * voltsPerCount / p.bridge.excitation_v;
        return 2.0 * ratio / p.bridge.gaugeFactor / beam.rootStrainPerNewton();
    };
    std::size_t pressed = 0;
    for (std::size_t i = 500; i < r.samples.sampleCount(); ++i) {
        const double fh = force(r.samples.value(0, i), zeroHigh, high);
        const double fl = force(r.samples.value(1, i), zeroLow, low);
        ASSERT_NEAR(chunk.values[0][i], fh, 1e-9) << i;
        ASSERT_NEAR(chunk.values[1][i], fl, 1e-9) << i;
        if (fh > 0.01 && fl > 0.01) {
            ASSERT_NEAR(chunk.values[2][i], fh / fl, 1e-9 * fh / fl) << i;
            ++pressed;
        } else {
            ASSERT_TRUE(std::isnan(chunk.values[2][i])) << i;
        }
    }
    EXPECT_GT(pressed, 1000u);  // the first press is in these 6 s
}

TEST(LivePalpation, AGapSplitsThePressInProgressAndATareIsRefusedWhilePressing)
{
    const Recording r = palpate(18.0);
    const auto expected = wholeRecordReadings(r);
    ASSERT_GE(expected.size(), 3u);
    // A moment in the middle of the second press.
    const auto middle = static_cast<std::size_t>((expected[1].start_s + expected[1].end_s) / 2.0 * kRate_hz);

    // A gap there: no reading spans it; the part of the press after the gap
    // is read on its own, and the other presses are read unchanged.
    LivePalpation gapped(r.scenario.channels(), kRate_hz, settingsOf(r.scenario), 20.0);
    feed(gapped, r.samples, 0, middle, 0);
    feed(gapped, r.samples, middle, r.samples.sampleCount(), middle + 50);
    auto readings = gapped.takeReadings();
    ASSERT_EQ(readings.size(), expected.size());
    EXPECT_DOUBLE_EQ(readings[0].start_s, expected[0].start_s);
    EXPECT_DOUBLE_EQ(readings[1].start_s, r.samples.timeAt_s(middle));
    EXPECT_DOUBLE_EQ(readings[1].end_s, expected[1].end_s);
    EXPECT_NEAR(readings[1].stiffness.objectStiffness_n_per_m, kTruth_n_per_m, 0.05 * kTruth_n_per_m);
    EXPECT_DOUBLE_EQ(readings[2].start_s, expected[2].start_s);

    // A tare there is refused (the probe is pressing) and changes nothing.
    LivePalpation tared(r.scenario.channels(), kRate_hz, settingsOf(r.scenario), 20.0);
    feed(tared, r.samples, 0, middle, 0);
    const auto refusal = tared.tare();
    ASSERT_TRUE(refusal.has_value());
    EXPECT_NE(refusal->find("pressing"), std::string::npos) << *refusal;
    feed(tared, r.samples, middle, r.samples.sampleCount(), middle);
    readings = tared.takeReadings();
    ASSERT_EQ(readings.size(), expected.size());
    EXPECT_DOUBLE_EQ(readings[1].start_s, expected[1].start_s);
    EXPECT_DOUBLE_EQ(readings[1].stiffness.objectStiffness_n_per_m, expected[1].stiffness.objectStiffness_n_per_m);

    // Between presses, lifted and still, it is taken at once from the last
    // half second, and the next press reads the same stiffness.
    const auto lifted = static_cast<std::size_t>((expected[1].end_s + expected[2].start_s) / 2.0 * kRate_hz);
    LivePalpation between(r.scenario.channels(), kRate_hz, settingsOf(r.scenario), 20.0);
    feed(between, r.samples, 0, lifted, 0);
    const auto accepted = between.tare();
    EXPECT_FALSE(accepted.has_value()) << *accepted;
    feed(between, r.samples, lifted, r.samples.sampleCount(), lifted);
    EXPECT_FALSE(between.state().taring);
    readings = between.takeReadings();
    ASSERT_EQ(readings.size(), expected.size());
    EXPECT_NEAR(readings[2].stiffness.objectStiffness_n_per_m, expected[2].stiffness.objectStiffness_n_per_m,
                0.02 * expected[2].stiffness.objectStiffness_n_per_m);
}

TEST(LivePalpation, RefusesAProbeWithoutADisplacementChannel)
{
    const std::vector<core::ChannelDescriptor> channels{{"high", "count", core::ChannelKind::Other},
                                                        {"low", "count", core::ChannelKind::Other}};
    const auto settings = settingsOf(devices::simulator::PalpationScenario());
    EXPECT_THROW(LivePalpation(channels, kRate_hz, settings, 10.0), std::invalid_argument);
}

// Another profile chosen while the probe presses rebuilds the processor:
// it goes on from the zero taken lifted and reads every later press as
// the first processor does; one that took its own first zero there would
// have zeroed the load (the fault this rule removes).
TEST(LivePalpation, AProcessorRebuiltWhilePressingKeepsTheZeroTakenLifted)
{
    const Recording r = palpate(18.0);
    const auto expected = wholeRecordReadings(r);
    ASSERT_GE(expected.size(), 3u);
    const auto middle = static_cast<std::size_t>((expected[1].start_s + expected[1].end_s) / 2.0 * kRate_hz);

    LivePalpation first(r.scenario.channels(), kRate_hz, settingsOf(r.scenario), 20.0);
    feed(first, r.samples, 0, middle, 0);
    ASSERT_TRUE(first.state().pressing);
    const auto before = first.takeReadings();
    ASSERT_EQ(before.size(), 1u);

    LivePalpation rebuilt(r.scenario.channels(), kRate_hz, settingsOf(r.scenario), 20.0);
    rebuilt.inheritZero(first);
    EXPECT_FALSE(rebuilt.state().taring);
    ASSERT_TRUE(rebuilt.currentZero());
    EXPECT_EQ(rebuilt.currentZero()->firstIndex, first.currentZero()->firstIndex);
    EXPECT_TRUE(rebuilt.takeZeroChanges().empty());  // no new zero to record
    feed(rebuilt, r.samples, middle, r.samples.sampleCount(), middle);
    const auto after = rebuilt.takeReadings();
    // The press cut by the rebuild is read from the rebuild on; the ones
    // after it exactly as the whole record reads them.
    ASSERT_EQ(after.size(), expected.size() - 1);
    for (std::size_t i = 1; i < after.size(); ++i) {
        EXPECT_DOUBLE_EQ(after[i].start_s, expected[i + 1].start_s) << i;
        EXPECT_NEAR(after[i].stiffness.objectStiffness_n_per_m, expected[i + 1].stiffness.objectStiffness_n_per_m,
                    1e-9 * kTruth_n_per_m)
            << i;
    }
}

// A stream that starts anywhere in a press (a ramp, the hold, the way
// out): its first zero is never the pressed beams'. One taken in motion
// waits for a steady half second; one taken in a hold held still is
// found out once the probe lifts (both forces then hold below zero, which
// no press does) and taken again there. Before, a zero taken half a second
// into the press read the stiff beam 1708 counts high and missed presses.
TEST(LivePalpation, AStreamThatStartsInAPressTakesItsZeroLifted)
{
    const Recording r = palpate(14.0);
    const auto expected = wholeRecordReadings(r);
    ASSERT_GE(expected.size(), 4u);
    LivePalpation lifted(r.scenario.channels(), kRate_hz, settingsOf(r.scenario), 20.0);
    feed(lifted, r.samples, 0, r.samples.sampleCount(), 0);
    const auto zero = lifted.currentZero()->zero;
    std::size_t zeroedAgain = 0;
    for (double start_s = expected[1].start_s - 0.05; start_s < expected[1].end_s; start_s += 0.05) {
        const auto first = static_cast<std::size_t>(start_s * kRate_hz);
        LivePalpation fresh(r.scenario.channels(), kRate_hz, settingsOf(r.scenario), 20.0);
        feed(fresh, r.samples, first, r.samples.sampleCount(), first);
        ASSERT_TRUE(fresh.currentZero()) << start_s;
        // A first zero taken in the press's hold is taken again once the
        // probe lifts, and that one says why (the record keeps it); the
        // first says nothing.
        const auto zeros = fresh.takeZeroChanges();
        ASSERT_FALSE(zeros.empty());
        EXPECT_TRUE(zeros.front().note.empty()) << zeros.front().note;
        for (std::size_t z = 1; z < zeros.size(); ++z) {
            EXPECT_TRUE(zeros[z].note.starts_with("the forces held at F_H -")) << zeros[z].note;
            EXPECT_TRUE(zeros[z].note.ends_with("zeroed again here")) << zeros[z].note;
            EXPECT_NEAR(zeros[z].time_s, static_cast<double>(zeros[z].firstIndex) / kRate_hz, 1e-9);
        }
        if (zeros.size() > 1) ++zeroedAgain;
        // Within the contact threshold of the lifted zero (the tare rule's
        // own bound on a steady probe), in each beam's force.
        EXPECT_LE(std::abs(forceOf(r, true, zero.high, fresh.currentZero()->zero.high)), 0.01) << start_s;
        EXPECT_LE(std::abs(forceOf(r, false, zero.low, fresh.currentZero()->zero.low)), 0.01) << start_s;
        // Every press after the next pause is read, as the whole record
        // reads it (its start, where a force crosses the threshold, moves
        // with the zero a little).
        const auto readings = fresh.takeReadings();
        for (std::size_t i = 2; i < expected.size(); ++i) {
            const auto same = std::ranges::find_if(
                readings, [&](const PressReading& p) { return std::abs(p.start_s - expected[i].start_s) < 0.1; });
            ASSERT_NE(same, readings.end()) << start_s << " press " << i;
            EXPECT_NEAR(same->stiffness.objectStiffness_n_per_m, expected[i].stiffness.objectStiffness_n_per_m,
                        0.01 * kTruth_n_per_m);
        }
    }
    EXPECT_GE(zeroedAgain, 1u) << "no start fell in the press's hold: the re-zero was not tried";
}
