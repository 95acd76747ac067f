// Schema 6 through a real store: a version-5 store becomes version 6 with
// its events (ids, kinds, notes) kept and the events table still tied to its
// sessions; a triggered session keeps the trigger it was cut by and its
// `trigger` event, in the store and in an export's side file; a kind word
// the store does not know is still refused.
#include "core/SampleBlock.h"
#include "core/storage/Schema.h"
#include "core/storage/SessionExport.h"
#include "core/storage/SessionStore.h"

#include "support/TempDirectory.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace tactiscope::core;
using namespace tactiscope::core::storage;

namespace {

using TriggerStoreTest = tactiscope::testing::TempDirectoryTest;

std::int64_t countOf(Database& db, const std::string& table)
{
    auto count = db.prepare("SELECT count(*) FROM " + table);
    count.step();
    return count.int64(0);
}

}  // namespace

TEST_F(TriggerStoreTest, AVersion5StoreBecomesVersion6WithItsEventsAndTheirSessions)
{
    const std::string path = file("v5.tactiscope");
    {
        Database db(path, Database::Access::ReadWrite);
        ASSERT_EQ(prepareSchema(db, 5), 0);
        db.exec("INSERT INTO sessions (id, uuid, mode, subject, started_utc, status, app_version) VALUES "
                "(1, 'u1', 'panel-scan', 'door-17', '2026-01-01T00:00:00.000Z', 'complete', '0.9'),"
                "(2, 'u2', 'general', 'board', '2026-01-02T00:00:00.000Z', 'complete', '0.9')");
        db.exec("INSERT INTO events (id, session_id, kind, start_s, end_s, direction, lag_s, note) VALUES "
                "(7, 1, 'defect', 1, 1.1, 1, 0.004, ''), (9, 1, 'alarm', 2, 2, 0, NULL, 'the link failed'), "
                "(12, 2, 'marker', 0.5, 0.5, 0, NULL, 'here')");
    }
    SessionStore store(path);
    auto version = store.database().prepare("PRAGMA user_version");
    ASSERT_TRUE(version.step());
    EXPECT_EQ(version.int64(0), kSchemaVersion);  // and on through the later migrations
    const auto events = store.events(1);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].id, 7);
    EXPECT_EQ(events[0].kind, EventKind::Defect);
    EXPECT_EQ(events[0].direction, 1);
    ASSERT_TRUE(events[0].lag_s);
    EXPECT_DOUBLE_EQ(*events[0].lag_s, 0.004);
    EXPECT_EQ(events[1].kind, EventKind::Alarm);
    EXPECT_EQ(events[1].note, "the link failed");
    EXPECT_EQ(store.session(1)->metadata.trigger, "");  // recorded by hand

    auto& db = store.database();
    db.exec("DELETE FROM sessions WHERE id = 1");
    EXPECT_EQ(countOf(db, "events"), 1);  // session 1's went with it
    EXPECT_THROW(db.exec("INSERT INTO events (session_id, kind, start_s, end_s) VALUES (99, 'trigger', 0, 0)"),
                 StorageError);
    EXPECT_THROW(db.exec("INSERT INTO events (session_id, kind, start_s, end_s) VALUES (2, 'triggered', 0, 0)"),
                 StorageError);
}

TEST_F(TriggerStoreTest, ATriggeredSessionKeepsItsTriggerAndItsTriggerEventThroughAnExport)
{
    const std::string path = file("t.tactiscope");
    SessionStore store(path);
    SessionMetadata metadata;
    metadata.subject = "door-18";
    metadata.trigger = "a>2e-05, pre 0.5 s, post 1 s, hold-off 0 s";
    const std::vector<ChannelDescriptor> channels{{"a", "", ChannelKind::Strain}, {"b", "", ChannelKind::Strain}};
    const auto id = store.beginSession(metadata, channels, 100.0);
    SampleBlock block(2, 200, 0.0, 0.01, 0);
    store.appendBlocks(id, std::span<const SampleBlock>(&block, 1));
    SessionEvent trigger;
    trigger.kind = EventKind::Trigger;
    trigger.start_s = trigger.end_s = 0.5;
    trigger.note = "a>2e-05";
    store.addEvents(id, std::span<const SessionEvent>(&trigger, 1));
    store.endSession(id, SessionStatus::Complete);

    EXPECT_EQ(store.session(id)->metadata.trigger, metadata.trigger);
    const auto events = store.events(id);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, EventKind::Trigger);
    EXPECT_DOUBLE_EQ(events[0].start_s, 0.5);
    EXPECT_EQ(events[0].note, "a>2e-05");

    std::ostringstream text;
    writeSessionMetadataJson(store, id, text);
    EXPECT_NE(text.str().find(R"("trigger":"a>2e-05, pre 0.5 s, post 1 s, hold-off 0 s")"), std::string::npos)
        << text.str();
    EXPECT_NE(text.str().find(R"("kind":"trigger","start_s":0.5)"), std::string::npos) << text.str();
}
