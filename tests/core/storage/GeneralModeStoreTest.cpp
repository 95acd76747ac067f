// Schema 5 through a real store: a version-4 store with sessions and all
// their rows becomes version 5 with nothing lost and its foreign keys still
// in force (the sessions table is rebuilt for the general mode's CHECK);
// a general session keeps the roles its channels played; the store refuses
// a role word it does not know. Schema 8: a version-7 store keeps its
// channels and their roles through the channels table's rebuild, and a
// channel may then be a reference force.
#include "core/SampleBlock.h"
#include "core/storage/ChunkCodec.h"
#include "core/storage/Schema.h"
#include "core/storage/SessionStore.h"

#include "support/TempDirectory.h"

#include <gtest/gtest.h>

using namespace tactiscope::core;
using namespace tactiscope::core::storage;

namespace {

using GeneralModeStoreTest = tactiscope::testing::TempDirectoryTest;

std::int64_t countOf(Database& db, const std::string& table)
{
    auto count = db.prepare("SELECT count(*) FROM " + table);
    count.step();
    return count.int64(0);
}

}  // namespace

TEST_F(GeneralModeStoreTest, AVersion4StoreBecomesVersion5WithEveryRowAndItsForeignKeys)
{
    const std::string path = file("v4.tactiscope");
    {
        Database db(path, Database::Access::ReadWrite);
        ASSERT_EQ(prepareSchema(db, 4), 0);
        db.exec("INSERT INTO sessions (id, uuid, mode, subject, started_utc, ended_utc, status, verdict, app_version, "
                "calibrations_json) VALUES "
                "(1, 'u1', 'panel-scan', 'door-17', '2026-01-01T00:00:00.000Z', '2026-01-01T00:01:00.000Z', "
                "'complete', 'pass', '0.9', ''),"
                "(2, 'u2', 'palpation', 'phantom', '2026-01-02T00:00:00.000Z', NULL, 'interrupted', '', '0.9', '[]')");
        db.exec("INSERT INTO channels VALUES (1, 0, 'a', '', 'strain', 500), (1, 1, 'b', '', 'strain', 500), "
                "(2, 0, 'high', 'counts', 'other', 1000)");
        SampleBlock block(2, 4, 0.0, 2e-3, 0);
        for (std::size_t c = 0; c < 2; ++c)
            for (std::size_t s = 0; s < 4; ++s) block.channel(c)[s] = 1e-6 * static_cast<double>(s + c);
        db.prepare("INSERT INTO chunks (session_id, first_index, first_time_s, count, samples) VALUES (1, 0, 0, 4, ?)")
            .bindBlob(1, encodeChunk(block))
            .run();
        db.exec("INSERT INTO events (session_id, kind, start_s, end_s, direction) VALUES (1, 'defect', 1, 1.1, 1)");
        db.exec("INSERT INTO verdicts (session_id, role, verdict, decided_utc) VALUES "
                "(1, 'automatic', 'pass', '2026-01-01T00:01:00.000Z')");
        db.exec("INSERT INTO readings (session_id, kind, start_s, end_s, quantity, unit, value) "
                "VALUES (2, 'compliance', 1, 2, 'stiffness', 'N/m', 117)");
    }
    SessionStore store(path);
    auto version = store.database().prepare("PRAGMA user_version");
    ASSERT_TRUE(version.step());
    EXPECT_EQ(version.int64(0), kSchemaVersion);  // and on through the later migrations
    const auto sessions = store.sessions();
    ASSERT_EQ(sessions.size(), 2u);
    const auto first = store.session(1);
    ASSERT_TRUE(first);
    EXPECT_EQ(first->metadata.subject, "door-17");
    EXPECT_EQ(first->verdict, Verdict::Pass);
    EXPECT_EQ(store.session(2)->status, SessionStatus::Interrupted);
    EXPECT_EQ(store.sampleCount(1), 4u);
    EXPECT_DOUBLE_EQ(store.readChannel(1, 1, 3, 1).front(), static_cast<double>(static_cast<float>(4e-6)));
    const auto channels = store.channels(1);
    ASSERT_EQ(channels.size(), 2u);
    EXPECT_FALSE(channels[0].descriptor.role);  // sessions before roles played none
    EXPECT_EQ(store.verdicts(1).size(), 1u);

    // The children still belong to the rebuilt table: deleting a session
    // takes its rows with it, and a row for no session is refused.
    auto& db = store.database();
    db.exec("DELETE FROM sessions WHERE id = 1");
    EXPECT_EQ(countOf(db, "channels"), 1);
    EXPECT_EQ(countOf(db, "chunks"), 0);
    EXPECT_EQ(countOf(db, "events"), 0);
    EXPECT_EQ(countOf(db, "verdicts"), 0);
    EXPECT_EQ(countOf(db, "readings"), 1);
    EXPECT_THROW(db.exec("INSERT INTO events (session_id, kind, start_s, end_s) VALUES (99, 'marker', 0, 0)"),
                 StorageError);
}

TEST_F(GeneralModeStoreTest, AGeneralSessionKeepsTheRolesItsChannelsPlayed)
{
    SessionStore store(file("g.tactiscope"));
    SessionMetadata metadata;
    metadata.mode = Mode::General;
    metadata.subject = "maker board";
    std::vector<ChannelDescriptor> channels{
        {"a", "", ChannelKind::Other}, {"b", "", ChannelKind::Other}, {"temp", "degC", ChannelKind::Other}};
    channels[0].role = ChannelRole::CantileverA;
    channels[1].role = ChannelRole::CantileverB;
    const auto id = store.beginSession(metadata, channels, 100.0);
    store.endSession(id, SessionStatus::Complete);
    EXPECT_EQ(store.session(id)->metadata.mode, Mode::General);
    const auto stored = store.channels(id);
    ASSERT_EQ(stored.size(), 3u);
    for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(stored[c].descriptor, channels[c]) << c;
    SessionFilter general;
    general.mode = Mode::General;
    EXPECT_EQ(store.sessions(general).size(), 1u);
    EXPECT_THROW(store.database().exec("UPDATE channels SET role = 'cantilever-c' WHERE position = 2"), StorageError);
}

TEST_F(GeneralModeStoreTest, AVersion7StoreBecomesCurrentWithItsChannelsAndTheirRoles)
{
    const std::string path = file("v7.tactiscope");
    {
        Database db(path, Database::Access::ReadWrite);
        ASSERT_EQ(prepareSchema(db, 7), 0);
        db.exec("INSERT INTO sessions (id, uuid, mode, subject, started_utc, status, app_version) VALUES "
                "(1, 'u1', 'general', 'board', '2026-01-01T00:00:00.000Z', 'complete', '0.9'),"
                "(2, 'u2', 'capacitive', 'beam', '2026-01-02T00:00:00.000Z', 'complete', '0.9')");
        db.exec("INSERT INTO channels (session_id, position, name, unit, kind, sample_rate_hz, role) VALUES "
                "(1, 0, 'a', '', 'other', 100, 'cantilever-a'), (1, 1, 'b', '', 'other', 100, 'cantilever-b'), "
                "(2, 0, 'capacitance', 'F', 'capacitance', 10, '')");
        EXPECT_THROW(db.exec("UPDATE channels SET role = 'reference-force' WHERE session_id = 2"), StorageError);
    }
    SessionStore store(path);
    auto version = store.database().prepare("PRAGMA user_version");
    ASSERT_TRUE(version.step());
    EXPECT_EQ(version.int64(0), kSchemaVersion);  // 8, then 9 (no session says why it was not judged) and 10
    EXPECT_EQ(store.session(2)->unjudged, "");
    const auto general = store.channels(1);
    ASSERT_EQ(general.size(), 2u);
    EXPECT_EQ(general[0].descriptor.role, ChannelRole::CantileverA);
    EXPECT_EQ(general[1].descriptor.role, ChannelRole::CantileverB);
    EXPECT_DOUBLE_EQ(general[1].sampleRate_hz, 100.0);
    ASSERT_EQ(store.channels(2).size(), 1u);
    auto& db = store.database();
    db.exec("INSERT INTO channels (session_id, position, name, unit, kind, sample_rate_hz, role) VALUES "
            "(2, 1, 'force', 'N', 'force', 1000, 'reference-force')");
    EXPECT_EQ(store.channels(2)[1].descriptor.role, ChannelRole::ReferenceForce);
    db.exec("DELETE FROM sessions WHERE id = 1");  // the rebuilt table is still its session's
    EXPECT_EQ(countOf(db, "channels"), 2);
    EXPECT_THROW(db.exec("INSERT INTO channels (session_id, position, name, unit, kind, sample_rate_hz) VALUES "
                         "(99, 0, 'x', '', 'other', 1)"),
                 StorageError);
}

// Version 10 lets a channel be the probe's position along a panel scan's
// stroke (an encoder): a version-9 store keeps its channels and roles, and
// then takes the role it refused.
TEST_F(GeneralModeStoreTest, AVersion9StoreTakesTheRolePositionKeepingItsChannels)
{
    const std::string path = file("v9.tactiscope");
    {
        Database db(path, Database::Access::ReadWrite);
        ASSERT_EQ(prepareSchema(db, 9), 0);
        db.exec("INSERT INTO sessions (id, uuid, mode, subject, started_utc, status, app_version) VALUES "
                "(1, 'u1', 'panel-scan', 'panel', '2026-01-01T00:00:00.000Z', 'complete', '0.9')");
        db.exec("INSERT INTO channels (session_id, position, name, unit, kind, sample_rate_hz, role) VALUES "
                "(1, 0, 'a', '', 'strain', 500, 'cantilever-a'), (1, 1, 'b', '', 'strain', 500, 'cantilever-b'), "
                "(1, 2, 'x', 'm', 'position', 500, '')");
        EXPECT_THROW(db.exec("UPDATE channels SET role = 'position' WHERE position = 2"), StorageError);
    }
    SessionStore store(path);
    auto& db = store.database();
    auto version = db.prepare("PRAGMA user_version");
    ASSERT_TRUE(version.step());
    EXPECT_EQ(version.int64(0), kSchemaVersion);  // 10, then 11 (no session says how it was filtered)
    ASSERT_EQ(store.channels(1).size(), 3u);
    EXPECT_EQ(store.channels(1)[0].descriptor.role, ChannelRole::CantileverA);
    db.exec("UPDATE channels SET role = 'position' WHERE position = 2");
    EXPECT_EQ(store.channels(1)[2].descriptor.role, ChannelRole::Position);
    db.exec("DELETE FROM sessions WHERE id = 1");  // the rebuilt table is still its session's
    EXPECT_EQ(countOf(db, "channels"), 0);
}

// A newer program's store may hold a mode this build does not know: it is
// read as a general recording (its channels as they came), never as a
// panel scan whose detector would run on channels of another kind.
TEST_F(GeneralModeStoreTest, AModeWordThisBuildDoesNotKnowIsReadAsGeneral)
{
    const std::string path = file("newer.tactiscope");
    {
        SessionStore store(path);
        SessionMetadata metadata;
        metadata.mode = Mode::PanelScan;
        const auto id =
            store.beginSession(metadata, std::vector<ChannelDescriptor>{{"t", "K", ChannelKind::Other}}, 10.0);
        store.endSession(id, SessionStatus::Complete);
        store.database().exec("PRAGMA ignore_check_constraints = ON");
        store.database().exec("UPDATE sessions SET mode = 'thermal-map' WHERE id = " + std::to_string(id));
    }
    SessionStore store(path, Database::Access::ReadOnly);
    EXPECT_EQ(store.sessions().front().metadata.mode, Mode::General);
}
