// Lists on a central store that holds more than a browser's cap (issue
// 56), on the suite's real PostgreSQL: 5,100 sessions of two stations grown
// by SQL in the shape a sync writes, and one interrupted session older than
// all of them. The status filter is asked of the server, so the old
// interrupted session is found behind 5,000 newer ones; a station is asked
// for by name; a text is found through its index among what the login may
// see only; and every filter's question has an index path (EXPLAIN with
// its index named in the plan: the filter read as an index range, not
// every session walked in date order and its rows thrown away).
#include "core/storage/central/CentralSchema.h"
#include "core/storage/central/CentralStore.h"
#include "core/storage/central/PgConnection.h"
#include "support/CliRunner.h"
#include "support/PostgresServer.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <memory>

using namespace tactiscope;
using core::storage::SessionFilter;
using core::storage::central::CentralStore;
using core::storage::central::PgConnection;
using tactiscope::testing::CliResult;
using tactiscope::testing::PostgresServer;
using tactiscope::testing::runCli;

namespace {

constexpr int kGrown = 5100;

class CentralListing : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        s_server = std::make_unique<PostgresServer>();
        PgConnection owner(s_server->conninfo());
        owner.run("CREATE DATABASE listing");
        const std::string site = s_server->conninfo(PostgresServer::kOwner, "listing");
        ASSERT_EQ(runCli({"server", "init", QString::fromStdString(site)}).exitCode, 0);
        PgConnection store(site);
        store.run("CREATE ROLE press_a LOGIN IN ROLE tactiscope_station; "
                  "CREATE ROLE press_b LOGIN IN ROLE tactiscope_station; "
                  "CREATE ROLE quality LOGIN IN ROLE tactiscope_reviewer;");
        // Whole sessions of one device, a minute apart through 2026, as
        // the stations' syncs leave them (the owner writes them at once);
        // each filter picks a few in a hundred, so the server takes the
        // filter's own index where it has one.
        store.run("INSERT INTO sessions (uuid, station, complete, mode, subject, operator, started_utc, ended_utc, "
                  "status, verdict, app_version) SELECT md5(g::text), CASE WHEN g % 100 = 0 THEN 'press_a' ELSE "
                  "'press_b' END, true, 'panel-scan', 'door-' || g, 'op-' || (g % 50), to_char(timestamp "
                  "'2026-01-01' + g * interval '1 minute', 'YYYY-MM-DD\"T\"HH24:MI:SS.MS\"Z\"'), to_char(timestamp "
                  "'2026-01-01' + g * interval '1 minute' + interval '30 seconds', "
                  "'YYYY-MM-DD\"T\"HH24:MI:SS.MS\"Z\"'), 'complete', CASE WHEN g % 50 = 0 THEN 'defects found' "
                  "ELSE 'pass' END, '0.1.0' FROM generate_series(1, " +
                  std::to_string(kGrown) +
                  ") g; "
                  "INSERT INTO sessions (uuid, station, complete, mode, subject, operator, started_utc, ended_utc, "
                  "status, app_version) VALUES ('old-interrupted', 'press_b', true, 'palpation', 'phantom-3', "
                  "'Ada', '2025-06-01T08:00:00.000Z', '2025-06-01T08:00:40.000Z', 'interrupted', '0.1.0'); "
                  "ANALYZE sessions;");
    }
    static void TearDownTestSuite() { s_server.reset(); }

    static std::string reviewer() { return s_server->conninfo("quality", "listing"); }
    static QStringList listed(const QStringList& options)
    {
        const CliResult r =
            runCli(QStringList{"sessions", "--db", QString::fromStdString(reviewer()), "list", "--json"} + options);
        EXPECT_EQ(r.exitCode, 0) << r.err.toStdString();
        QStringList subjects;
        for (const auto s : QJsonDocument::fromJson(r.out.toUtf8()).array())
            subjects << s.toObject()["subject"].toString() + "@" + s.toObject()["station"].toString();
        return subjects;
    }

    static inline std::unique_ptr<PostgresServer> s_server;
};

}  // namespace

TEST_F(CentralListing, AStatusIsAskedOfTheServerSoTheOldInterruptedSessionIsFoundBehindTheCap)
{
    CentralStore store(reviewer(), core::storage::Database::Access::ReadOnly);
    SessionFilter newest;
    newest.limit = 5000;  // the session browser's cap
    EXPECT_EQ(store.sessions(newest).size(), 5000u);
    SessionFilter interrupted = newest;
    interrupted.status = core::SessionStatus::Interrupted;
    const auto found = store.sessions(interrupted);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].metadata.subject, "phantom-3");
    EXPECT_EQ(listed({"--status", "interrupted"}), QStringList{"phantom-3@press_b"});
}

TEST_F(CentralListing, AStationIsAskedForByName)
{
    const QStringList a = listed({"--station", "press_a", "--all"});
    EXPECT_EQ(a.size(), kGrown / 100);
    EXPECT_TRUE(a.filter(QStringLiteral("@press_a")).size() == a.size());
    EXPECT_EQ(listed({"--station", "press_a", "--subject", "door-5100"}), QStringList{"door-5100@press_a"});
    QTemporaryDir dir;
    const CliResult file = runCli({"sessions", "--db", dir.filePath("none.tactiscope"), "list", "--station", "x"});
    EXPECT_EQ(file.exitCode, 2);
}

TEST_F(CentralListing, EveryFiltersQuestionIsAnIndexRange)
{
    CentralStore store(reviewer(), core::storage::Database::Access::ReadOnly);
    struct Question {
        std::string what;
        std::string index;  // the one the question is read through
        SessionFilter filter;
    };
    std::vector<Question> questions(10);
    questions[0] = {"the newest", "sessions_listed", {}};
    questions[1] = {"a station", "sessions_listed_by_station", {}};
    questions[1].filter.station = "press_a";
    questions[2] = {"a subject", "sessions_listed_by_subject", {}};
    questions[2].filter.subject = "door-17";
    questions[3] = {"an operator", "sessions_listed_by_operator", {}};
    questions[3].filter.operatorName = "op-3";
    questions[4] = {"a mode", "sessions_listed_by_mode", {}};
    questions[4].filter.mode = core::Mode::Capacitive;
    questions[5] = {"a status", "sessions_listed_by_status", {}};
    questions[5].filter.status = core::SessionStatus::Interrupted;
    questions[6] = {"a verdict", "sessions_listed_by_verdict", {}};
    questions[6].filter.verdict = core::Verdict::DefectsFound;
    questions[7] = {"a day", "sessions_listed", {}};
    questions[7].filter.startedFrom = "2026-01-02";
    questions[7].filter.startedBefore = "2026-01-03";
    questions[8] = {"the next page", "sessions_listed", {}};
    questions[8].filter.after = 42;
    questions[9] = {"a station's day", "sessions_listed_by_station", {}};
    questions[9].filter.station = "press_a";
    questions[9].filter.startedFrom = "2026-01-02";
    questions[9].filter.startedBefore = "2026-01-03";
    for (auto& [what, index, filter] : questions) {
        filter.limit = 5000;
        const std::string plan = store.listingPlan(filter);
        EXPECT_NE(plan.find("\"Index Name\": \"" + index + "\""), std::string::npos) << what << ":\n" << plan;
        EXPECT_EQ(plan.find("Seq Scan"), std::string::npos) << what << ":\n" << plan;
    }
    // A text: the sessions the search function finds, each by its id.
    SessionFilter text;
    text.text = "phantom";
    text.limit = 5000;
    const std::string plan = store.listingPlan(text);
    EXPECT_NE(plan.find("sessions_with_text"), std::string::npos) << plan;
    EXPECT_EQ(plan.find("Seq Scan"), std::string::npos) << plan;
    // …whose own question, asked as the owner who runs it, can read the
    // trigram index. On so few rows the server would rather test each, so
    // testing one costs here what it does among millions.
    PgConnection owner(s_server->conninfo(PostgresServer::kOwner, "listing"));
    owner.run("SET cpu_operator_cost = 10");
    std::string question = "EXPLAIN (FORMAT JSON) SELECT id FROM sessions WHERE complete AND parent_id IS NULL AND ";
    question.append(core::storage::central::kSessionSearchText).append(" ILIKE '%phantom%'");
    const std::string inside = owner.query(question).text(0, 0);
    EXPECT_NE(inside.find("\"Index Name\": \"sessions_listed_by_text\""), std::string::npos) << inside;
}

// The search runs as the owner through the index: it still finds only what
// the login may see. A station finds its own sessions; asked directly, the
// function names no other station's; a reviewer finds every station's.
TEST_F(CentralListing, ATextIsFoundThroughTheIndexAmongWhatTheLoginMaySeeOnly)
{
    EXPECT_EQ(listed({"--search", "DOOR-51", "--all"}).size(), 12);  // door-51, door-510…519, door-5100, any case
    EXPECT_EQ(listed({"--search", "phantom"}), QStringList{"phantom-3@press_b"});
    CentralStore station(s_server->conninfo("press_a", "listing"), core::storage::Database::Access::ReadOnly);
    SessionFilter doors;
    doors.text = "door-5";
    const auto own = station.sessions(doors);
    ASSERT_FALSE(own.empty());
    for (const auto& s : own) EXPECT_EQ(s.station, "press_a") << s.metadata.subject;
    PgConnection owner(s_server->conninfo(PostgresServer::kOwner, "listing"));
    const std::string found =
        PgConnection(s_server->conninfo("press_a", "listing"))
            .query("SELECT string_agg(id::text, ',' ORDER BY id) FROM sessions_with_text('%door%') AS f(id)")
            .text(0, 0);
    const std::string pressA =
        owner.query("SELECT string_agg(id::text, ',' ORDER BY id) FROM sessions WHERE station = 'press_a'").text(0, 0);
    EXPECT_EQ(found, pressA);
}
