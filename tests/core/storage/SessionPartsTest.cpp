// Sessions of several devices in a real store (schema 7): a session row
// with a part per device, each part a session of its own with its clock
// mapping. The list shows the session, not its parts; deleting it takes
// the parts and their samples; a part cannot be begun under what is not a
// session of several devices; an altered mapping reads as none.
#include "core/storage/SessionStore.h"

#include "core/SampleBlock.h"
#include "core/timing/ClockMappingJson.h"
#include "core/timing/ClockMappingText.h"

#include "support/TempDirectory.h"

#include <gtest/gtest.h>

using namespace tactiscope::core;
using namespace tactiscope::core::storage;

namespace {

using SessionPartsTest = tactiscope::testing::TempDirectoryTest;

const std::vector<ChannelDescriptor> kChannels{{"force", "N", ChannelKind::Force}};

SampleBlock blockOf(std::uint64_t count, double rate_hz)
{
    SampleBlock block(1, count, 0.0, 1.0 / rate_hz, 0);
    for (std::uint64_t s = 0; s < count; ++s) block.channel(0)[s] = static_cast<double>(s);
    return block;
}

struct Stored {
    std::int64_t session = 0, beam = 0, cell = 0;
};

Stored storeTwoDevices(SessionStore& store)
{
    SessionMetadata metadata;
    metadata.mode = Mode::Capacitive;
    metadata.subject = "beam-7";
    Stored ids;
    ids.session = store.beginSessionOfDevices(metadata);
    metadata.partOf = ids.session;
    metadata.deviceName = "beam";
    metadata.deviceModel = "TSP-C";
    ids.beam = store.beginSession(metadata, kChannels, 100.0);
    store.appendBlocks(ids.beam, std::vector{blockOf(1000, 100.0)});  // 10 s
    metadata.deviceName = "load-cell";
    metadata.deviceModel = "LC-1";
    ids.cell = store.beginSession(metadata, kChannels, 1000.0);
    store.appendBlocks(ids.cell, std::vector{blockOf(12000, 1000.0)});  // 12 s
    for (const auto id : {ids.beam, ids.cell, ids.session}) store.endSession(id, SessionStatus::Complete);
    return ids;
}

}  // namespace

TEST_F(SessionPartsTest, TheListShowsTheSessionWithItsDevicesAndItsLongestPartsDuration)
{
    SessionStore store(file("s.tactiscope"));
    const auto ids = storeTwoDevices(store);
    const auto listed = store.sessions();
    ASSERT_EQ(listed.size(), 1u);
    EXPECT_EQ(listed[0].id, ids.session);
    EXPECT_EQ(listed[0].devices, 2u);
    EXPECT_DOUBLE_EQ(listed[0].duration_s(), 12.0);
    EXPECT_TRUE(listed[0].metadata.deviceModel.empty());  // each part has its own
    const auto parts = store.parts(ids.session);
    ASSERT_EQ(parts.size(), 2u);
    EXPECT_EQ(parts[0].id, ids.beam);
    EXPECT_EQ(parts[0].deviceName, "beam");
    EXPECT_EQ(parts[0].deviceModel, "TSP-C");
    EXPECT_EQ(parts[1].deviceName, "load-cell");
    EXPECT_EQ(parts[1].status, SessionStatus::Complete);
    EXPECT_TRUE(store.parts(ids.beam).empty());
    // A part is a session of its own, read as one.
    EXPECT_EQ(store.sampleCount(ids.cell), 12000u);
    EXPECT_EQ(store.session(ids.cell)->metadata.deviceName, "load-cell");
    EXPECT_EQ(store.session(ids.cell)->metadata.partOf, ids.session);
    // The session holds no samples of its own, and is not damaged for it.
    EXPECT_TRUE(store.channels(ids.session).empty());
    EXPECT_EQ(store.sampleCount(ids.session), 0u);
}

// A part alone is not deleted (fresh eyes, issue 52: the session kept a
// verdict and events of a part that was gone); the session goes whole.
TEST_F(SessionPartsTest, DeletingTheSessionTakesItsPartsAndTheirSamples)
{
    SessionStore store(file("s.tactiscope"));
    const auto ids = storeTwoDevices(store);
    try {
        store.deleteSession(ids.cell);
        ADD_FAILURE() << "a part was deleted alone";
    } catch (const StorageError& e) {
        EXPECT_EQ(std::string(e.what()), "session " + std::to_string(ids.cell) +
                                             " is the part of device load-cell in session " +
                                             std::to_string(ids.session) + "; delete session " +
                                             std::to_string(ids.session) + ", which goes with all its parts");
    }
    EXPECT_TRUE(store.session(ids.cell));
    store.deleteSession(ids.session);
    EXPECT_FALSE(store.session(ids.beam));
    EXPECT_FALSE(store.session(ids.cell));
    auto chunks = store.database().prepare("SELECT count(*) FROM chunks");
    ASSERT_TRUE(chunks.step());
    EXPECT_EQ(chunks.int64(0), 0);
}

TEST_F(SessionPartsTest, APartNeedsASessionOfSeveralDevicesAndAMappingOnlyAPart)
{
    SessionStore store(file("s.tactiscope"));
    SessionMetadata plain;
    const auto single = store.beginSession(plain, kChannels, 100.0);
    SessionMetadata part;
    part.partOf = single;  // has channels of its own
    EXPECT_THROW(store.beginSession(part, kChannels, 100.0), StorageError);
    part.partOf = 999;  // none
    EXPECT_THROW(store.beginSession(part, kChannels, 100.0), StorageError);
    const auto ids = storeTwoDevices(store);
    part.partOf = ids.beam;  // a part is no session of several devices
    EXPECT_THROW(store.beginSession(part, kChannels, 100.0), StorageError);
    EXPECT_THROW(store.setClockMapping(single, "{}"), StorageError);
    EXPECT_THROW(store.beginSessionOfDevices(part), StorageError);
    part.partOf = ids.session;
    part.deviceName = std::string("a\0b", 3);
    EXPECT_THROW(store.beginSession(part, kChannels, 100.0), StoreInputError);
}

TEST_F(SessionPartsTest, AStoredMappingComesBackAndAnAlteredOneReadsAsNone)
{
    SessionStore store(file("s.tactiscope"));
    const auto ids = storeTwoDevices(store);
    timing::ClockMapping mapping;
    mapping.reference_s = 5.0;
    mapping.offset_s = 0.5;
    mapping.drift = 80e-6;
    mapping.span_s = 9.75;
    mapping.pairs = 1000;
    mapping.basis = timing::ClockUncertaintyBasis::Spread;
    mapping.offset_u_s = 12e-6;
    mapping.drift_u = 0.3e-6;
    store.setClockMapping(ids.beam, timing::toJson(mapping));
    const auto back = timing::clockMappingFromJson(store.parts(ids.session)[0].clockJson);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->offset_s, 0.5);
    EXPECT_EQ(back->drift, 80e-6);
    EXPECT_EQ(back->basis, timing::ClockUncertaintyBasis::Spread);
    EXPECT_EQ(back->offset_u_s, 12e-6);
    // By hand: host(0) = 0 + 0.5 + 80e-6·(0 − 5) = 0.4996 s; u(0) = √(12² + (0.3·5)²) µs = 12.09 µs.
    EXPECT_EQ(timing::clockMappingText(store.parts(ids.session)[0].clockJson),
              "+0.499600 s at the start ± 0.012 ms, 80.0 ± 0.3 ppm slow (± from the spread of the fastest frames' "
              "delays)");
    EXPECT_EQ(timing::clockMappingText(store.parts(ids.session)[1].clockJson),
              "not mapped (no frames with the device's times were seen)");
    // Issue 55: its sample period's doubt, T/√12 = 577.35 µs at 2 ms, with
    // the rest in quadrature: √(12.09² + 577.35²) = 577.48 µs.
    mapping.samplePeriod_s = 0.002;
    EXPECT_EQ(timing::clockMappingText(timing::toJson(mapping)),
              "+0.499600 s at the start ± 0.577 ms, 80.0 ± 0.3 ppm slow (± from the spread of the fastest frames' "
              "delays; in the time's ±, ± 0.577 ms for where within its 2 ms sample period a sample is taken)");
    mapping.samplePeriod_s = 0.0;
    // Too few frames to tell its drift (fresh eyes: "153.1 ppm slow (± too
    // few frames to tell)" for 0.3 s): no drift figure is given.
    mapping.basis = timing::ClockUncertaintyBasis::TooFewFrames;
    EXPECT_EQ(timing::clockMappingText(timing::toJson(mapping)),
              "+0.499600 s at the start; its drift not known (too few frames to tell)");
    for (const char* altered :
         {"not json", "[]", R"({"offset_s":0.5})",
          R"({"reference_s":5,"offset_s":0.5,"drift":0.5,"span_s":9,)"
          R"("pairs":1,"uncertainty":"spread","offset_u_s":0,"drift_u":0})",
          R"({"reference_s":5,"offset_s":0.5,"drift":0,"span_s":9,"pairs":1,"uncertainty":"guess",)"
          R"("offset_u_s":0,"drift_u":0})",
          R"({"reference_s":5,"offset_s":0.5,"drift":0,"span_s":9,"pairs":1,"uncertainty":"spread",)"
          R"("offset_u_s":-1,"drift_u":0})",
          R"({"reference_s":5,"offset_s":0.5,"drift":0,"span_s":9,"pairs":1,"uncertainty":"exact",)"
          R"("offset_u_s":1e-6,"drift_u":0})",
          R"({"reference_s":5,"offset_s":1e400,"drift":0,"span_s":9,"pairs":1,"uncertainty":"spread",)"
          R"("offset_u_s":0,"drift_u":0})",
          R"({"reference_s":5,"offset_s":0.5,"drift":0,"span_s":9,"pairs":1,"uncertainty":"spread",)"
          R"("offset_u_s":0,"drift_u":0,"sample_period_s":-0.001})",
          R"({"reference_s":5,"offset_s":0.5,"drift":0,"span_s":9,"pairs":1,"uncertainty":"spread",)"
          R"("offset_u_s":0,"drift_u":0,"sample_period_s":"fast"})",
          R"({"reference_s":5,"offset_s":0.5,"drift":0,"span_s":9,"pairs":1,"uncertainty":"spread",)"
          R"("offset_u_s":0,"drift_u":0,"sample_period_s":1e9})"}) {
        EXPECT_FALSE(timing::clockMappingFromJson(altered)) << altered;
        store.setClockMapping(ids.cell, altered);
        EXPECT_EQ(timing::clockMappingText(store.parts(ids.session)[1].clockJson),
                  "not mapped (the stored mapping does not read as one: damaged, or written by another program)");
    }
}

// A part's times onto its session's: by hand, a device whose stream began
// at its own 100 s (origin), mapped host = a + 2 + 1e-4·(a − 110), in a
// session that began at host 101.5 s. Its sample at part time s = 10
// (a = 110) is at host 112, session time 10.5.
TEST(ClockMappingOnSessionClocks, ShiftsTheMappingToThePartsAndTheSessionsZeros)
{
    timing::ClockMapping mapping;
    mapping.reference_s = 110.0;
    mapping.offset_s = 2.0;
    mapping.drift = 1e-4;
    const auto shifted = timing::onSessionClocks(mapping, 100.0, 101.5);
    EXPECT_NEAR(shifted.host_s(10.0), 10.5, 1e-12);
    // s = 0 (a = 100): host = 100 + 2 − 1e-3 = 101.999, session 0.499.
    EXPECT_NEAR(shifted.host_s(0.0), 0.499, 1e-12);
}
