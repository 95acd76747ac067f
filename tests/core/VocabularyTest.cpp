// The session vocabulary against the store's schema: every word the core
// writes is one the schema's CHECK lists accept (checked with raw SQL on a
// real store file, not through the store's own code), words outside the
// vocabulary are refused, and each word reads back as the value it came from.
#include "core/Vocabulary.h"
#include "core/storage/Database.h"
#include "core/storage/SessionStore.h"
#include "support/TempPath.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

using namespace tactiscope::core;
using storage::Database;

namespace {

class VocabularySchema : public ::testing::Test {
protected:
    void SetUp() override
    {
        storage::SessionStore create(m_path);  // the current schema, by migration
        m_db = std::make_unique<Database>(m_path, Database::Access::ReadWrite);
        m_db->exec("PRAGMA foreign_keys = ON");
        m_session = insertSession("panel-scan", "complete");
    }
    void TearDown() override
    {
        m_db.reset();
        std::filesystem::remove(m_path);
    }

    std::int64_t insertSession(std::string_view mode, std::string_view status)
    {
        m_db->prepare("INSERT INTO sessions (uuid, mode, started_utc, status, app_version) "
                      "VALUES (?, ?, '2026-11-23T08:00:00Z', ?, 'test')")
            .bind(1, "uuid-" + std::to_string(++m_uuid))
            .bind(2, mode)
            .bind(3, status)
            .step();
        return m_db->lastInsertId();
    }
    void insertEvent(std::string_view kind)
    {
        m_db->prepare("INSERT INTO events (session_id, kind, start_s, end_s) VALUES (?, ?, 1.0, 2.0)")
            .bind(1, m_session)
            .bind(2, kind)
            .step();
    }
    void insertReading(std::string_view kind)
    {
        m_db->prepare("INSERT INTO readings (session_id, kind, start_s, end_s, quantity, value, unit) "
                      "VALUES (?, ?, 1.0, 2.0, 'k', 1.0, 'N/m')")
            .bind(1, m_session)
            .bind(2, kind)
            .step();
    }

    std::string m_path = tactiscope::testing::uniqueTempPath("vocabulary.tactiscope");
    std::unique_ptr<Database> m_db;
    std::int64_t m_session = 0;
    int m_uuid = 0;
};

}  // namespace

TEST_F(VocabularySchema, AcceptsEveryModeAndStatusAndRefusesOthers)
{
    for (const Mode mode : kModes) EXPECT_NO_THROW(insertSession(toString(mode), "complete")) << toString(mode);
    for (const SessionStatus status : kSessionStatuses)
        EXPECT_NO_THROW(insertSession("palpation", toString(status))) << toString(status);
    EXPECT_THROW(insertSession("panel scan", "complete"), storage::StorageError);
    EXPECT_THROW(insertSession("Palpation", "complete"), storage::StorageError);
    EXPECT_THROW(insertSession("palpation", "done"), storage::StorageError);
}

TEST_F(VocabularySchema, AcceptsEveryEventAndReadingKindAndRefusesOthers)
{
    for (const EventKind kind : kEventKinds) EXPECT_NO_THROW(insertEvent(toString(kind))) << toString(kind);
    for (const ReadingKind kind : kReadingKinds) EXPECT_NO_THROW(insertReading(toString(kind))) << toString(kind);
    EXPECT_THROW(insertEvent("dent"), storage::StorageError);
    EXPECT_THROW(insertReading("stiffness"), storage::StorageError);
}

TEST(Vocabulary, EachWordReadsBackAsItsValueAndNothingElseParses)
{
    for (const Mode mode : kModes) EXPECT_EQ(modeFromString(toString(mode)), mode);
    for (const SessionStatus status : kSessionStatuses) EXPECT_EQ(sessionStatusFromString(toString(status)), status);
    for (const Verdict verdict : kVerdicts) EXPECT_EQ(verdictFromString(toString(verdict)), verdict);
    for (const EventKind kind : kEventKinds) EXPECT_EQ(eventKindFromString(toString(kind)), kind);
    for (const ReadingKind kind : kReadingKinds) EXPECT_EQ(readingKindFromString(toString(kind)), kind);
    for (const std::string_view text : {"", " panel-scan", "PASS", "defects_found", "unknown"}) {
        EXPECT_FALSE(modeFromString(text));
        EXPECT_FALSE(verdictFromString(text));
        EXPECT_FALSE(eventKindFromString(text));
    }
    // The words other tools read, kept exactly.
    EXPECT_EQ(toString(Mode::PanelScan), "panel-scan");
    EXPECT_EQ(toString(Verdict::DefectsFound), "defects found");
    EXPECT_EQ(verdictText(std::nullopt), "");
    EXPECT_EQ(toString(Mode::General), "general");
    EXPECT_EQ(modeChoices(), "panel-scan, palpation, capacitive or general");
}

TEST(Vocabulary, APanelPassesOnlyWithoutDefects)
{
    EXPECT_EQ(automaticVerdict(0), Verdict::Pass);
    EXPECT_EQ(automaticVerdict(1), Verdict::DefectsFound);
    EXPECT_EQ(automaticVerdict(40), Verdict::DefectsFound);
}
