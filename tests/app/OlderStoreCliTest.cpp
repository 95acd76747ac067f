// An older store opens, whatever a plain `sqlite3` left in it: a version-4
// store made here table by table, with one `events` row whose session was
// deleted by hand (SQLite keeps foreign keys off unless asked, so the row
// stays). Before, the upgrade refused it ("would leave rows without their
// session") and every read-only reader refused it as "older", naming no
// command: no command read it. Now a reader reads it through a private
// copy brought up to date, leaving the file as it was, and says which
// command updates it; `sessions upgrade` does, leaving the orphan out with
// a note of how many rows of what.
#include "core/storage/Database.h"
#include "core/storage/Schema.h"
#include "support/CliRunner.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace tactiscope::core::storage;
using tactiscope::testing::CliResult;
using tactiscope::testing::runCli;

namespace {

// The store version in the file's header (PRAGMA user_version), read
// from the bytes: offset 60, big-endian.
int versionInHeader(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return -1;
    const QByteArray header = file.read(64);
    int version = 0;
    for (int i = 60; i < 64; ++i) version = version * 256 + static_cast<unsigned char>(header[i]);
    return version;
}

QByteArray contentOf(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

class OlderStoreCli : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_TRUE(m_dir.isValid());
        Database db(m_path.toStdString(), Database::Access::ReadWrite);
        ASSERT_EQ(prepareSchema(db, 4), 0);
        db.exec("PRAGMA journal_mode = DELETE");  // one file, as a copied store is
        db.exec("INSERT INTO sessions (id, uuid, mode, subject, started_utc, ended_utc, status, verdict, app_version, "
                "calibrations_json) VALUES "
                "(1, '6a0e1d9c-1f0e-4c9a-9d55-6d0b7a1c2e01', 'panel-scan', 'door-17', '2026-01-01T00:00:00.000Z', "
                "'2026-01-01T00:01:00.000Z', 'complete', 'pass', '0.9', ''),"
                "(2, '6a0e1d9c-1f0e-4c9a-9d55-6d0b7a1c2e02', 'panel-scan', 'door-18', '2026-01-02T00:00:00.000Z', "
                "'2026-01-02T00:01:00.000Z', 'complete', 'pass', '0.9', '')");
        db.exec("INSERT INTO channels VALUES (1, 0, 'a', '', 'strain', 500), (2, 0, 'a', '', 'strain', 500)");
        db.exec("INSERT INTO events (session_id, kind, start_s, end_s, direction) VALUES (1, 'defect', 1, 1.1, 1), "
                "(2, 'defect', 2, 2.1, -1)");
        // The session deleted as `sqlite3` does: foreign keys off, its
        // event left behind.
        db.exec("PRAGMA foreign_keys = OFF");
        db.exec("DELETE FROM channels WHERE session_id = 2");
        db.exec("DELETE FROM sessions WHERE id = 2");
    }

    CliResult sessions(const QStringList& arguments)
    {
        return runCli(QStringList{"sessions", "--db", m_path} + arguments);
    }

    QTemporaryDir m_dir;
    QString m_path = m_dir.filePath("v4.tactiscope");
};

}  // namespace

TEST_F(OlderStoreCli, AReaderReadsItThroughAPrivateUpdatedCopyAndSaysHowToUpdateIt)
{
    const QByteArray before = contentOf(m_path);
    ASSERT_EQ(versionInHeader(m_path), 4);
    const CliResult list = sessions({"list"});
    ASSERT_EQ(list.exitCode, 0) << list.err.toStdString();
    EXPECT_TRUE(list.out.contains("door-17") && !list.out.contains("door-18")) << list.out.toStdString();
    EXPECT_TRUE(list.err.contains("has an older store version (4): read through a private copy brought up to "
                                  "version " +
                                  QString::number(kSchemaVersion)))
        << list.err.toStdString();
    EXPECT_TRUE(list.err.contains("`tactiscope-cli sessions --db " + m_path + " upgrade` updates the store itself"))
        << list.err.toStdString();
    EXPECT_TRUE(list.err.contains("left out 1 events row without their session")) << list.err.toStdString();
    const CliResult show = sessions({"show", "last"});
    EXPECT_EQ(show.exitCode, 0) << show.err.toStdString();
    EXPECT_TRUE(show.out.contains("door-17")) << show.out.toStdString();
    // The store itself is as it was: same bytes, still version 4.
    EXPECT_EQ(contentOf(m_path), before);
}

TEST_F(OlderStoreCli, UpgradeUpdatesItInPlaceLeavingTheOrphanRowOutWithANote)
{
    const CliResult upgrade = sessions({"upgrade"});
    ASSERT_EQ(upgrade.exitCode, 0) << upgrade.err.toStdString();
    EXPECT_EQ(upgrade.out,
              m_path + ": store version " + QString::number(kSchemaVersion) + " (updated from version 4)\n");
    EXPECT_TRUE(upgrade.err.contains("updating it from store version 4 left out 1 events row without their session"))
        << upgrade.err.toStdString();
    EXPECT_EQ(versionInHeader(m_path), kSchemaVersion);
    {
        Database db(m_path.toStdString(), Database::Access::ReadOnly);
        auto events = db.prepare("SELECT session_id FROM events");
        ASSERT_TRUE(events.step());
        EXPECT_EQ(events.int64(0), 1);  // the session's own event kept
        EXPECT_FALSE(events.step());
    }
    const CliResult again = sessions({"upgrade"});
    EXPECT_EQ(again.out, m_path + ": store version " + QString::number(kSchemaVersion) + ", already up to date\n");
    EXPECT_TRUE(again.err.isEmpty()) << again.err.toStdString();
    const CliResult list = sessions({"list"});
    EXPECT_EQ(list.exitCode, 0);
    EXPECT_TRUE(list.err.isEmpty()) << list.err.toStdString();
    EXPECT_TRUE(list.out.contains("door-17"));
}

TEST_F(OlderStoreCli, UpgradeOfACentralStoreNamesServerInit)
{
    const CliResult r = runCli({"sessions", "--db", "host=/nonexistent dbname=x", "upgrade"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(r.err.contains("server init")) << r.err.toStdString();
}
