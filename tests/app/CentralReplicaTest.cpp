// A reviewer on a read replica of the central store (issue 56), on the
// suite's real PostgreSQL and a hot standby of it (pg_basebackup, then
// streaming): browsing, reviewing, exporting and reporting read the
// replica; a verdict asked of the replica alone says it needs the primary
// and how to name it; an address naming the replica, then the primary,
// reads the replica and writes the primary, and the verdict is read back
// at once; a station's sync to the replica says it sends to the primary.
#include "core/storage/central/PgConnection.h"
#include "support/CliRunner.h"
#include "support/PostgresServer.h"
#include "support/StationStore.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <thread>

using namespace tactiscope;
using core::storage::central::PgConnection;
using tactiscope::testing::CliResult;
using tactiscope::testing::PostgresServer;
using tactiscope::testing::runCli;

namespace {

class CentralReplica : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        s_primary = tactiscope::testing::centralStoreServer(
            {{"press_a", "tactiscope_station"}, {"quality", "tactiscope_reviewer"}});
        s_dir = std::make_unique<QTemporaryDir>();
        s_station = s_dir->filePath("press-a.tactiscope");
        tactiscope::testing::writeStationStore(s_station.toStdString());
        const CliResult sync =
            runCli({"sync", "--db", s_station, "--server", QString::fromStdString(s_primary->conninfo("press_a"))});
        ASSERT_EQ(sync.exitCode, 0) << sync.err.toStdString();
        s_standby = s_primary->standby();
        // Caught up once the replica has replayed the primary's last write.
        PgConnection primary(s_primary->conninfo()), standby(s_standby->conninfo());
        const std::string written = primary.query("SELECT pg_current_wal_lsn()::text").text(0, 0);
        for (int wait = 0; wait < 500; ++wait) {
            if (standby.query("SELECT pg_last_wal_replay_lsn() >= $1::pg_lsn", {written}).text(0, 0) == "t") break;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
    }
    static void TearDownTestSuite()
    {
        s_standby.reset();
        s_primary.reset();
        s_dir.reset();
    }

    // The replica alone, or the replica then the primary (libpq picks the
    // standby to read).
    static QString replica() { return QString::fromStdString(s_standby->conninfo("quality")); }
    static QString replicaThenPrimary()
    {
        return QString::fromStdString("host=" + s_standby->folder() + "," + s_primary->folder() +
                                      " dbname=postgres user=quality target_session_attrs=prefer-standby");
    }
    static QString firstUuid(const QString& db)
    {
        const CliResult list = runCli({"sessions", "--db", db, "list", "--json"});
        EXPECT_EQ(list.exitCode, 0) << list.err.toStdString();
        const auto sessions = QJsonDocument::fromJson(list.out.toUtf8()).array();
        EXPECT_EQ(sessions.size(), 3);
        return sessions.isEmpty() ? QString() : sessions.last().toObject()["uuid"].toString();
    }

    static inline std::unique_ptr<PostgresServer> s_primary, s_standby;
    static inline std::unique_ptr<QTemporaryDir> s_dir;
    static inline QString s_station;
};

}  // namespace

TEST_F(CentralReplica, AReviewerBrowsesReviewsExportsAndReportsOnTheReplica)
{
    PgConnection standby(s_standby->conninfo());
    ASSERT_EQ(standby.query("SELECT pg_is_in_recovery()").text(0, 0), "t");
    const QString uuid = firstUuid(replica());
    ASSERT_FALSE(uuid.isEmpty());
    const CliResult show = runCli({"sessions", "--db", replica(), "show", uuid});
    EXPECT_EQ(show.exitCode, 0) << show.err.toStdString();
    EXPECT_TRUE(show.out.contains(uuid));
    const CliResult last = runCli({"sessions", "--db", replica(), "show", "last"});
    EXPECT_EQ(last.exitCode, 0) << last.err.toStdString();
    const QString csv = s_dir->filePath("replica.csv");
    const CliResult exported =
        runCli({"sessions", "--db", replica(), "export", uuid, "--format", "csv", "--output", csv});
    EXPECT_EQ(exported.exitCode, 0) << exported.err.toStdString();
    EXPECT_GT(QFileInfo(csv).size(), 1000);
    const QString pdf = s_dir->filePath("replica.pdf");
    const CliResult report = runCli({"report", "--db", replica(), "--session", uuid, "--output", pdf});
    EXPECT_EQ(report.exitCode, 0) << report.err.toStdString();
    EXPECT_GT(QFileInfo(pdf).size(), 1000);
}

TEST_F(CentralReplica, AVerdictOnTheReplicaAloneSaysItNeedsThePrimaryAndHowToNameIt)
{
    const QString uuid = firstUuid(replica());
    const CliResult verdict =
        runCli({"sessions", "--db", replica(), "verdict", uuid, "pass", "--by", "Grace", "--note", "looked again"});
    EXPECT_EQ(verdict.exitCode, 1);
    EXPECT_TRUE(verdict.err.contains("is a read-only replica of the central store")) << verdict.err.toStdString();
    EXPECT_TRUE(verdict.err.contains("target_session_attrs=prefer-standby")) << verdict.err.toStdString();
    EXPECT_FALSE(verdict.err.contains("cannot reach")) << verdict.err.toStdString();  // it reached the replica
    EXPECT_FALSE(verdict.err.contains("read-only transaction")) << verdict.err.toStdString();

    const CliResult sync =
        runCli({"sync", "--db", s_station, "--server", QString::fromStdString(s_standby->conninfo("press_a"))});
    EXPECT_EQ(sync.exitCode, 1);
    EXPECT_TRUE(sync.err.contains("a station sends its sessions to the primary")) << sync.err.toStdString();
    // Nor does the owner keep the store there.
    const CliResult maintain =
        runCli({"server", "maintain", QString::fromStdString(s_standby->conninfo(PostgresServer::kOwner))});
    EXPECT_EQ(maintain.exitCode, 1);
    EXPECT_TRUE(maintain.err.contains("run server on the primary")) << maintain.err.toStdString();
}

TEST_F(CentralReplica, AnAddressNamingThePrimaryTooReadsTheReplicaAndWritesThePrimary)
{
    const QString uuid = firstUuid(replicaThenPrimary());
    const CliResult verdict = runCli({"sessions", "--db", replicaThenPrimary(), "verdict", uuid, "defects-found",
                                      "--by", "Grace", "--note", "a dent at 0.3 s"});
    ASSERT_EQ(verdict.exitCode, 0) << verdict.err.toStdString();
    PgConnection primary(s_primary->conninfo());
    EXPECT_EQ(primary
                  .query("SELECT count(*) FROM verdicts v JOIN sessions s ON s.id = v.session_id WHERE s.uuid = $1 "
                         "AND v.role = 'reviewer' AND v.decided_by = 'Grace'",
                         {uuid.toStdString()})
                  .text(0, 0),
              "1");
    // Read back from the replica at once, the session's verdict with it.
    const CliResult show = runCli({"sessions", "--db", replica(), "show", uuid});
    EXPECT_TRUE(show.out.contains("a dent at 0.3 s")) << show.out.toStdString();
    EXPECT_TRUE(show.out.contains("defects found")) << show.out.toStdString();
}
