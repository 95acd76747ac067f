// The detector over a stored session, window by window from a real SQLite
// store: the same events as over the whole channels held in memory (a
// recording of three windows with a lost stretch inside the second), the
// progress it reports, and a cancel that stops it.
#include "core/derived/StoredDetection.h"

#include "core/SampleBlock.h"
#include "core/detector/OfflineDetection.h"
#include "support/TempDirectory.h"

#include <gtest/gtest.h>

#include <random>

using namespace tactiscope::core;

namespace {

using StoredDetectionTest = tactiscope::testing::TempDirectoryTest;

constexpr std::size_t kSamples = 2 * detector::StreamingDetection::kChunk + 20000;
constexpr std::uint64_t kLostFrom = 100000;  // 1000 samples lost from here

// Two strain gauges at 500 Hz: quiet noise with a pass over a defect every
// 4 s (b repeats a 26 samples later), a thousand lost in the second window.
std::int64_t writeSession(storage::SessionStore& store)
{
    storage::SessionMetadata metadata;
    metadata.mode = Mode::PanelScan;
    const std::vector<ChannelDescriptor> channels{{"a", "", ChannelKind::Strain}, {"b", "", ChannelKind::Strain}};
    const std::int64_t id = store.beginSession(metadata, channels, 500.0);
    std::mt19937_64 random(5);
    std::normal_distribution<double> quiet(0.0, 1e-6), loud(0.0, 3e-4);
    std::vector<double> a(kSamples), b(kSamples);
    for (std::size_t i = 0; i < kSamples; ++i) {
        const bool pass = i % 2000 < 250;
        a[i] = pass ? loud(random) : quiet(random);
        b[i] = pass && i % 2000 >= 26 ? a[i - 26] : quiet(random);
    }
    for (std::uint64_t first = 0; first < kSamples; first += 1000) {
        if (first == kLostFrom) continue;
        const std::size_t count = std::min<std::size_t>(1000, kSamples - first);
        SampleBlock block(2, count, static_cast<double>(first) / 500.0, 1.0 / 500.0, first);
        for (std::size_t s = 0; s < count; ++s) {
            block.channel(0)[s] = a[first + s];
            block.channel(1)[s] = b[first + s];
        }
        store.appendBlocks(id, std::span(&block, 1));
    }
    store.endSession(id, SessionStatus::Complete);
    return id;
}

}  // namespace

TEST_F(StoredDetectionTest, WindowsFromTheStoreGiveTheEventsOfTheWholeChannels)
{
    storage::SessionStore store(file("s.tactiscope"));
    const std::int64_t id = writeSession(store);
    const std::vector<std::size_t> cantilevers{0, 1};
    const detector::StretchSettings settings{detector::DetectorParameters{}, 0.02, 0.015, 2};

    std::vector<std::vector<double>> whole;
    for (const std::size_t c : cantilevers) whole.push_back(store.readChannel(id, c, 0, kSamples));
    const auto expected = detector::detectStretches(whole, settings);
    ASSERT_GE(expected.events.size(), 70u);  // 76 passes, one lost in the gap

    std::vector<std::uint64_t> reported;
    const auto streamed =
        derived::detectStoredSession(store, id, cantilevers, settings, [&](std::uint64_t done, std::uint64_t total) {
            EXPECT_EQ(total, kSamples);
            reported.push_back(done);
            return true;
        });
    ASSERT_TRUE(streamed.has_value());
    EXPECT_EQ(streamed->analysedSamples, kSamples - 1000);  // the lost thousand
    EXPECT_EQ(streamed->analysedSamples, expected.analysedSamples);
    ASSERT_EQ(streamed->events.size(), expected.events.size());
    for (std::size_t e = 0; e < expected.events.size(); ++e) {
        EXPECT_EQ(streamed->events[e].start_s, expected.events[e].start_s) << e;
        EXPECT_EQ(streamed->events[e].end_s, expected.events[e].end_s) << e;
        EXPECT_EQ(streamed->events[e].peakR, expected.events[e].peakR) << e;
        EXPECT_EQ(streamed->events[e].speed_m_per_s, expected.events[e].speed_m_per_s) << e;
    }
    // One report per window, rising to the whole session.
    ASSERT_EQ(reported.size(), 3u);
    EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
    EXPECT_EQ(reported.back(), kSamples);

    // Cancelled after the first window: nothing.
    int calls = 0;
    EXPECT_FALSE(derived::detectStoredSession(store, id, cantilevers, settings, [&](std::uint64_t, std::uint64_t) {
                     ++calls;
                     return false;
                 }).has_value());
    EXPECT_EQ(calls, 1);
}
