// `tactiscope-cli server init` against a real PostgreSQL server started for
// the suite: the schema and both roles made, a second run changing nothing,
// an unreachable server exiting 1 with its reason; and the rights it sets,
// tried as the roles themselves: a station adds and reads its own sessions
// only and can neither change nor delete another's; a reviewer sees only
// finished sessions and adds verdicts, never deletes.
#include "core/storage/central/CentralSchema.h"
#include "core/storage/central/PgConnection.h"
#include "support/CliRunner.h"
#include "support/PostgresServer.h"

#include <QCryptographicHash>

#include <gtest/gtest.h>

#include <memory>

using tactiscope::core::storage::StorageError;
using tactiscope::core::storage::central::PgConnection;
using tactiscope::testing::CliResult;
using tactiscope::testing::PostgresServer;
using tactiscope::testing::runCli;

namespace {

class ServerCli : public ::testing::Test {
protected:
    static void SetUpTestSuite() { s_server = std::make_unique<PostgresServer>(); }
    static void TearDownTestSuite() { s_server.reset(); }
    static QString owner() { return QString::fromStdString(s_server->conninfo()); }

    // A row of a session as `station` adds it; its id.
    // A session still arriving, as the sync begins one.
    static std::string addSession(PgConnection& as, const std::string& uuid)
    {
        return as
            .query("INSERT INTO sessions (uuid, mode, started_utc, status, app_version) "
                   "VALUES ($1, 'panel-scan', '2026-11-24T10:00:00.000Z', 'complete', 'test') RETURNING id",
                   {uuid})
            .text(0, 0);
    }

    static inline std::unique_ptr<PostgresServer> s_server;
};

// True when `statement` is refused by the server.
bool refused(PgConnection& as, const std::string& statement, std::vector<std::optional<std::string>> parameters = {})
{
    try {
        as.query(statement, parameters);
        return false;
    } catch (const StorageError&) {
        return true;
    }
}

}  // namespace

TEST_F(ServerCli, InitMakesTheSchemaAndRolesAndASecondRunChangesNothing)
{
    for (int run = 0; run < 2; ++run) {
        const CliResult result = runCli({"server", "init", owner()});
        ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
        EXPECT_TRUE(result.out.startsWith(QStringLiteral("central store ready"))) << result.out.toStdString();
    }
    PgConnection db(s_server->conninfo());
    EXPECT_EQ(db.query("SELECT count(*) FROM pg_roles WHERE rolname IN ('tactiscope_station', 'tactiscope_reviewer')")
                  .text(0, 0),
              "2");
    EXPECT_EQ(db.query("SELECT version FROM schema_version").text(0, 0),
              std::to_string(tactiscope::core::storage::central::kCentralSchemaVersion));
    for (const char* table : {"sessions", "channels", "chunks", "gaps", "lod", "events", "readings", "annotations",
                              "verdicts", "zeros", "calibrations", "session_calibrations"})
        EXPECT_EQ(db.query("SELECT count(*) FROM pg_tables WHERE tablename = $1", {std::string(table)}).text(0, 0), "1")
            << table;
}

TEST_F(ServerCli, AnUnreachableServerExitsOneWithTheReason)
{
    const CliResult result = runCli({"server", "init", "host=/nonexistent-socket-dir dbname=postgres"});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_TRUE(result.err.contains(QStringLiteral("cannot reach the central store"))) << result.err.toStdString();
    EXPECT_EQ(runCli({"server", "init"}).exitCode, 2);
}

TEST_F(ServerCli, AStationKeepsToItsOwnRowsAndAReviewerOnlyReadsAndDecides)
{
    ASSERT_EQ(runCli({"server", "init", owner()}).exitCode, 0);
    PgConnection db(s_server->conninfo());
    db.run("DO $$ BEGIN "
           "IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'press_a') THEN "
           "CREATE ROLE press_a LOGIN IN ROLE tactiscope_station; END IF; "
           "IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'press_b') THEN "
           "CREATE ROLE press_b LOGIN IN ROLE tactiscope_station; END IF; "
           "IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'quality') THEN "
           "CREATE ROLE quality LOGIN IN ROLE tactiscope_reviewer; END IF; END $$;");
    PgConnection a(s_server->conninfo("press_a")), b(s_server->conninfo("press_b")),
        reviewer(s_server->conninfo("quality"));

    // One sent whole (its channel, a chunk, then marked complete as the
    // sync's last step), one still arriving.
    const std::string finished = addSession(a, "11111111-1111-4111-8111-111111111111");
    a.query("INSERT INTO channels (session_id, position, name, unit, kind, sample_rate_hz) VALUES ($1, 0, 'a', '', "
            "'strain', 1000)",
            {finished});
    // Its month made, as the sync asks before it sends (CentralSchema's month_ready).
    a.query("SELECT month_ready(started_utc) FROM sessions WHERE id = $1", {finished});
    a.query("INSERT INTO chunks (session_id, session_month, first_index, first_time_s, count, samples) VALUES ($1, "
            "(SELECT session_month(started_utc) FROM sessions WHERE id = $1::bigint), 0, 0, 1, "
            "'\\x0000803f')",
            {finished});
    // Its checksum (CentralClaimsTest): the md5 of "0:1:" and its bytes' md5.
    const std::string checksum =
        QCryptographicHash::hash(
            "0:1:" + QCryptographicHash::hash(QByteArray::fromHex("0000803f"), QCryptographicHash::Md5).toHex(),
            QCryptographicHash::Md5)
            .toHex()
            .toStdString();
    a.query("UPDATE sessions SET complete = true, checksum = $1 WHERE id = $2", {checksum, finished});
    addSession(a, "22222222-2222-4222-8222-222222222222");
    EXPECT_TRUE(refused(a, "INSERT INTO sessions (uuid, mode, started_utc, status, app_version, complete) VALUES "
                           "('44444444-4444-4444-8444-444444444444', 'panel-scan', '2026-11-24T10:00:00.000Z', "
                           "'complete', 'test', true)"))
        << "a session is complete only by the sync's last step, after its rows";
    EXPECT_EQ(a.query("SELECT station FROM sessions WHERE id = $1", {finished}).text(0, 0), "press_a");
    EXPECT_EQ(a.query("SELECT count(*) FROM sessions").text(0, 0), "2");

    // Another station: sees none of them, changes and deletes nothing, and
    // cannot add rows as press_a or into press_a's session.
    EXPECT_EQ(b.query("SELECT count(*) FROM sessions").text(0, 0), "0");
    EXPECT_EQ(b.query("SELECT count(*) FROM chunks").text(0, 0), "0");
    EXPECT_TRUE(refused(b, "DELETE FROM sessions WHERE id = $1", {finished}));
    EXPECT_TRUE(refused(b, "UPDATE sessions SET subject = 'x' WHERE id = $1", {finished}));
    EXPECT_EQ(b.query("UPDATE sessions SET complete = false WHERE id = $1 RETURNING id", {finished}).rows(), 0);
    EXPECT_TRUE(refused(b, "INSERT INTO sessions (uuid, station, mode, started_utc, status, app_version) "
                           "VALUES ('33333333-3333-4333-8333-333333333333', 'press_a', 'panel-scan', 'x', 'complete', "
                           "'test')"));
    EXPECT_TRUE(
        refused(b, "INSERT INTO events (session_id, kind, start_s, end_s) VALUES ($1, 'marker', 0, 0)", {finished}));
    // The station itself deletes nothing either: only the owner does.
    EXPECT_TRUE(refused(a, "DELETE FROM sessions WHERE id = $1", {finished}));

    // The reviewer: finished sessions only, adds a verdict, deletes nothing.
    EXPECT_EQ(reviewer.query("SELECT count(*) FROM sessions").text(0, 0), "1");
    EXPECT_EQ(reviewer.query("SELECT count(*) FROM chunks").text(0, 0), "1");
    reviewer.query("INSERT INTO verdicts (session_id, role, verdict, decided_by, decided_utc) "
                   "VALUES ($1, 'reviewer', 'pass', 'Grace', '2026-11-24T11:00:00Z')",
                   {finished});
    EXPECT_TRUE(refused(reviewer, "DELETE FROM sessions WHERE id = $1", {finished}));
    EXPECT_TRUE(refused(reviewer, "DELETE FROM chunks"));

    // The owner deletes.
    EXPECT_EQ(db.query("DELETE FROM sessions WHERE id = $1 RETURNING id", {finished}).rows(), 1);
    EXPECT_EQ(db.query("SELECT count(*) FROM chunks").text(0, 0), "0");
}
