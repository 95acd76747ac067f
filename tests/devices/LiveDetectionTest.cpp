// The live detector on the simulated panel scan, fed block by block as the
// acquisition does: its output and events equal the offline detector's over
// the same samples; new settings apply from the next block, exactly as a
// fresh detector started there with them; a gap restarts it likewise.
#include "core/detector/LiveDetection.h"
#include "core/SampleBlock.h"
#include "core/detector/OfflineDetection.h"
#include "devices/simulator/PanelScanScenario.h"

#include <gtest/gtest.h>

using namespace tactiscope;
using core::detector::LiveDetection;
using core::detector::LiveDetectionSettings;

namespace {

constexpr double kDt = 0.002;

core::SampleBlock simulate(double seconds)
{
    devices::simulator::PanelScanParameters p;
    p.seed = 9;
    devices::simulator::PanelScanScenario scenario(p);
    core::SampleBlock block(2, static_cast<std::size_t>(seconds * 500.0), 0.0, kDt);
    scenario.generate(block);
    return block;
}

// Samples [first, first + count) of `scan` as a block numbered from `index`.
core::SampleBlock slice(const core::SampleBlock& scan, std::size_t first, std::size_t count, std::uint64_t index)
{
    core::SampleBlock block(2, count, scan.timeAt_s(first), kDt, index);
    for (std::size_t c = 0; c < 2; ++c)
        std::copy_n(scan.channel(c).begin() + static_cast<std::ptrdiff_t>(first), count, block.channel(c).begin());
    return block;
}

// The offline detector over samples [first, end) of the scan.
std::vector<core::detector::ProbeOutput> offline(const core::SampleBlock& scan, std::size_t first, std::size_t end,
                                                 core::detector::DetectorParameters parameters)
{
    parameters.sampleInterval_s = kDt;
    core::detector::SeriesInput input{
        scan.timeAt_s(first),
        {scan.channel(0).subspan(first, end - first), scan.channel(1).subspan(first, end - first)},
        {}};
    return core::detector::detectSeries(input, parameters);
}

struct Display {
    std::vector<double> decision, rab;
};

Display drain(const LiveDetection& live)
{
    core::LiveCursor cursor;
    core::LiveChunk chunk;
    live.output()->readNew(cursor, chunk);
    return {chunk.values[0], chunk.values[1]};
}

}  // namespace

TEST(LiveDetection, BlockByBlockEqualsTheOfflineDetectorAndItsEvents)
{
    const auto scan = simulate(12.0);
    LiveDetection live({0, 1}, 500.0, {}, 20.0);
    std::vector<core::detector::DefectEvent> events;
    std::size_t first = 0;
    for (std::size_t size = 1; first < scan.sampleCount(); size = size % 37 + 3) {
        const std::size_t count = std::min(size, scan.sampleCount() - first);
        live.consume(slice(scan, first, count, first));
        for (const auto& e : live.takeEvents()) events.push_back(e);
        first += count;
    }
    const auto expected = offline(scan, 0, scan.sampleCount(), {});
    const auto shown = drain(live);
    ASSERT_EQ(shown.decision.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        ASSERT_EQ(shown.decision[i], expected[i].combined.decision) << i;
        ASSERT_EQ(shown.rab[i], expected[i].combined.rab) << i;
    }
    // Events: those the offline segmenter finds, but for one still open at the end.
    const auto offlineEvents = core::detector::segmentEvents(expected, kDt, 0.020, std::nullopt);
    ASSERT_GT(offlineEvents.size(), 4u);
    ASSERT_GE(events.size() + 1, offlineEvents.size());
    for (std::size_t e = 0; e < events.size(); ++e) {
        EXPECT_NEAR(events[e].start_s, offlineEvents[e].start_s, 1e-9) << e;  // t0 + s·Δt per block
        EXPECT_EQ(events[e].direction, offlineEvents[e].direction) << e;
        EXPECT_EQ(events[e].peakR, offlineEvents[e].peakR) << e;
    }
}

TEST(LiveDetection, NewSettingsActFromTheNextBlockAsAFreshDetectorWould)
{
    const auto scan = simulate(8.0);
    LiveDetection live({0, 1}, 500.0, {}, 20.0);
    live.consume(slice(scan, 0, 1500, 0));
    LiveDetectionSettings stricter;
    stricter.parameters.threshold = 0.95;
    stricter.parameters.lags_s = core::detector::lagRange_s(0.010, 0.100, 0.004);
    live.setSettings(stricter);
    EXPECT_EQ(live.settings().parameters.threshold, 0.95);
    live.consume(slice(scan, 1500, scan.sampleCount() - 1500, 1500));
    const auto shown = drain(live);
    const auto before = offline(scan, 0, 1500, {});
    const auto after = offline(scan, 1500, scan.sampleCount(), stricter.parameters);
    for (std::size_t i = 0; i < 1500; ++i) ASSERT_EQ(shown.rab[i], before[i].combined.rab) << i;
    for (std::size_t i = 0; i < after.size(); ++i) {
        ASSERT_EQ(shown.decision[1500 + i], after[i].combined.decision) << i;
        ASSERT_EQ(shown.rab[1500 + i], after[i].combined.rab) << i;
    }
    // Bad settings are refused and change nothing.
    LiveDetectionSettings bad;
    bad.parameters.threshold = 0.9;
    bad.parameters.lags_s.clear();
    EXPECT_THROW(live.setSettings(bad), std::invalid_argument);
    EXPECT_EQ(live.settings().parameters.threshold, 0.95);
}

TEST(LiveDetection, AGapRestartsTheDetector)
{
    const auto scan = simulate(8.0);
    LiveDetection live({0, 1}, 500.0, {}, 20.0);
    live.consume(slice(scan, 0, 1000, 0));
    // 200 samples lost: the next block's index jumps.
    live.consume(slice(scan, 1200, scan.sampleCount() - 1200, 1200));
    const auto shown = drain(live);
    const auto after = offline(scan, 1200, scan.sampleCount(), {});
    for (std::size_t i = 0; i < after.size(); ++i) ASSERT_EQ(shown.rab[1000 + i], after[i].combined.rab) << i;
}
