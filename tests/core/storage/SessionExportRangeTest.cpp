// A CSV export of part of a session (a range chosen in review): exactly the
// stored samples of the range, gaps left out, with the range and the
// calibrations named in its metadata.
#include "core/storage/SessionExport.h"

#include "core/SampleBlock.h"

#include "support/TempDirectory.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>

using namespace tactiscope::core;
using namespace tactiscope::core::storage;

namespace {

using SessionExportRangeTest = tactiscope::testing::TempDirectoryTest;

// At 4 Hz, sample i of channel "a" holds i / 2: exact in binary32 and in text.
SampleBlock blockAt(std::uint64_t first, std::size_t count)
{
    SampleBlock block(1, count, static_cast<double>(first) / 4.0, 0.25, first);
    for (std::size_t s = 0; s < count; ++s) block.channel(0)[s] = static_cast<double>(first + s) / 2.0;
    return block;
}

}  // namespace

TEST_F(SessionExportRangeTest, ARangeHoldsItsStoredSamplesAndSaysWhichInItsMetadata)
{
    SessionStore store(file("s.tactiscope"));
    SessionMetadata metadata;
    metadata.mode = tactiscope::core::Mode::Capacitive;
    metadata.calibrationsJson = R"([{"kind":"capacitive","c0_pf":51.44}])";
    const std::vector<ChannelDescriptor> channels{{"a", "pF", ChannelKind::Capacitance}};
    const auto id = store.beginSession(metadata, channels, 4.0);
    // Samples 0–5, then 6 and 7 lost, then 8–19.
    store.appendBlocks(id, std::vector{blockAt(0, 6)});
    store.appendBlocks(id, std::vector{blockAt(8, 12)});
    store.endSession(id, tactiscope::core::SessionStatus::Complete);

    std::ostringstream csv;
    writeSessionCsv(store, id, csv, {4, 6});  // samples 4…9: 6 and 7 are lost
    EXPECT_EQ(csv.str(), "t [s],a [pF]\n1,2\n1.25,2.5\n2,4\n2.25,4.5\n");

    std::ostringstream meta;
    writeSessionMetadataJson(store, id, meta, {4, 6});
    const auto json = nlohmann::json::parse(meta.str());
    EXPECT_EQ(json["exported_range"]["first_index"], 4);
    EXPECT_EQ(json["exported_range"]["count"], 6);
    EXPECT_DOUBLE_EQ(json["exported_range"]["from_s"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(json["exported_range"]["to_s"].get<double>(), 2.5);
    EXPECT_EQ(json["session"]["calibrations_json"], metadata.calibrationsJson);

    std::ostringstream tail;  // a range past the end is clipped to it
    writeSessionCsv(store, id, tail, {18, 100});
    EXPECT_EQ(tail.str(), "t [s],a [pF]\n4.5,9\n4.75,9.5\n");
}
