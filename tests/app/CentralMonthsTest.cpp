// The central store's samples at a year's scale (issue 56), on the suite's
// real PostgreSQL: a session reaches the server in chunks of 4,096 instants
// (cut at fixed indices, whatever the station committed), with the same
// samples and a checksum both sides agree on; a session sent in the
// station's own chunks before schema 11 is still "already there"; chunks
// and the pyramid are kept by the month their session started in, a month
// made when a station first needs it, detached by `server maintain` (its
// sessions then say where their samples went) and attached again; and a
// store of schema 10, its chunks in plain tables, is upgraded by `server
// init` with every sample kept.
#include "core/storage/SessionStore.h"
#include "core/storage/central/CentralSync.h"
#include "core/storage/central/PgConnection.h"
#include "support/CliRunner.h"
#include "support/FileBytes.h"
#include "support/PostgresServer.h"
#include "support/StationStore.h"

#include <QDateTime>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <memory>

using namespace tactiscope;
using core::storage::SessionStore;
using core::storage::central::ChunkCut;
using core::storage::central::PgConnection;
using core::storage::central::sessionChecksum;
using tactiscope::testing::CliResult;
using tactiscope::testing::fileBytes;
using tactiscope::testing::PostgresServer;
using tactiscope::testing::runCli;

namespace {

// A 30 s panel scan of 2 channels at 500 Hz, as the recorder commits it:
// 125 instants (250 ms) per chunk, the instants [gapFirst, gapEnd) lost.
constexpr double kRate_hz = 500.0;
constexpr std::uint64_t kInstants = 15000;
constexpr std::uint64_t kGapFirst = 5000, kGapEnd = 6000;

std::int64_t writePanel(SessionStore& store, std::uint64_t perCommit, const std::string& startedUtc = {},
                        const std::string& subject = "door-17")
{
    using namespace core;
    const std::vector<ChannelDescriptor> channels{{"a", "", ChannelKind::Strain, ChannelRole::CantileverA},
                                                  {"b", "", ChannelKind::Strain, ChannelRole::CantileverB}};
    storage::SessionMetadata panel;
    panel.mode = Mode::PanelScan;
    panel.subject = subject;
    const auto session = store.beginSession(panel, channels, kRate_hz);
    for (std::uint64_t first = 0; first < kInstants; first += perCommit) {
        const auto count = static_cast<std::size_t>(std::min(perCommit, kInstants - first));
        if (first >= kGapFirst && first < kGapEnd) continue;
        store.appendBlocks(session, std::vector{tactiscope::testing::stationBlock(2, first, count, kRate_hz, 3)});
    }
    store.endSession(session, SessionStatus::Complete);
    if (!startedUtc.empty()) {
        // Recorded at another time (a station sending an old archive).
        auto update = store.database().prepare("UPDATE sessions SET started_utc = ?, ended_utc = ? WHERE id = ?");
        const QDateTime started = QDateTime::fromString(QString::fromStdString(startedUtc), Qt::ISODateWithMs);
        update.bind(1, startedUtc)
            .bind(2, started.addSecs(30).toString(Qt::ISODateWithMs).toStdString())
            .bind(3, session)
            .run();
    }
    return session;
}

std::string uuidOf(SessionStore& store, std::int64_t session)
{
    return store.session(session)->uuid;
}

class CentralMonths : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        s_server = std::make_unique<PostgresServer>();
        PgConnection(s_server->conninfo()).run("CREATE ROLE press_a LOGIN; CREATE ROLE quality LOGIN;");
    }
    static void TearDownTestSuite() { s_server.reset(); }

    void SetUp() override
    {
        static int count = 0;
        m_database = "months" + std::to_string(++count);
        PgConnection(s_server->conninfo()).run("CREATE DATABASE " + m_database);
        const CliResult init = runCli({"server", "init", server()});
        ASSERT_EQ(init.exitCode, 0) << init.err.toStdString();
        PgConnection(s_server->conninfo())
            .run("GRANT tactiscope_station TO press_a; GRANT tactiscope_reviewer TO quality;");
    }

    QString server(const std::string& user = PostgresServer::kOwner) const
    {
        return QString::fromStdString(s_server->conninfo(user, m_database));
    }
    PgConnection owner() const { return PgConnection(s_server->conninfo(PostgresServer::kOwner, m_database)); }
    CliResult sync(const QString& station) const
    {
        return runCli({"sync", "--db", station, "--server", server("press_a")});
    }
    CliResult exported(const QString& db, const std::string& uuid, const QString& path) const
    {
        return runCli(
            {"sessions", "--db", db, "export", QString::fromStdString(uuid), "--format", "csv", "--output", path});
    }
    // The session exports to the same bytes from the station and from the
    // server, as the reviewer reads it.
    void expectSameSamples(const std::string& uuid) const
    {
        const QString here = m_dir.filePath("station.csv"), there = m_dir.filePath("central.csv");
        ASSERT_EQ(exported(m_station, uuid, here).exitCode, 0);
        const CliResult central = exported(server("quality"), uuid, there);
        ASSERT_EQ(central.exitCode, 0) << central.err.toStdString();
        const std::string bytes = fileBytes(here.toStdString());
        EXPECT_GT(bytes.size(), 100000U);
        EXPECT_TRUE(bytes == fileBytes(there.toStdString())) << uuid;
    }

    static inline std::unique_ptr<PostgresServer> s_server;
    QTemporaryDir m_dir;
    QString m_station = m_dir.filePath("station.tactiscope");
    std::string m_database;
};

}  // namespace

TEST_F(CentralMonths, ASessionArrivesInChunksOf4096InstantsCutAtFixedIndicesWithItsSamplesIntact)
{
    SessionStore store(m_station.toStdString());
    const auto session = writePanel(store, 125);
    const std::string uuid = uuidOf(store, session);
    ASSERT_EQ(sync(m_station).exitCode, 0);

    // Cut at every multiple of 4 096 and where the samples stop at the gap:
    // [0, 4096), [4096, 5000), [6000, 8192), [8192, 12288), [12288, 15000).
    const auto chunks = owner().query("SELECT first_index, count FROM chunks c JOIN sessions s ON s.id = c.session_id "
                                      "WHERE s.uuid = $1 ORDER BY first_index",
                                      {uuid});
    std::vector<std::pair<std::string, std::string>> cuts;
    for (int i = 0; i < chunks.rows(); ++i) cuts.emplace_back(chunks.text(i, 0), chunks.text(i, 1));
    const std::vector<std::pair<std::string, std::string>> expected{
        {"0", "4096"}, {"4096", "904"}, {"6000", "2192"}, {"8192", "4096"}, {"12288", "2712"}};
    EXPECT_EQ(cuts, expected);
    auto stored = store.database().prepare("SELECT count(*) FROM chunks WHERE session_id = ?");
    stored.bind(1, session);
    ASSERT_TRUE(stored.step());
    EXPECT_EQ(stored.int64(0), 112);  // 120 commits, eight of them lost
    EXPECT_GE(stored.int64(0), 16 * chunks.rows());
    expectSameSamples(uuid);
    // What a list shows of it, kept in its row by the server as it was
    // made complete: 15 000 instants at 500 Hz, no live event, no part.
    const auto listed = owner().query(
        "SELECT listed_samples, listed_events, listed_rate_hz, listed_parts FROM sessions WHERE uuid = $1", {uuid});
    EXPECT_EQ(listed.text(0, 0), "15000");
    EXPECT_EQ(listed.text(0, 1), "0");
    EXPECT_EQ(listed.text(0, 2), "500");
    EXPECT_EQ(listed.text(0, 3), "0");
}

TEST_F(CentralMonths, TheChecksumIsTheSameWhateverCommitsTheStationMade)
{
    SessionStore a(m_dir.filePath("a.tactiscope").toStdString()), b(m_dir.filePath("b.tactiscope").toStdString());
    const auto small = writePanel(a, 125), large = writePanel(b, 1000);
    EXPECT_EQ(sessionChecksum(a, small), sessionChecksum(b, large));
    EXPECT_NE(sessionChecksum(a, small, ChunkCut::AsStored), sessionChecksum(b, large, ChunkCut::AsStored));
}

// A session sent before schema 11 holds the station's own chunks, and the
// checksum over them: the next sync finds it there, neither refused as
// "other samples" nor sent again.
TEST_F(CentralMonths, ASessionSentInTheStationsOwnChunksBeforeIsAlreadyThere)
{
    SessionStore store(m_station.toStdString());
    const auto session = writePanel(store, 125);
    ASSERT_EQ(sync(m_station).exitCode, 0);
    owner().query("UPDATE sessions SET checksum = $1 WHERE uuid = $2",
                  {sessionChecksum(store, session, ChunkCut::AsStored), uuidOf(store, session)});
    const CliResult again = sync(m_station);
    EXPECT_EQ(again.exitCode, 0) << again.err.toStdString();
    EXPECT_TRUE(again.out.contains("1 already there")) << again.out.toStdString();
}

TEST_F(CentralMonths, AnOldMonthIsMadeWhenNeededDetachedAndAttachedAgain)
{
    // Init made this month and the next two; maintain the next three.
    const QString thisMonth = QDateTime::currentDateTimeUtc().toString("yyyy-MM");
    const QString inThree = QDateTime::currentDateTimeUtc().addMonths(3).toString("yyyy-MM");
    const auto tables = [this](const QString& month) {
        return owner()
            .query("SELECT count(*) FROM pg_inherits WHERE inhrelid IN (to_regclass($1), to_regclass($2))",
                   {"months.chunks_" + QString(month).replace('-', '_').toStdString(),
                    "months.lod_" + QString(month).replace('-', '_').toStdString()})
            .text(0, 0);
    };
    EXPECT_EQ(tables(thisMonth), "2");
    EXPECT_EQ(tables(inThree), "0");
    const CliResult maintain = runCli({"server", "maintain", server(), "--months-ahead", "3"});
    ASSERT_EQ(maintain.exitCode, 0) << maintain.err.toStdString();
    EXPECT_TRUE(maintain.out.contains("months made: " + inThree)) << maintain.out.toStdString();
    EXPECT_EQ(tables(inThree), "2");
    EXPECT_TRUE(runCli({"server", "maintain", server()}).out.contains("months made: none"));

    // A station's archive of March 2025: its month made as it is sent.
    SessionStore store(m_station.toStdString());
    const std::string march = uuidOf(store, writePanel(store, 125, "2025-03-14T09:00:00.000Z", "old-door"));
    ASSERT_EQ(sync(m_station).exitCode, 0);
    EXPECT_EQ(tables("2025-03"), "2");
    EXPECT_EQ(owner().query("SELECT count(*) FROM months.chunks_2025_03").text(0, 0), "5");
    EXPECT_EQ(
        owner().query("SELECT count(*) FROM months.chunks_" + thisMonth.toStdString().replace(4, 1, "_")).text(0, 0),
        "0");

    // Detached: listed still, its samples said to be elsewhere.
    const CliResult tooLate = runCli({"server", "maintain", server(), "--detach-before", inThree});
    EXPECT_EQ(tooLate.exitCode, 2);
    EXPECT_TRUE(tooLate.err.contains("still being sent")) << tooLate.err.toStdString();
    const CliResult both =
        runCli({"server", "maintain", server(), "--detach-before", "2025-07", "--attach", "2025-03"});
    EXPECT_EQ(both.exitCode, 2);
    EXPECT_TRUE(both.err.contains("contradict")) << both.err.toStdString();
    const CliResult notOwner = runCli({"server", "maintain", server("quality")});
    EXPECT_EQ(notOwner.exitCode, 1);
    EXPECT_TRUE(notOwner.err.contains("the login quality does not own the central store"))
        << notOwner.err.toStdString();
    const CliResult detach = runCli({"server", "maintain", server(), "--detach-before", "2025-04"});
    ASSERT_EQ(detach.exitCode, 0) << detach.err.toStdString();
    EXPECT_TRUE(detach.out.contains("months detached: 2025-03\n")) << detach.out.toStdString();
    EXPECT_TRUE(detach.out.contains("months.chunks_2025_03")) << detach.out.toStdString();
    EXPECT_TRUE(detach.out.contains("2025-03 (detached), ")) << detach.out.toStdString();
    EXPECT_EQ(tables("2025-03"), "0");
    const CliResult list = runCli({"sessions", "--db", server("quality"), "list"});
    EXPECT_TRUE(list.out.contains("old-door")) << list.out.toStdString();
    EXPECT_TRUE(list.out.contains("press_a")) << list.out.toStdString();  // the station column
    // Its fields, records and verdict trail read as ever; a verdict is given.
    const CliResult shown = runCli({"sessions", "--db", server("quality"), "show", QString::fromStdString(march)});
    EXPECT_EQ(shown.exitCode, 0) << shown.err.toStdString();
    EXPECT_TRUE(shown.out.contains("old-door")) << shown.out.toStdString();
    const CliResult decided = runCli(
        {"sessions", "--db", server("quality"), "verdict", QString::fromStdString(march), "pass", "--by", "Grace"});
    EXPECT_EQ(decided.exitCode, 0) << decided.err.toStdString();
    const CliResult show = runCli({"sessions", "--db", server("quality"), "export", QString::fromStdString(march),
                                   "--format", "csv", "--output", m_dir.filePath("march.csv")});
    EXPECT_EQ(show.exitCode, 2);
    EXPECT_TRUE(show.err.contains("the month it started in (2025-03) was detached on"));
    EXPECT_TRUE(show.err.contains("server maintain --attach 2025-03")) << show.err.toStdString();

    // Another session of that month waits for it, named.
    writePanel(store, 125, "2025-03-20T09:00:00.000Z", "late-door");
    const CliResult late = sync(m_station);
    EXPECT_EQ(late.exitCode, 1);
    EXPECT_TRUE(late.err.contains("the month 2025-03 was detached from the central store")) << late.err.toStdString();
    EXPECT_TRUE(late.err.contains("this one waits")) << late.err.toStdString();
    EXPECT_FALSE(late.err.contains("CONTEXT")) << late.err.toStdString();  // no server internals

    // Attached again: both read, and the late one goes.
    const CliResult attach = runCli({"server", "maintain", server(), "--attach", "2025-03"});
    ASSERT_EQ(attach.exitCode, 0) << attach.err.toStdString();
    EXPECT_EQ(tables("2025-03"), "2");
    const CliResult after = sync(m_station);
    EXPECT_EQ(after.exitCode, 0) << after.err.toStdString();
    expectSameSamples(march);
    const CliResult again = runCli({"server", "maintain", server(), "--attach", "2025-03"});
    EXPECT_EQ(again.exitCode, 0);
    EXPECT_TRUE(again.out.contains("2025-03 is in the store already")) << again.out.toStdString();
    EXPECT_EQ(runCli({"server", "maintain", server(), "--attach", "2024-02"}).exitCode, 1);  // never held
    EXPECT_EQ(runCli({"server", "maintain", server(), "--attach", "2025-13"}).exitCode, 2);
}

// A store made before schema 11 held chunks and the pyramid in plain
// tables: made again here as it was (the rows moved back into plain
// tables, schema 10), then upgraded by `server init`.
TEST_F(CentralMonths, AStoreOfSchema10IsUpgradedWithEverySampleKept)
{
    SessionStore store(m_station.toStdString());
    const std::string uuid = uuidOf(store, writePanel(store, 125, "2025-07-01T10:00:00.000Z"));
    ASSERT_EQ(sync(m_station).exitCode, 0);
    PgConnection db = owner();
    db.run("BEGIN;"
           "CREATE TABLE chunks_10 AS SELECT session_id, first_index, first_time_s, count, samples FROM chunks;"
           "CREATE TABLE lod_10 AS SELECT session_id, channel, level, first_bucket, count, buckets FROM lod;"
           "DROP TABLE chunks, lod CASCADE;"
           "ALTER TABLE chunks_10 RENAME TO chunks; ALTER TABLE lod_10 RENAME TO lod;"
           "ALTER TABLE chunks ADD PRIMARY KEY (session_id, first_index);"
           "ALTER TABLE lod ADD PRIMARY KEY (session_id, channel, level, first_bucket);"
           "DROP SCHEMA months CASCADE; UPDATE schema_version SET version = 10; COMMIT;");
    const CliResult refused = runCli({"sessions", "--db", server("quality"), "list"});
    EXPECT_EQ(refused.exitCode, 1);
    EXPECT_TRUE(refused.err.contains("server init")) << refused.err.toStdString();

    const CliResult init = runCli({"server", "init", server()});
    ASSERT_EQ(init.exitCode, 0) << init.err.toStdString();
    EXPECT_EQ(db.query("SELECT relkind FROM pg_class WHERE oid = 'chunks'::regclass").text(0, 0), "p");
    EXPECT_EQ(db.query("SELECT count(*) FROM months.chunks_2025_07").text(0, 0), "5");
    EXPECT_EQ(db.query("SELECT count(*) FROM months.lod_2025_07").text(0, 0),
              db.query("SELECT count(*) FROM lod").text(0, 0));
    EXPECT_NE(db.query("SELECT count(*) FROM lod").text(0, 0), "0");
    expectSameSamples(uuid);
    const CliResult again = sync(m_station);
    EXPECT_TRUE(again.out.contains("1 already there")) << again.out.toStdString();
}

// Two stations at once, each first to need a month not made yet: the
// server makes it once (one maker at a time), and both sessions arrive.
TEST_F(CentralMonths, TwoStationsNeedingTheSameNewMonthAtOnceBothSend)
{
    PgConnection(s_server->conninfo())
        .run("DO $$ BEGIN IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'press_b') THEN "
             "CREATE ROLE press_b LOGIN IN ROLE tactiscope_station; END IF; END $$;");
    const QString other = m_dir.filePath("other.tactiscope");
    for (const QString& path : {m_station, other}) {
        SessionStore store(path.toStdString());
        writePanel(store, 125, "2024-02-10T09:00:00.000Z", "february");
    }
    QProcess first, second;
    first.start(QStringLiteral(TACTISCOPE_CLI), {"sync", "--db", m_station, "--server", server("press_a")});
    second.start(QStringLiteral(TACTISCOPE_CLI), {"sync", "--db", other, "--server", server("press_b")});
    for (QProcess* sync : {&first, &second}) {
        ASSERT_TRUE(sync->waitForFinished(60000));
        EXPECT_EQ(sync->exitCode(), 0) << sync->readAllStandardError().toStdString();
    }
    EXPECT_EQ(owner().query("SELECT count(DISTINCT session_id) FROM months.chunks_2024_02").text(0, 0), "2");
    EXPECT_EQ(
        owner().query("SELECT count(*) FROM pg_inherits WHERE inhrelid = 'months.chunks_2024_02'::regclass").text(0, 0),
        "1");
}
