// The central store judges what a station claims, attacked through libpq
// as the station's own role (as psql would) on a real PostgreSQL started
// for the suite, each attack beside the act that is allowed, so a refusal
// is the check's and not some other error's. Found by an attack on the
// product: a station dated an operator's verdict 9999-12-31 and so
// overrode a reviewer's later "defects found"; 'not a date' was a decision
// time; a session was marked complete with a made-up checksum, and a
// session of several devices before its parts.
#include "core/storage/central/PgConnection.h"
#include "support/CliRunner.h"
#include "support/PostgresServer.h"

#include <QCryptographicHash>
#include <QDateTime>

#include <gtest/gtest.h>

#include <memory>

using tactiscope::core::storage::StorageError;
using tactiscope::core::storage::central::PgConnection;
using tactiscope::testing::PostgresServer;
using tactiscope::testing::runCli;

namespace {

std::string md5Hex(const QByteArray& bytes)
{
    return QCryptographicHash::hash(bytes, QCryptographicHash::Md5).toHex().toStdString();
}

// A UTC time `seconds` from now in the stored form.
std::string utcIn(qint64 seconds)
{
    return QDateTime::currentDateTimeUtc().addSecs(seconds).toString(Qt::ISODateWithMs).toStdString();
}

class CentralClaims : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        s_server = std::make_unique<PostgresServer>();
        ASSERT_EQ(runCli({"server", "init", QString::fromStdString(s_server->conninfo())}).exitCode, 0);
        PgConnection(s_server->conninfo())
            .run("CREATE ROLE press_a LOGIN IN ROLE tactiscope_station; "
                 "CREATE ROLE quality LOGIN IN ROLE tactiscope_reviewer;");
    }
    static void TearDownTestSuite() { s_server.reset(); }

    // A session as a station's sync begins one; its id.
    static std::string addSession(PgConnection& as, const std::string& uuid, const std::string& parent = {},
                                  const std::string& device = {})
    {
        std::vector<std::optional<std::string>> p{uuid, utcIn(-3600), utcIn(-3000), device};
        p.push_back(parent.empty() ? std::nullopt : std::optional(parent));
        return as
            .query("INSERT INTO sessions (uuid, mode, started_utc, ended_utc, status, app_version, device_name, "
                   "parent_id) VALUES ($1, 'panel-scan', $2, $3, 'complete', 'test', $4, $5::bigint) RETURNING id",
                   p)
            .text(0, 0);
    }

    // One channel and one chunk of one sample, 1.0f; the checksum of its
    // samples as the station computes it (one line per chunk:
    // "first:count:md5 of its bytes", and the md5 of the lines).
    static std::string addSamples(PgConnection& as, const std::string& session)
    {
        as.query("INSERT INTO channels (session_id, position, name, unit, kind, sample_rate_hz) VALUES ($1, 0, 'a', "
                 "'', 'strain', 1000)",
                 {session});
        as.query("SELECT month_ready(started_utc) FROM sessions WHERE id = $1", {session});
        as.query(
            "INSERT INTO chunks (session_id, session_month, first_index, first_time_s, count, samples) VALUES ($1, "
            "(SELECT session_month(started_utc) FROM sessions WHERE id = $1::bigint), 0, 0, 1, "
            "'\\x0000803f')",
            {session});
        return md5Hex(QByteArray("0:1:") + QByteArray::fromStdString(md5Hex(QByteArray::fromHex("0000803f"))));
    }

    static std::string complete(PgConnection& as, const std::string& session, const std::string& checksum)
    {
        as.query("UPDATE sessions SET complete = true, checksum = $1 WHERE id = $2", {checksum, session});
        return session;
    }

    static std::string verdictOf(const std::string& session)
    {
        return PgConnection(s_server->conninfo())
            .query("SELECT verdict FROM sessions WHERE id = $1", {session})
            .text(0, 0);
    }

    static inline std::unique_ptr<PostgresServer> s_server;
};

// The server's refusal of `statement`, or "" when it was done.
std::string refusal(PgConnection& as, const std::string& statement,
                    std::vector<std::optional<std::string>> parameters = {})
{
    try {
        as.query(statement, parameters);
        return {};
    } catch (const StorageError& e) {
        return e.what();
    }
}

constexpr const char* kOperatorVerdict =
    "INSERT INTO verdicts (session_id, role, verdict, decided_by, decided_utc) VALUES ($1, 'operator', $2, 'Ada', $3)";

}  // namespace

TEST_F(CentralClaims, ASessionIsCompleteOnlyWithTheChecksumOfWhatArrived)
{
    PgConnection station(s_server->conninfo("press_a"));
    const std::string id = addSession(station, "10000000-0000-4000-8000-000000000001");
    const std::string checksum = addSamples(station, id);
    const std::string madeUp = md5Hex("made up");
    const std::string refused =
        refusal(station, "UPDATE sessions SET complete = true, checksum = $1 WHERE id = $2", {madeUp, id});
    EXPECT_NE(refused.find("its samples arrived damaged (checksum " + checksum + ", sent " + madeUp), std::string::npos)
        << refused;
    complete(station, id, checksum);
    EXPECT_EQ(PgConnection(s_server->conninfo("quality"))
                  .query("SELECT checksum FROM sessions WHERE id = $1", {id})
                  .text(0, 0),
              checksum);
}

TEST_F(CentralClaims, ASessionOfSeveralDevicesIsCompleteOnlyAfterItsParts)
{
    PgConnection station(s_server->conninfo("press_a"));
    const std::string parent = addSession(station, "20000000-0000-4000-8000-000000000002");
    const std::string part = addSession(station, "20000000-0000-4000-8000-000000000003", parent, "left");
    const std::string partChecksum = addSamples(station, part);
    // The parent's checksum: one line per part, "device checksum".
    const std::string checksum = md5Hex(QByteArray::fromStdString("left " + partChecksum + "\n"));
    const std::string early = "UPDATE sessions SET complete = true, checksum = $1 WHERE id = $2";
    const std::string beforeParts = refusal(station, early, {checksum, parent});
    EXPECT_NE(beforeParts.find("complete only after its parts: 1 of them not yet"), std::string::npos) << beforeParts;
    complete(station, part, partChecksum);
    EXPECT_NE(refusal(station, early, {md5Hex("left x\n"), parent}).find("arrived damaged"), std::string::npos);
    complete(station, parent, checksum);
    // Its parts arrived whole before it: nothing more joins it.
    EXPECT_NE(refusal(station,
                      "INSERT INTO sessions (uuid, mode, started_utc, status, app_version, parent_id) VALUES "
                      "('20000000-0000-4000-8000-000000000004', 'panel-scan', $1, 'complete', 'test', $2)",
                      {utcIn(-60), parent})
                  .find("still being sent"),
              std::string::npos);
}

TEST_F(CentralClaims, TheTimesAStationClaimsAreDatesNotInTheFuture)
{
    PgConnection station(s_server->conninfo("press_a"));
    const std::string insert = "INSERT INTO sessions (uuid, mode, started_utc, ended_utc, status, app_version) "
                               "VALUES ('30000000-0000-4000-8000-000000000005', 'panel-scan', $1, $2, 'complete', "
                               "'test')";
    EXPECT_NE(refusal(station, insert, {"not a date", std::nullopt}).find("its start 'not a date' is not a UTC time"),
              std::string::npos);
    EXPECT_NE(refusal(station, insert, {"2026-13-45T00:00:00Z", std::nullopt}).find("is not a date"),
              std::string::npos);
    EXPECT_NE(refusal(station, insert, {"9999-12-31T00:00:00Z", std::nullopt}).find("later than the central store"),
              std::string::npos);
    EXPECT_NE(refusal(station, insert, {utcIn(-60), utcIn(-120)}).find("is before its start"), std::string::npos);
    EXPECT_EQ(refusal(station, insert, {utcIn(-120), utcIn(-60)}), "");

    const std::string id = addSession(station, "30000000-0000-4000-8000-000000000006");
    const std::string note =
        "INSERT INTO annotations (session_id, time_s, text, created_utc, modified_utc) VALUES ($1, 0, 'x', $2, $2)";
    EXPECT_NE(refusal(station, note, {id, "9999-12-31T00:00:00.000Z"}).find("the note's time"), std::string::npos);
    EXPECT_NE(refusal(station, note, {id, std::string(100000, '7')}).find("(100000 characters)"), std::string::npos);
    EXPECT_EQ(refusal(station, note, {id, utcIn(-600)}), "");
    EXPECT_NE(refusal(station, kOperatorVerdict, {id, "pass", "not a date"}).find("the decision's time"),
              std::string::npos);
    EXPECT_EQ(refusal(station, kOperatorVerdict, {id, "pass", utcIn(-1800)}), "");
    EXPECT_EQ(verdictOf(id), "pass");
}

// The attack itself: a reviewer's "defects found", then a station's
// operator "pass" dated 9999-12-31, which was the latest decision of the
// trail and so the session's verdict. A reviewer's decision is dated by the
// server's clock, whatever time the reviewer's program sends.
TEST_F(CentralClaims, AStationCannotDateADecisionPastAReviewers)
{
    PgConnection station(s_server->conninfo("press_a"));
    const std::string id = addSession(station, "40000000-0000-4000-8000-000000000007");
    complete(station, id, addSamples(station, id));
    PgConnection reviewer(s_server->conninfo("quality"));
    const std::string decided = reviewer
                                    .query("INSERT INTO verdicts (session_id, role, verdict, decided_by, decided_utc) "
                                           "VALUES ($1, 'reviewer', 'defects found', 'Grace', "
                                           "'2000-01-01T00:00:00.000Z') RETURNING decided_utc",
                                           {id})
                                    .text(0, 0);
    const QDateTime stored = QDateTime::fromString(QString::fromStdString(decided), Qt::ISODateWithMs);
    EXPECT_LT(std::abs(stored.secsTo(QDateTime::currentDateTimeUtc())), 60) << decided;
    EXPECT_EQ(verdictOf(id), "defects found");

    EXPECT_NE(refusal(station, kOperatorVerdict, {id, "pass", "9999-12-31T00:00:00.000Z"}).find("later than"),
              std::string::npos);
    // An operator's decision made before the reviewer's, sent later, is
    // kept in the trail and outranks nothing.
    EXPECT_EQ(refusal(station, kOperatorVerdict, {id, "pass", utcIn(-1800)}), "");
    EXPECT_EQ(verdictOf(id), "defects found");
}
