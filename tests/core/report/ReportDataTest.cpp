// ReportData from a real store: the session's sensor and calibrations from
// its copies, records narrowed to a range, and the channels' overviews
// equal to the min/max computed directly from the samples.
#include "core/report/ReportData.h"

#include "core/SampleBlock.h"
#include "support/TempDirectory.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace tactiscope::core;
using namespace tactiscope::core::storage;

namespace {

using ReportDataTest = tactiscope::testing::TempDirectoryTest;

constexpr double kRate_hz = 100.0;
constexpr std::size_t kSamples = 2000;  // 20 s

double sampleValue(std::size_t i)
{
    return std::sin(0.01 * static_cast<double>(i)) + 0.001 * static_cast<double>(i % 7);
}

std::int64_t recordSession(SessionStore& store)
{
    SessionMetadata metadata;
    metadata.mode = tactiscope::core::Mode::PanelScan;
    metadata.subject = "door-7";
    metadata.operatorName = "Ada";
    metadata.profileJson = R"({"kind": "cantilever", "name": "Capsule probe 3", "length_m": 0.05})";
    calibration::CalibrationRecord record;
    record.kind = "gauge_factor";
    record.sensorName = "Capsule probe 3";
    record.operatorName = "Grace";
    record.timestampUtc = "2026-11-20T09:00:00Z";
    record.values = {{"gauge_factor", 2.07}};
    metadata.calibrationsJson = "[" + record.toJson() + ", {\"not\": \"a record\"}]";
    const std::vector<ChannelDescriptor> channels{{"a", "", ChannelKind::Strain}};
    const auto id = store.beginSession(metadata, channels, kRate_hz);
    std::vector<SampleBlock> blocks;
    for (std::size_t first = 0; first < kSamples; first += 100) {
        SampleBlock block(1, 100, static_cast<double>(first) / kRate_hz, 1.0 / kRate_hz, first);
        for (std::size_t i = 0; i < 100; ++i) block.channel(0)[i] = sampleValue(first + i);
        blocks.push_back(std::move(block));
    }
    store.appendBlocks(id, blocks);
    store.addEvents(id,
                    std::vector<SessionEvent>{
                        {0, kLiveAnalysis, tactiscope::core::EventKind::Defect, 2.0, 2.2, 1, 0.95, 0.05, 0.9, ""},
                        {0, kLiveAnalysis, tactiscope::core::EventKind::Defect, 12.0, 12.3, -1, 0.93, 0.04, 1.1, ""},
                        {0, "other", tactiscope::core::EventKind::Defect, 12.0, 12.3, -1, 0.5, 0.04, 1.1, ""},
                    });
    store.addAnnotation(id, {0, 15.0, "Ada", "scratch, not a dent", "", ""});
    store.endSession(id, tactiscope::core::SessionStatus::Complete);
    return id;
}

}  // namespace

TEST_F(ReportDataTest, TheWholeSessionWithItsSensorCalibrationsAndLiveEvents)
{
    SessionStore store(file("r.tactiscope"));
    const auto id = recordSession(store);
    const auto data = report::gatherReport(store, id);
    EXPECT_TRUE(data.wholeSession());
    EXPECT_EQ(data.session.metadata.subject, "door-7");
    EXPECT_EQ(data.sensorName, "Capsule probe 3");
    ASSERT_EQ(data.calibrations.size(), 1u);  // the unreadable one is left out
    EXPECT_EQ(data.calibrations[0].value("gauge_factor"), 2.07);
    ASSERT_EQ(data.events.size(), 2u);  // the live analysis only
    EXPECT_EQ(data.annotations.size(), 1u);
    ASSERT_EQ(data.traces.size(), 1u);
    EXPECT_EQ(data.traces[0].channel.descriptor.name, "a");
}

TEST_F(ReportDataTest, ARangeNarrowsTheRecordsAndTheOverviewMatchesTheSamples)
{
    SessionStore store(file("r.tactiscope"));
    const auto id = recordSession(store);
    const auto data = report::gatherReport(store, id, {{10.0, 14.0}}, 40);
    EXPECT_FALSE(data.wholeSession());
    ASSERT_EQ(data.events.size(), 1u);
    EXPECT_EQ(data.events[0].start_s, 12.0);
    EXPECT_TRUE(data.annotations.empty());  // at 15 s
    const auto& points = data.traces[0].points;
    ASSERT_FALSE(points.empty());
    EXPECT_EQ(points.front().firstIndex, 1000u);
    EXPECT_EQ(points.back().firstIndex + points.back().count, 1400u);
    // Each stretch's extremes, straight from the formula that made the
    // samples (stored as binary32).
    for (const auto& p : points) {
        double lo = INFINITY, hi = -INFINITY;
        for (std::uint64_t i = p.firstIndex; i < p.firstIndex + p.count; ++i) {
            const double v = static_cast<float>(sampleValue(i));
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        EXPECT_DOUBLE_EQ(p.min, lo) << p.firstIndex;
        EXPECT_DOUBLE_EQ(p.max, hi) << p.firstIndex;
    }
}

TEST_F(ReportDataTest, RefusesAnUnknownSessionOrARangeOutsideIt)
{
    SessionStore store(file("r.tactiscope"));
    const auto id = recordSession(store);
    EXPECT_THROW(report::gatherReport(store, id + 1), StorageError);
    EXPECT_THROW(report::gatherReport(store, id, {{5.0, 4.0}}), std::invalid_argument);
    EXPECT_THROW(report::gatherReport(store, id, {{std::nullopt, 25.0}}), std::invalid_argument);
    EXPECT_THROW(report::gatherReport(store, id, {{-1.0, std::nullopt}}), std::invalid_argument);
}
