// The live signal chain against re-analysis: whatever blocks the samples
// came in, whenever a recording's restart was heard of (before its sample,
// within its block, or after, re-run from what was kept), and across lost
// samples, the chain's outputs from the restart on are bit for bit what
// chainSeries() computes from the samples as stored (binary32) from there.
// The expected series are computed from the stored-precision samples alone.
#include "core/signal/SignalChain.h"
#include "core/SampleBlock.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>
#include <random>

using namespace tactiscope;
using core::signal::SignalSetup;

namespace {

constexpr double kRate_hz = 1000.0;

std::vector<core::ChannelDescriptor> gauges()
{
    return {{"a", "", core::ChannelKind::Strain}, {"b", "", core::ChannelKind::Strain}};
}

SignalSetup notchedSetup()
{
    SignalSetup setup;
    core::dsp::FilterSettings notch;
    notch.notch_hz = 50.0;
    notch.lowpass_hz = 40.0;
    setup.filters = {{"a", notch}};
    setup.math = {core::math::parseMathDefinition("diff[µε]=a - b")};
    return setup;
}

// Strain with hum and noise, at full double precision (the chain rounds).
std::vector<std::vector<double>> samples(std::size_t n, unsigned seed)
{
    std::mt19937 random(seed);
    std::normal_distribution<double> noise(0.0, 1e-6);
    std::vector<std::vector<double>> values(2, std::vector<double>(n));
    for (std::size_t i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) / kRate_hz;
        const double hum = 1e-4 * std::sin(2.0 * std::numbers::pi * 50.0 * t);
        values[0][i] = 1e-4 * std::sin(2.0 * std::numbers::pi * 2.0 * t) + hum + noise(random);
        values[1][i] = 3e-5 + hum + noise(random);
    }
    return values;
}

// Feeds [from, to) of `values` in blocks of `block` samples, device index = position.
void feed(core::signal::SignalChain& chain, const std::vector<std::vector<double>>& values, std::size_t from,
          std::size_t to, std::size_t block)
{
    for (std::size_t first = from; first < to; first += block) {
        const std::size_t n = std::min(block, to - first);
        core::SampleBlock b(2, n, static_cast<double>(first) / kRate_hz, 1.0 / kRate_hz, first);
        for (std::size_t c = 0; c < 2; ++c)
            std::copy_n(values[c].begin() + static_cast<std::ptrdiff_t>(first), n, b.channel(c).begin());
        chain.consume(b);
    }
}

std::vector<std::vector<double>> allOutputs(const core::signal::SignalChain& chain)
{
    core::LiveCursor cursor;
    core::LiveChunk chunk;
    chain.output()->readNew(cursor, chunk);
    return chunk.values;
}

// The stored samples from `first` on: binary32, NaN where lost.
std::vector<std::vector<double>> stored(const std::vector<std::vector<double>>& values, std::size_t first)
{
    std::vector<std::vector<double>> out(values.size());
    for (std::size_t c = 0; c < values.size(); ++c)
        for (std::size_t i = first; i < values[c].size(); ++i)
            out[c].push_back(static_cast<double>(static_cast<float>(values[c][i])));
    return out;
}

void expectBitwiseEqual(const std::vector<double>& live, std::size_t from, const std::vector<double>& again)
{
    ASSERT_EQ(live.size() - from, again.size());
    for (std::size_t i = 0; i < again.size(); ++i) {
        const double x = live[from + i], y = again[i];
        ASSERT_TRUE((std::isnan(x) && std::isnan(y)) || std::memcmp(&x, &y, sizeof x) == 0)
            << "sample " << i << ": live " << x << ", re-analysis " << y;
    }
}

}  // namespace

TEST(SignalChain, ARecordingsBeginningHeardOfBeforeWithinOrAfterItsSampleGivesTheReanalysedSeriesBitForBit)
{
    const auto values = samples(4000, 7);
    const std::size_t first = 1234;  // the recording's first sample, within a block of 100
    for (const std::size_t heardAt : {std::size_t{1000}, std::size_t{1200}, std::size_t{2500}}) {
        core::signal::SignalChain chain(notchedSetup(), gauges(), kRate_hz, 8000, 5.0);
        std::optional<core::signal::SignalChain::StartState> found;
        feed(chain, values, 0, heardAt, 100);
        chain.recordingBegins(first, [&](core::signal::SignalChain::StartState states) { found = states; });
        feed(chain, values, heardAt, values[0].size(), 100);
        ASSERT_TRUE(found) << heardAt;
        const auto live = allOutputs(chain);
        SignalSetup recorded = notchedSetup();
        recorded.startState = *found;
        // Through its JSON, as a session keeps it.
        recorded = core::signal::signalSetupFromJson(core::signal::signalSetupJson(recorded));
        const auto again = core::signal::chainSeries(recorded, gauges(), kRate_hz, stored(values, first));
        for (std::size_t o = 0; o < live.size(); ++o) expectBitwiseEqual(live[o], first, again[o]);
    }
}

// A moving average starts afresh at the recording's first sample, as in
// re-analysis; heard of late, what the chain put out before it heard stays
// as it was put out, and from then on the series is re-analysis's.
TEST(SignalChain, AMovingAverageStartsAfreshAtTheRecordingAndMatchesFromWhenItWasHeardOf)
{
    const auto values = samples(4000, 5);
    SignalSetup averaged = notchedSetup();
    averaged.filters[0].settings.movingAverage_s = 0.02;
    for (const std::size_t heardAt : {std::size_t{1000}, std::size_t{2500}}) {
        core::signal::SignalChain chain(averaged, gauges(), kRate_hz, 8000, 5.0);
        std::optional<core::signal::SignalChain::StartState> found;
        feed(chain, values, 0, heardAt, 100);
        chain.recordingBegins(1234, [&](core::signal::SignalChain::StartState states) { found = states; });
        feed(chain, values, heardAt, values[0].size(), 100);
        ASSERT_TRUE(found);
        SignalSetup recorded = averaged;
        recorded.startState = *found;
        const auto live = allOutputs(chain);
        const auto again = core::signal::chainSeries(recorded, gauges(), kRate_hz, stored(values, 1234));
        const std::size_t from = std::max<std::size_t>(1234, heardAt);
        expectBitwiseEqual(
            live[0], from,
            std::vector<double>(again[0].begin() + static_cast<std::ptrdiff_t>(from - 1234), again[0].end()));
    }
}

// The filters run on through the record press: the live series has no
// step or ringing there, where a restart from the first sample's steady
// state rings at the hum's amplitude for a few tenths of a second.
TEST(SignalChain, NothingRingsAtARecordingsBeginning)
{
    const auto values = samples(4000, 9);
    core::signal::SignalChain going(notchedSetup(), gauges(), kRate_hz, 8000, 5.0);
    core::signal::SignalChain untouched(notchedSetup(), gauges(), kRate_hz, 8000, 5.0);
    going.recordingBegins(2000, [](core::signal::SignalChain::StartState) {});
    feed(going, values, 0, values[0].size(), 100);
    feed(untouched, values, 0, values[0].size(), 100);
    const auto a = allOutputs(going), b = allOutputs(untouched);
    for (std::size_t o = 0; o < a.size(); ++o) expectBitwiseEqual(a[o], 0, b[o]);
}

TEST(SignalChain, LostSamplesAreMissingAndTheFiltersStartAgainAfterThemAsOnAStoredGap)
{
    auto values = samples(3000, 11);
    core::signal::SignalChain chain(notchedSetup(), gauges(), kRate_hz, 8000, 5.0);
    feed(chain, values, 0, 1000, 50);
    feed(chain, values, 1300, 3000, 50);  // 300 lost
    // The live output holds the samples that came; re-analysis sees a stored gap of NaN.
    for (std::size_t c = 0; c < 2; ++c) std::fill(values[c].begin() + 1000, values[c].begin() + 1300, std::nan(""));
    const auto again = core::signal::chainSeries(notchedSetup(), gauges(), kRate_hz, stored(values, 0));
    const auto live = allOutputs(chain);
    for (std::size_t o = 0; o < live.size(); ++o) {
        std::vector<double> cameAgain(again[o].begin(), again[o].begin() + 1000);
        cameAgain.insert(cameAgain.end(), again[o].begin() + 1300, again[o].end());
        expectBitwiseEqual(live[o], 0, cameAgain);
    }
}

TEST(SignalChain, TheFilteredChannelKeepsItsUnitAndTheMathChannelItsOwn)
{
    const core::signal::SignalChain chain(notchedSetup(), gauges(), kRate_hz, 100);
    ASSERT_EQ(chain.outputs().size(), 2u);
    EXPECT_EQ(chain.outputs()[0].name, "a.filtered");
    EXPECT_EQ(chain.outputs()[0].kind, core::ChannelKind::Strain);
    EXPECT_EQ(chain.outputs()[1].name, "diff");
    EXPECT_EQ(chain.outputs()[1].unit, "µε");
    EXPECT_GT(chain.delay_s(0), 0.0);
    EXPECT_EQ(chain.delay_s(1), 0.0);
}

TEST(SignalChain, ASetupTheChannelsOrTheRateCannotRunIsRefusedInWords)
{
    SignalSetup setup = notchedSetup();
    setup.filters[0].channel = "c";
    EXPECT_THROW(core::signal::SignalChain(setup, gauges(), kRate_hz, 100), std::invalid_argument);
    setup = notchedSetup();
    setup.filters[0].settings.zeroPhase = true;
    EXPECT_THROW(core::signal::SignalChain(setup, gauges(), kRate_hz, 100), std::invalid_argument);
    setup = notchedSetup();
    setup.math = {core::math::parseMathDefinition("bad[mN]=a + 1")};
    EXPECT_THROW(core::signal::SignalChain(setup, gauges(), kRate_hz, 100), core::math::MathError);
}

TEST(SignalSetup, ItsJsonGivesItBack)
{
    SignalSetup setup = notchedSetup();
    setup.analysisFiltered = true;
    const auto back = core::signal::signalSetupFromJson(core::signal::signalSetupJson(setup));
    EXPECT_EQ(back.filters, setup.filters);
    ASSERT_EQ(back.math.size(), 1u);
    EXPECT_EQ(back.math[0].text(), "diff[µε]=a - b");
    EXPECT_TRUE(back.analysisFiltered);
    EXPECT_EQ(core::signal::signalSetupJson({}), "");
    EXPECT_TRUE(core::signal::signalSetupFromJson("").empty());
    EXPECT_THROW(core::signal::signalSetupFromJson(R"({"filters": [{"channel": "a", "order": 9}]})"),
                 std::invalid_argument);
    EXPECT_TRUE(core::signal::signalSetupText("{").starts_with("unreadable: "));
}

TEST(SignalChain, ItsDisplayIsEveryChannelAsTheTracesShowItAndItsMathAlone)
{
    const auto values = samples(500, 3);
    core::signal::SignalChain chain(notchedSetup(), gauges(), kRate_hz, 1000, 0.0, 1000);
    feed(chain, values, 0, 500, 50);
    core::LiveCursor cursor, mathCursor;
    core::LiveChunk shown, math;
    chain.display()->readNew(cursor, shown);
    chain.mathOutput()->readNew(mathCursor, math);
    const auto outputs = allOutputs(chain);
    ASSERT_EQ(shown.values.size(), 2u);
    ASSERT_EQ(math.values.size(), 1u);
    ASSERT_EQ(chain.mathOutputs().size(), 1u);
    EXPECT_EQ(chain.mathOutputs()[0].name, "diff");
    for (std::size_t i = 0; i < 500; ++i) {
        EXPECT_EQ(shown.values[0][i], outputs[0][i]);                                          // a, filtered
        EXPECT_EQ(shown.values[1][i], static_cast<double>(static_cast<float>(values[1][i])));  // b, as stored
        EXPECT_EQ(math.values[0][i], outputs[1][i]);
    }
    EXPECT_FALSE(core::signal::SignalChain(notchedSetup(), gauges(), kRate_hz, 100).display());
}
