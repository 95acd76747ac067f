// A central-store connection heals (issue 37): the suite's PostgreSQL is
// killed and started again under an open connection. The next statement
// connects again by itself, with the connection's settings (a reviewer's
// read-only stays read-only); a server still down is tried three times and
// then named as unreachable; a transaction or a sync's lock cut by the
// outage fails for its holder instead of going on, unnoticed, on a new
// connection that holds neither.
#include "core/storage/SessionStore.h"
#include "core/storage/central/CentralStore.h"
#include "core/storage/central/CentralSync.h"
#include "support/PostgresServer.h"
#include "support/StationStore.h"
#include "support/TempPath.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace tactiscope;
using core::storage::StorageError;
using core::storage::central::CentralStore;
using core::storage::central::PgConnection;
using core::storage::central::PgTransaction;
using tactiscope::testing::PostgresServer;

namespace {

class CentralReconnect : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        s_server = tactiscope::testing::centralStoreServer(
            {{"press_a", "tactiscope_station"}, {"quality", "tactiscope_reviewer"}});
        tactiscope::testing::writeStationStore(s_station.string());
        core::storage::SessionStore local(s_station.string());
        CentralStore central(s_server->conninfo("press_a"));
        ASSERT_EQ(core::storage::central::syncToCentral(local, central).sent, 3);
    }
    static void TearDownTestSuite()
    {
        s_server.reset();
        std::filesystem::remove(s_station);
    }
    static void restart()
    {
        s_server->crash();
        s_server->start();
    }

    static inline std::unique_ptr<PostgresServer> s_server;
    static inline std::filesystem::path s_station = tactiscope::testing::uniqueTempPath("station.tactiscope");
};

}  // namespace

TEST_F(CentralReconnect, TheNextReadAfterARestartConnectsAgainAndStaysReadOnly)
{
    CentralStore reviewer(s_server->conninfo("quality"), core::storage::Database::Access::ReadOnly);
    ASSERT_EQ(reviewer.sessions().size(), 3U);
    restart();
    EXPECT_EQ(reviewer.sessions().size(), 3U);  // before: "server closed the connection unexpectedly" for ever
    EXPECT_EQ(reviewer.connection().reconnects(), 1);
    try {
        reviewer.connection().query("INSERT INTO annotations (session_id, time_s, text, created_utc, modified_utc) "
                                    "SELECT min(id), 0, 'x', 'now', 'now' FROM sessions");
        ADD_FAILURE() << "a read-only connection wrote after reconnecting";
    } catch (const StorageError& e) {
        EXPECT_NE(std::string(e.what()).find("read-only"), std::string::npos) << e.what();
    }
}

TEST_F(CentralReconnect, AServerStillDownIsNamedAndReachedOnceItIsBack)
{
    CentralStore reviewer(s_server->conninfo("quality"));
    s_server->crash();
    // The first read may still find the old connection (its backend dies a
    // moment after the postmaster): "closed unexpectedly"; the next tries
    // to connect again and cannot. Both say the server is out of reach.
    for (int read = 0; read < 2; ++read) EXPECT_THROW(reviewer.sessions(), core::storage::central::CentralUnreachable);
    try {
        reviewer.sessions();
    } catch (const StorageError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot reach the central store"), std::string::npos) << e.what();
    }
    s_server->start();
    EXPECT_EQ(reviewer.sessions().size(), 3U);
}

TEST_F(CentralReconnect, ATransactionCutByTheOutageFailsAndTheNextWorks)
{
    PgConnection station(s_server->conninfo("press_a"));
    const std::string before = station.query("SELECT count(*) FROM sessions").text(0, 0);
    {
        PgTransaction transaction(station);
        station.query("INSERT INTO sessions (uuid, mode, started_utc, status, app_version) VALUES "
                      "('00000000-0000-4000-8000-0000000000b1', 'panel-scan', '2026-11-26T10:00:00.000Z', "
                      "'complete', 'test')");
        restart();
        // Neither the rest of the transaction nor its COMMIT may go to a new
        // connection, where the insert never happened.
        EXPECT_THROW(station.query("SELECT 1"), StorageError);
        EXPECT_THROW(transaction.commit(), StorageError);
    }
    EXPECT_EQ(station.query("SELECT count(*) FROM sessions").text(0, 0), before);
    EXPECT_EQ(station.reconnects(), 1);
}

TEST_F(CentralReconnect, ALockCutByTheOutageIsNeverTakenOverByANewConnection)
{
    PgConnection station(s_server->conninfo("press_a"));
    station.query("SELECT pg_advisory_lock(1)");
    station.holdServerState();
    restart();
    EXPECT_THROW(station.query("SELECT 1"), StorageError);
    station.releaseServerState();
    EXPECT_EQ(station.query("SELECT 1").text(0, 0), "1");
}
