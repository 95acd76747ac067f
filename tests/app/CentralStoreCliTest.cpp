// A site's central store on a real PostgreSQL server started for the suite,
// fed by `tactiscope-cli sync` from two stations' stores written through
// the store API: listed together with their station names, exported from
// the server to the same bytes as from the station, a second sync sending
// nothing, a sync killed mid-transaction leaving nothing and the next one
// an exact copy, an unreachable server exiting 1 with the station's store
// untouched, a uuid with other samples refused, a station unable to
// delete or change another's session or to add rows readers cannot bound,
// and a reviewer meeting older unbounded rows as damage.
#include "core/storage/AutomaticVerdict.h"
#include "core/storage/Database.h"
#include "core/storage/SessionStore.h"
#include "core/storage/central/PgConnection.h"
#include "devices/session/SessionOfDevices.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/FileBytes.h"
#include "support/PostgresServer.h"
#include "support/StationStore.h"
#include "support/TextBoard.h"
#include "support/WaitFor.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <map>
#include <memory>

using namespace tactiscope;
using core::storage::StorageError;
using core::storage::central::PgConnection;
using tactiscope::testing::CliResult;
using tactiscope::testing::fileBytes;
using tactiscope::testing::PostgresServer;
using tactiscope::testing::runCli;

namespace {

class CentralStoreCli : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        s_server = std::make_unique<PostgresServer>();
        PgConnection owner(s_server->conninfo());
        // Roles are the cluster's; each test has a database of its own.
        ASSERT_EQ(runCli({"server", "init", QString::fromStdString(s_server->conninfo())}).exitCode, 0);
        owner.run("CREATE ROLE press_a LOGIN IN ROLE tactiscope_station; "
                  "CREATE ROLE press_b LOGIN IN ROLE tactiscope_station; "
                  "CREATE ROLE quality LOGIN IN ROLE tactiscope_reviewer;");
    }
    static void TearDownTestSuite() { s_server.reset(); }

    void SetUp() override
    {
        static int count = 0;
        m_database = "site" + std::to_string(++count);
        PgConnection(s_server->conninfo()).run("CREATE DATABASE " + m_database);
        const CliResult init = runCli({"server", "init", server()});
        ASSERT_EQ(init.exitCode, 0) << init.err.toStdString();
        tactiscope::testing::StationStoreOptions a, b;
        a.subjectPrefix = "door";
        b.subjectPrefix = "hood";
        b.seed = 7;
        tactiscope::testing::writeStationStore(m_stationA.toStdString(), a);
        tactiscope::testing::writeStationStore(m_stationB.toStdString(), b);
    }

    QString server(const std::string& user = PostgresServer::kOwner) const
    {
        return QString::fromStdString(s_server->conninfo(user, m_database));
    }
    PgConnection connect(const std::string& user = PostgresServer::kOwner) const
    {
        return PgConnection(s_server->conninfo(user, m_database));
    }
    static CliResult sync(const QString& db, const QString& server, const QStringList& extra = {})
    {
        return runCli(QStringList{"sync", "--db", db, "--server", server} + extra);
    }
    // uuid → station of what `db` lists.
    static std::map<QString, QString> listed(const QString& db)
    {
        const CliResult list = runCli({"sessions", "--db", db, "list", "--json"});
        EXPECT_EQ(list.exitCode, 0) << list.err.toStdString();
        std::map<QString, QString> result;
        for (const auto& s : QJsonDocument::fromJson(list.out.toUtf8()).array())
            result[s.toObject()["uuid"].toString()] = s.toObject()["station"].toString();
        return result;
    }
    QString exported(const QString& db, const QString& uuid, const QString& format, const QString& name) const
    {
        const QString path = m_dir.filePath(name);
        const CliResult r = runCli({"sessions", "--db", db, "export", uuid, "--format", format, "--output", path});
        EXPECT_EQ(r.exitCode, 0) << r.err.toStdString();
        return path;
    }
    // The station's sessions export to the same bytes from the server.
    void expectSameExports(const QString& station, const QString& central) const
    {
        for (const auto& [uuid, name] : listed(station)) {
            for (const QString format : {"json", "csv"}) {
                const QString local = exported(station, uuid, format, uuid + "-local." + format);
                const QString server = exported(central, uuid, format, uuid + "-central." + format);
                const std::string fromStation = fileBytes(local.toStdString());
                EXPECT_TRUE(fromStation == fileBytes(server.toStdString()))
                    << uuid.toStdString() << " " << format.toStdString();
                EXPECT_GT(fromStation.size(), 100U);
            }
            const QString localMeta = m_dir.filePath(uuid + "-local.meta.json");
            EXPECT_TRUE(fileBytes(localMeta.toStdString()) ==
                        fileBytes(m_dir.filePath(uuid + "-central.meta.json").toStdString()))
                << uuid.toStdString();
        }
    }

    static inline std::unique_ptr<PostgresServer> s_server;
    QTemporaryDir m_dir;
    QString m_stationA = m_dir.filePath("press-a.tactiscope");
    QString m_stationB = m_dir.filePath("press-b.tactiscope");
    std::string m_database;
};

// A panel scan of two seconds at 500 Hz into the station store at `path`,
// with `metadata`'s subject and more; `more` adds to it before it ends.
void writePanelScan(const QString& path, core::storage::SessionMetadata metadata,
                    const std::function<void(core::storage::SessionStore&, std::int64_t)>& more = {})
{
    core::storage::SessionStore store(path.toStdString());
    metadata.mode = core::Mode::PanelScan;
    const std::vector<core::ChannelDescriptor> channels{
        {"a", "", core::ChannelKind::Strain, core::ChannelRole::CantileverA},
        {"b", "", core::ChannelKind::Strain, core::ChannelRole::CantileverB}};
    const auto id = store.beginSession(metadata, channels, 500.0);
    tactiscope::testing::writeSamples(store, id, 2, 1000, 500.0, 5);
    if (more) more(store, id);
    store.endSession(id, core::SessionStatus::Complete);
}

bool refused(PgConnection& as, const std::string& statement, const std::vector<std::optional<std::string>>& values)
{
    try {
        return as.query(statement, values).rows() == 0;  // RLS hides the row: nothing changed
    } catch (const StorageError&) {
        return true;
    }
}

}  // namespace

// A maker's board recorded in the general mode, its channels given roles:
// the server keeps the mode and the roles, and exports the same bytes.
TEST_F(CentralStoreCli, AGeneralSessionAndItsChannelsRolesGoToTheServerAsTheyAre)
{
    const QString maker = m_dir.filePath("maker.tactiscope");
    {
        core::storage::SessionStore store(maker.toStdString());
        core::storage::SessionMetadata metadata;
        metadata.mode = core::Mode::General;
        metadata.subject = "board-1";
        const std::vector<core::ChannelDescriptor> channels{
            {"a", "", core::ChannelKind::Other, core::ChannelRole::StiffBeam},
            {"temp", "degC", core::ChannelKind::Other}};
        const auto id = store.beginSession(metadata, channels, 100.0);
        tactiscope::testing::writeSamples(store, id, 2, 900, 100.0, 3);
        store.endSession(id, core::SessionStatus::Complete);
    }
    const CliResult sent = sync(maker, server("press_a"));
    ASSERT_EQ(sent.exitCode, 0) << sent.err.toStdString();
    EXPECT_EQ(connect().query("SELECT mode FROM sessions").text(0, 0), "general");
    EXPECT_EQ(connect().query("SELECT string_agg(role, ',' ORDER BY position) FROM channels").text(0, 0),
              "stiff-beam,");
    expectSameExports(maker, server("quality"));
}

// A board printing lines, recorded through a real pty as a maker records
// it: its rate timed from the lines (not a round number), a unit from its
// label, a value that was no number (a hole in its channel alone) and the
// note saying how the rate was measured. The server keeps every one of
// them: the same bytes exported, the hole NaN there too.
TEST_F(CentralStoreCli, ABoardPrintingLinesGoesToTheServerWithItsTimedRateItsUnitsAndItsHoles)
{
    const QString link = m_dir.filePath("board");
    tactiscope::testing::TextBoard board(link.toStdString(),
                                         {100.0,
                                          [](std::uint64_t n) {
                                              return "force[mN]:" + std::to_string(static_cast<double>(n % 90)) +
                                                     " temp:" + (n % 37 == 0 ? std::string("nan") : "21.5") + "\r\n";
                                          },
                                          2, 1e-3, false});
    ASSERT_TRUE(board.ok());
    const QString maker = m_dir.filePath("maker.tactiscope");
    const CliResult recorded =
        runCli({"record", "--port", link, "--protocol", "text", "--seconds", "1", "--db", maker});
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();
    const CliResult sent = sync(maker, server("press_a"));
    ASSERT_EQ(sent.exitCode, 0) << sent.err.toStdString();
    EXPECT_EQ(connect().query("SELECT string_agg(unit, ',' ORDER BY position) FROM channels").text(0, 0), "N,");
    EXPECT_NE(connect().query("SELECT sample_rate_hz FROM channels LIMIT 1").text(0, 0), "100");
    EXPECT_EQ(connect().query("SELECT count(*) FROM events WHERE note LIKE 'the sample rate, %'").text(0, 0), "1");
    const QString csv = exported(server("quality"), listed(maker).begin()->first, "csv", "board-central.csv");
    EXPECT_TRUE(
        QString::fromStdString(fileBytes(csv.toStdString())).contains(QStringLiteral("nan"), Qt::CaseInsensitive));
    expectSameExports(maker, server("quality"));
}

// Issue 52: a session its mode could not judge (it went past a critical
// limit) says so on the server as on the station: `show` gives the reason,
// the list's verdict column "not judged" and its JSON the reason, a search
// for it finds it, and both export the same bytes.
TEST_F(CentralStoreCli, ASessionNotJudgedSaysWhyOnTheServerAsOnTheStation)
{
    const QString line = m_dir.filePath("line.tactiscope");
    const std::string why = "not judged: it went past a critical limit";
    core::storage::SessionMetadata metadata;
    metadata.subject = "door-40";
    writePanelScan(line, metadata,
                   [&](core::storage::SessionStore& store, std::int64_t id) { store.markUnjudged(id, why); });
    const CliResult sent = sync(line, server("press_a"));
    ASSERT_EQ(sent.exitCode, 0) << sent.err.toStdString();
    for (const QString& db : {line, server("quality")}) {
        SCOPED_TRACE(db.toStdString());
        const CliResult shown = runCli({"sessions", "--db", db, "show", "last"});
        ASSERT_EQ(shown.exitCode, 0) << shown.err.toStdString();
        EXPECT_TRUE(shown.out.contains(QRegularExpression(QStringLiteral("\\nverdict +") +
                                                          QRegularExpression::escape(QString::fromStdString(why)))))
            << shown.out.toStdString();
        const CliResult table = runCli({"sessions", "--db", db, "list"});
        EXPECT_TRUE(table.out.contains(QStringLiteral("not judged"))) << table.out.toStdString();
        for (const QString words : {"critical limit", "not judged"}) {
            const CliResult found = runCli({"sessions", "--db", db, "list", "--search", words, "--json"});
            ASSERT_EQ(found.exitCode, 0) << found.err.toStdString();
            const auto sessions = QJsonDocument::fromJson(found.out.toUtf8()).array();
            ASSERT_EQ(sessions.size(), 1) << found.out.toStdString();
            EXPECT_EQ(sessions[0].toObject()["subject"].toString(), QStringLiteral("door-40"));
            EXPECT_EQ(sessions[0].toObject()["unjudged"].toString(), QString::fromStdString(why));
        }
    }
    expectSameExports(line, server("quality"));
}

// A session's filters and math channels (issue 57) go to the server with
// it: the reviewer there reads the same setup, and the export's filtered
// and math columns, computed from the server's samples, are the station's
// to the byte.
TEST_F(CentralStoreCli, ASessionsFiltersAndMathChannelsAreTheSameOnTheServer)
{
    const QString line = m_dir.filePath("hummed.tactiscope");
    const std::string setup = R"({"filters":[{"channel":"a","notch_hz":50.0,"lowpass_hz":100.0,"order":4}],)"
                              R"("math":["diff[µε]=a - b"]})";
    core::storage::SessionMetadata metadata;
    metadata.subject = "door-57";
    metadata.signalSetup = setup;
    writePanelScan(line, metadata);
    const CliResult sent = sync(line, server("press_a"));
    ASSERT_EQ(sent.exitCode, 0) << sent.err.toStdString();
    for (const QString& db : {line, server("quality")}) {
        SCOPED_TRACE(db.toStdString());
        const CliResult shown = runCli({"sessions", "--db", db, "show", "last"});
        ASSERT_EQ(shown.exitCode, 0) << shown.err.toStdString();
        EXPECT_TRUE(shown.out.contains(
            QStringLiteral("\nsignal            a: mains notch 50 Hz and harmonics, low-pass 100 Hz (Butterworth, "
                           "order 4); diff[µε]=a - b\n")))
            << shown.out.toStdString();
    }
    const QString uuid = listed(line).begin()->first;
    const QString csv = exported(server("quality"), uuid, "csv", "central.csv");
    EXPECT_TRUE(
        fileBytes(csv.toStdString()).starts_with("t [s],a [strain],b [strain],a.filtered [strain],diff [µε]\n"));
    expectSameExports(line, server("quality"));
}

// A panel line's recording through TSP/1 with its encoder (issue 55): the
// reviewer on the server reads the same sites as the station, placed by
// the stored position channel, the dent at +30 mm within 1 mm.
TEST_F(CentralStoreCli, APanelLinesSitesFromItsEncoderAreTheSameOnTheServer)
{
    const QString line = m_dir.filePath("line.tactiscope");
    const CliResult record = tactiscope::testing::recordEmulated(m_dir.path(), line, QStringLiteral("panel-line"), 16);
    ASSERT_EQ(record.exitCode, 0) << record.err.toStdString();
    const CliResult sent = sync(line, server("press_a"));
    ASSERT_EQ(sent.exitCode, 0) << sent.err.toStdString();
    QJsonArray sites[2];
    for (int i = 0; i < 2; ++i) {
        const QString db = i == 0 ? line : server("quality");
        SCOPED_TRACE(db.toStdString());
        const CliResult shown = runCli({"sessions", "--db", db, "show", "last", "--json"});
        ASSERT_EQ(shown.exitCode, 0) << shown.err.toStdString();
        const QJsonObject o = QJsonDocument::fromJson(shown.out.toUtf8()).object();
        EXPECT_EQ(o["sites_method"].toString(), QStringLiteral("from the position channel")) << shown.out.toStdString();
        sites[i] = o["sites"].toArray();
        ASSERT_EQ(sites[i].size(), 1) << shown.out.toStdString();
        EXPECT_NEAR(sites[i][0].toObject()["position_mm"].toDouble(), 30.0, 1.0) << shown.out.toStdString();
    }
    EXPECT_EQ(sites[0], sites[1]);
    expectSameExports(line, server("quality"));
}

// Issue 56: a list is one page at a time, here and on the server alike.
// Seven sessions, four of them begun at one instant (two stations' clocks
// agree to the millisecond): pages of three, each after the last listed,
// give every session once in the list's order; `last` is the session
// stored last, one indexed row.
TEST_F(CentralStoreCli, AListPagesThroughEverySessionOnceTiesIncluded)
{
    const QString many = m_dir.filePath("many.tactiscope");
    {
        core::storage::SessionStore store(many.toStdString());
        core::storage::SessionMetadata metadata;
        metadata.mode = core::Mode::General;
        for (int i = 0; i < 7; ++i) {
            metadata.subject = "board-" + std::to_string(i);
            const std::vector<core::ChannelDescriptor> channels{{"a", "", core::ChannelKind::Other}};
            const auto id = store.beginSession(metadata, channels, 100.0);
            tactiscope::testing::writeSamples(store, id, 1, 200, 100.0, i);
            store.endSession(id, core::SessionStatus::Complete);
        }
    }
    core::storage::Database(many.toStdString(), core::storage::Database::Access::ReadWrite)
        .exec("UPDATE sessions SET started_utc = '2026-11-20T08:00:00.000Z' WHERE id BETWEEN 2 AND 5");
    ASSERT_EQ(sync(many, server("press_a")).exitCode, 0);
    for (const QString& db : {many, server("quality")}) {
        SCOPED_TRACE(db.toStdString());
        const auto subjects = [](const CliResult& r) {
            QStringList listed;
            for (const auto s : QJsonDocument::fromJson(r.out.toUtf8()).array())
                listed << s.toObject()["subject"].toString();
            return listed;
        };
        const CliResult all = runCli({"sessions", "--db", db, "list", "--all", "--json"});
        ASSERT_EQ(all.exitCode, 0) << all.err.toStdString();
        ASSERT_EQ(subjects(all).size(), 7);
        EXPECT_TRUE(all.err.isEmpty()) << all.err.toStdString();
        QStringList paged;
        QStringList after;
        for (int page = 0; page < 4; ++page) {
            const CliResult r = runCli(QStringList{"sessions", "--db", db, "list", "--limit", "3", "--json"} + after);
            ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
            paged += subjects(r);
            const auto next = QRegularExpression(QStringLiteral("--after (\\d+) lists the next 3")).match(r.err);
            if (!next.hasMatch()) break;
            after = QStringList{"--after", next.captured(1)};
        }
        EXPECT_EQ(paged, subjects(all));
        EXPECT_EQ(subjects(runCli({"sessions", "--db", db, "list", "--json"})), subjects(all));  // within the default

        const CliResult last = runCli({"sessions", "--db", db, "show", "last", "--json"});
        ASSERT_EQ(last.exitCode, 0) << last.err.toStdString();
        EXPECT_EQ(QJsonDocument::fromJson(last.out.toUtf8()).object()["session"].toObject()["subject"].toString(),
                  QStringLiteral("board-6"));

        const CliResult zero = runCli({"sessions", "--db", db, "list", "--limit", "0"});
        EXPECT_EQ(zero.exitCode, 2);
        EXPECT_TRUE(zero.err.contains(QStringLiteral("--limit must be"))) << zero.err.toStdString();
        const CliResult nowhere = runCli({"sessions", "--db", db, "list", "--after", "99999"});
        EXPECT_EQ(nowhere.exitCode, 2);
        EXPECT_TRUE(nowhere.err.contains(QStringLiteral("no session '99999'"))) << nowhere.err.toStdString();
    }
    // The product's connections compile no query (docs/fleet.md: JIT).
    EXPECT_EQ(connect("quality").query("SHOW jit").text(0, 0), "off");
}

// A session of several devices (issue 40) goes whole: the session, each
// device's part with its rate, samples and clock, in one transaction; the
// reviewer lists the session once, reads its parts and exports the same
// bytes as the station; a second sync finds it there. No station can hang
// a part on another station's session, nor add one to a finished session.
TEST_F(CentralStoreCli, ASessionOfSeveralDevicesGoesWholeWithItsPartsAndClocks)
{
    const QString lab = m_dir.filePath("lab.tactiscope");
    std::int64_t sessionId = 0;
    {
        core::storage::SessionStore store(lab.toStdString());
        core::storage::SessionMetadata metadata;
        metadata.mode = core::Mode::Capacitive;
        metadata.subject = "beam-3";
        sessionId = store.beginSessionOfDevices(metadata);
        metadata.partOf = sessionId;
        metadata.deviceName = "beam";
        const std::vector<core::ChannelDescriptor> capacitance{{"capacitance", "F", core::ChannelKind::Capacitance}};
        const std::vector<core::ChannelDescriptor> force{{"force", "N", core::ChannelKind::Force}};
        const std::int64_t beam = store.beginSession(metadata, capacitance, 100.0);
        tactiscope::testing::writeSamples(store, beam, 1, 1000, 100.0, 3);
        store.setClockMapping(beam, R"({"reference_s":5,"offset_s":0.5,"drift":8e-05,"span_s":9,"pairs":900,)"
                                    R"("uncertainty":"spread","offset_u_s":1.2e-05,"drift_u":3e-07})");
        metadata.deviceName = "load-cell";
        metadata.mode = core::Mode::General;
        const std::int64_t cell = store.beginSession(metadata, force, 1000.0);
        tactiscope::testing::writeSamples(store, cell, 1, 12000, 1000.0, 4);
        for (const std::int64_t id : {beam, cell, sessionId}) store.endSession(id, core::SessionStatus::Complete);
    }
    const CliResult sent = sync(lab, server("press_a"));
    ASSERT_EQ(sent.exitCode, 0) << sent.err.toStdString();
    EXPECT_TRUE(sent.out.contains("synced 1 sessions")) << sent.out.toStdString();
    auto owner = connect();
    EXPECT_EQ(owner.query("SELECT count(*) FROM sessions").text(0, 0), "3");
    EXPECT_EQ(owner.query("SELECT string_agg(device_name, ',' ORDER BY id) FROM sessions WHERE parent_id IS NOT NULL")
                  .text(0, 0),
              "beam,load-cell");
    EXPECT_EQ(owner.query("SELECT count(*) FROM sessions WHERE NOT complete").text(0, 0), "0");

    const auto onServer = listed(server("quality"));
    ASSERT_EQ(onServer.size(), 1u);  // the session, not its parts
    const CliResult shown = runCli({"sessions", "--db", server("quality"), "show", onServer.begin()->first});
    ASSERT_EQ(shown.exitCode, 0) << shown.err.toStdString();
    EXPECT_TRUE(shown.out.contains("load-cell")) << shown.out.toStdString();
    EXPECT_TRUE(shown.out.contains("80.0 ± 0.3 ppm slow")) << shown.out.toStdString();
    expectSameExports(lab, server("quality"));

    const CliResult again = sync(lab, server("press_a"));
    ASSERT_EQ(again.exitCode, 0) << again.err.toStdString();
    EXPECT_TRUE(again.out.contains("synced 0 sessions")) << again.out.toStdString();
    EXPECT_TRUE(again.out.contains("1 already there")) << again.out.toStdString();

    // A part hung on another station's session, or on a finished one of its own.
    const std::string parent = owner.query("SELECT id FROM sessions WHERE parent_id IS NULL").text(0, 0);
    const std::string part =
        "INSERT INTO sessions (uuid, station, mode, started_utc, status, app_version, parent_id, device_name) "
        "VALUES ($1, $2, 'general', '2026-01-01T00:00:00Z', 'complete', '1', $3, 'x')";
    auto pressB = connect("press_b");
    EXPECT_TRUE(refused(pressB, part, {"6f1c7d1e-0000-4000-8000-000000000001", "press_b", parent}));
    auto pressA = connect("press_a");
    EXPECT_TRUE(refused(pressA, part, {"6f1c7d1e-0000-4000-8000-000000000002", "press_a", parent}));
    EXPECT_EQ(owner.query("SELECT count(*) FROM sessions").text(0, 0), "3");

    // Not even the owner deletes a part alone: the session goes whole.
    const std::string beamPart = owner.query("SELECT id FROM sessions WHERE device_name = 'beam'").text(0, 0);
    const CliResult alone = runCli({"sessions", "--db", server(), "delete", QString::fromStdString(beamPart)});
    EXPECT_NE(alone.exitCode, 0);
    EXPECT_TRUE(alone.err.contains(QStringLiteral("is the part of device beam in session %1; delete session %1")
                                       .arg(QString::fromStdString(parent))))
        << alone.err.toStdString();
    EXPECT_EQ(owner.query("SELECT count(*) FROM sessions").text(0, 0), "3");
    const CliResult partShown = runCli({"sessions", "--db", server(), "show", QString::fromStdString(beamPart)});
    EXPECT_TRUE(partShown.out.contains(
        QStringLiteral("\npart of           session %1 (device beam)\n").arg(QString::fromStdString(parent))))
        << partShown.out.toStdString();
}

// Issue 52: a session of several devices carries its parts' verdict (the
// worst, naming the part that decided) and counts their events, at the
// station and on the server after a sync, where a reviewer's filter on
// the verdict finds it. Its end is SessionOfDevices's, as a recording's.
TEST_F(CentralStoreCli, ASessionOfSeveralDevicesHasItsPartsVerdictAndEventsHereAndOnTheServer)
{
    const QString lab = m_dir.filePath("line.tactiscope");
    std::int64_t sessionId = 0;
    {
        core::storage::SessionMetadata metadata;
        metadata.mode = core::Mode::PanelScan;
        metadata.subject = "door-9";
        devices::session::SessionOfDevices devicesSession(lab.toStdString(), metadata);
        sessionId = devicesSession.sessionId();
        {
            core::storage::SessionStore store(lab.toStdString());
            const std::vector<core::ChannelDescriptor> strains{{"a", "strain", core::ChannelKind::Strain},
                                                               {"b", "strain", core::ChannelKind::Strain}};
            // The first probe passes its panel; the second finds two crossings of one dent.
            for (const auto& [name, defects] : {std::pair{"left", 0}, std::pair{"right", 2}}) {
                metadata.partOf = sessionId;
                metadata.deviceName = name;
                const std::int64_t part = store.beginSession(metadata, strains, 500.0);
                tactiscope::testing::writeSamples(store, part, 2, 2000, 500.0, 5);
                std::vector<core::storage::SessionEvent> events(static_cast<std::size_t>(defects));
                for (auto& e : events) e.kind = core::EventKind::Defect;
                store.addEvents(part, events);
                store.decideVerdict(part, core::storage::automaticDecision("live", events.size(), defects ? 1 : 0, {}));
                store.endSession(part, core::SessionStatus::Complete);
            }
        }
        devicesSession.finish();
    }
    const auto expectVerdictAndEvents = [](const QString& db) {
        const CliResult found = runCli({"sessions", "--db", db, "list", "--verdict", "defects-found", "--json"});
        ASSERT_EQ(found.exitCode, 0) << found.err.toStdString();
        const auto rows = QJsonDocument::fromJson(found.out.toUtf8()).array();
        ASSERT_EQ(rows.size(), 1) << db.toStdString() << ": " << found.out.toStdString();
        EXPECT_EQ(rows[0].toObject()["subject"].toString(), QStringLiteral("door-9"));
        EXPECT_EQ(rows[0].toObject()["events"].toInt(), 2);
        const CliResult shown = runCli({"sessions", "--db", db, "show", rows[0].toObject()["uuid"].toString()});
        EXPECT_TRUE(shown.out.contains(QStringLiteral("defects found"))) << shown.out.toStdString();
        EXPECT_TRUE(shown.out.contains(QStringLiteral("its parts': left pass, right defects found")))
            << shown.out.toStdString();
    };
    expectVerdictAndEvents(lab);
    {
        core::storage::SessionStore store(lab.toStdString(), core::storage::Database::Access::ReadOnly);
        const auto trail = store.verdicts(sessionId);
        ASSERT_EQ(trail.size(), 1u);
        EXPECT_EQ(trail[0].verdict, core::Verdict::DefectsFound);
        EXPECT_NE(trail[0].basisJson.find(R"("decided_by_part":"right")"), std::string::npos) << trail[0].basisJson;
    }
    const CliResult sent = sync(lab, server("press_a"));
    ASSERT_EQ(sent.exitCode, 0) << sent.err.toStdString();
    expectVerdictAndEvents(server("quality"));
}

TEST_F(CentralStoreCli, TwoStationsListTogetherWithTheirNamesAndExportTheSameBytes)
{
    const CliResult a = sync(m_stationA, server("press_a"));
    ASSERT_EQ(a.exitCode, 0) << a.err.toStdString();
    // 5 500 + 1 500 + 700 samples per channel, over 2, 2 and 1 channels.
    EXPECT_EQ(a.out, "synced 3 sessions (0.015 M samples), 0 already there\n");
    const CliResult b = sync(m_stationB, server("press_b"));
    ASSERT_EQ(b.exitCode, 0) << b.err.toStdString();

    // The reviewer sees both stations; a station sees its own.
    const auto all = listed(server("quality"));
    ASSERT_EQ(all.size(), 6U);
    for (const auto& [uuid, station] : listed(m_stationA)) EXPECT_EQ(all.at(uuid), "press_a");
    for (const auto& [uuid, station] : listed(m_stationB)) EXPECT_EQ(all.at(uuid), "press_b");
    EXPECT_EQ(listed(server("press_b")).size(), 3U);
    EXPECT_EQ(listed(m_stationA).begin()->second, "");  // a station's own store names no station

    expectSameExports(m_stationA, server("quality"));
    expectSameExports(m_stationB, server("quality"));
}

TEST_F(CentralStoreCli, TheConnectionStringMayBeAUri)
{
    ASSERT_EQ(sync(m_stationA, server("press_a")).exitCode, 0);
    const QString uri = QStringLiteral("postgresql:///%1?host=%2&user=quality")
                            .arg(QString::fromStdString(m_database), QString::fromStdString(s_server->folder()));
    EXPECT_EQ(listed(uri).size(), 3U);
    const QString reportPath = m_dir.filePath("r.pdf");
    const CliResult report =
        runCli({"report", "--db", uri, "--session", listed(m_stationA).begin()->first, "--output", reportPath});
    EXPECT_EQ(report.exitCode, 0) << report.err.toStdString();
}

TEST_F(CentralStoreCli, AReviewerAnalysesAndDecidesOnTheServer)
{
    ASSERT_EQ(sync(m_stationA, server("press_a")).exitCode, 0);
    QString panel;
    for (const auto& [uuid, station] : listed(m_stationA))
        if (runCli({"sessions", "--db", m_stationA, "show", uuid}).out.contains("panel-scan")) panel = uuid;
    const CliResult analyze = runCli({"analyze", "--db", server("quality"), "--session", panel, "--json"});
    EXPECT_EQ(analyze.exitCode, 0) << analyze.err.toStdString();
    // Saving it is not a reviewer's on the central store: said before the detector runs.
    const CliResult save = runCli({"analyze", "--db", server("quality"), "--session", panel, "--save", "second"});
    EXPECT_EQ(save.exitCode, 1);
    EXPECT_TRUE(save.err.contains("may not save analyses on the central store")) << save.err.toStdString();
    EXPECT_FALSE(save.err.contains("permission denied")) << save.err.toStdString();
    const CliResult verdict = runCli(
        {"sessions", "--db", server("quality"), "verdict", panel, "pass", "--by", "Grace", "--note", "a smudge"});
    ASSERT_EQ(verdict.exitCode, 0) << verdict.err.toStdString();
    const CliResult show = runCli({"sessions", "--db", server("quality"), "show", panel});
    EXPECT_TRUE(show.out.contains("Grace") && show.out.contains("a smudge")) << show.out.toStdString();
    EXPECT_TRUE(show.out.contains("press_a (id 1 there)")) << show.out.toStdString();
    // The station's own store keeps its trail; the reviewer's is the server's.
    EXPECT_FALSE(runCli({"sessions", "--db", m_stationA, "show", panel}).out.contains("Grace"));
    EXPECT_EQ(connect().query("SELECT added_by FROM verdicts ORDER BY id DESC LIMIT 1").text(0, 0), "quality");
}

TEST_F(CentralStoreCli, ASecondSyncSendsNothing)
{
    ASSERT_EQ(sync(m_stationA, server("press_a")).exitCode, 0);
    const CliResult again = sync(m_stationA, server("press_a"));
    EXPECT_EQ(again.exitCode, 0) << again.err.toStdString();
    EXPECT_EQ(again.out, "synced 0 sessions (0 M samples), 3 already there\n");
    EXPECT_EQ(connect().query("SELECT count(*) FROM sessions").text(0, 0), "3");
}

TEST_F(CentralStoreCli, AVerdictAndANoteGivenAfterTheSyncFollowOnTheNext)
{
    ASSERT_EQ(sync(m_stationA, server("press_a")).exitCode, 0);
    // The operator decides after the session went (the GUI sends at the stop).
    QString panel;
    for (const auto& [uuid, station] : listed(m_stationA))
        if (runCli({"sessions", "--db", m_stationA, "show", uuid}).out.contains("panel-scan")) panel = uuid;
    {
        core::storage::SessionStore store(m_stationA.toStdString());
        const auto id = *store.sessionWithUuid(panel.toStdString());
        core::storage::VerdictDecision operatorSays;
        operatorSays.role = core::VerdictRole::Operator;
        operatorSays.verdict = core::Verdict::Pass;
        operatorSays.decidedBy = "Ada";
        operatorSays.note = "a smudge";
        store.decideVerdict(id, operatorSays);
        store.addAnnotation(id, {0, 1.5, "Ada", "wiped", "2026-11-24T12:00:00.000Z", "2026-11-24T12:00:00.000Z"});
    }
    const CliResult again = sync(m_stationA, server("press_a"));
    ASSERT_EQ(again.exitCode, 0) << again.err.toStdString();
    EXPECT_EQ(again.out, "synced 0 sessions (0 M samples), 3 already there\n");
    EXPECT_EQ(connect().query("SELECT verdict FROM sessions WHERE uuid = $1", {panel.toStdString()}).text(0, 0),
              "pass");
    expectSameExports(m_stationA, server("quality"));  // trail and notes as the station's
    // Once is enough: a third sync adds nothing twice.
    ASSERT_EQ(sync(m_stationA, server("press_a")).exitCode, 0);
    EXPECT_EQ(connect().query("SELECT count(*) FROM verdicts").text(0, 0), "3");
    EXPECT_EQ(connect().query("SELECT count(*) FROM annotations").text(0, 0), "2");
    // A reviewer's decision made at the station stays there: a station's
    // rows are its own facts (the sync says so and goes on).
    ASSERT_EQ(runCli({"sessions", "--db", m_stationA, "verdict", panel, "defects-found", "--by", "Grace"}).exitCode, 0);
    const CliResult fourth = sync(m_stationA, server("press_a"));
    EXPECT_EQ(fourth.exitCode, 0) << fourth.err.toStdString();
    EXPECT_TRUE(fourth.err.contains(QStringLiteral("its reviewer decisions stay at the station")))
        << fourth.err.toStdString();
    EXPECT_EQ(connect().query("SELECT count(*) FROM verdicts").text(0, 0), "3");
}

TEST_F(CentralStoreCli, ASyncKilledMidTransactionLeavesNothingAndTheNextMakesAnExactCopy)
{
    // The owner holds the pyramid table, so the sync stops inside its first
    // session's transaction, after the samples went in.
    PgConnection owner = connect();
    owner.run("BEGIN; LOCK TABLE lod IN ACCESS EXCLUSIVE MODE;");
    QProcess process;
    process.start(QStringLiteral(TACTISCOPE_CLI), {"sync", "--db", m_stationA, "--server", server("press_a")});
    PgConnection observer = connect();
    const auto waitingOnTheLock = [&] {
        return observer
                   .query("SELECT count(*) FROM pg_stat_activity WHERE usename = 'press_a' AND wait_event_type = "
                          "'Lock'")
                   .text(0, 0) == "1";
    };
    ASSERT_TRUE(tactiscope::testing::waitFor(waitingOnTheLock, 30000));
    EXPECT_EQ(listed(server("quality")).size(), 0U);  // nothing is visible half sent
    process.kill();                                   // SIGKILL
    process.waitForFinished();
    owner.run("ROLLBACK");
    const auto gone = [&] {
        return observer.query("SELECT count(*) FROM pg_stat_activity WHERE usename = 'press_a'").text(0, 0) == "0";
    };
    ASSERT_TRUE(tactiscope::testing::waitFor(gone, 30000));
    for (const char* table : {"sessions", "chunks", "lod", "channels", "events"})
        EXPECT_EQ(owner.query(std::string("SELECT count(*) FROM ") + table).text(0, 0), "0") << table;

    const CliResult again = sync(m_stationA, server("press_a"));
    ASSERT_EQ(again.exitCode, 0) << again.err.toStdString();
    EXPECT_TRUE(again.out.startsWith("synced 3 sessions")) << again.out.toStdString();
    expectSameExports(m_stationA, server("quality"));
}

TEST_F(CentralStoreCli, AnUnreachableServerExits1AndLeavesTheStationsStoreAsItWas)
{
    const std::string before = fileBytes(m_stationA.toStdString());
    const CliResult r =
        sync(m_stationA, QStringLiteral("host=%1 dbname=site user=press_a").arg(m_dir.filePath("none")));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(r.err.contains("cannot reach the central store")) << r.err.toStdString();
    EXPECT_TRUE(r.out.isEmpty());
    EXPECT_EQ(fileBytes(m_stationA.toStdString()), before);
    EXPECT_EQ(listed(m_stationA).size(), 3U);
}

// A station's store that already holds a uuid with '"' and '\\' (stored
// before imports checked uuids): before, the array literal it was spliced
// into was malformed and every later sync of the whole station failed.
// Now each uuid is a parameter: that session is refused and reported, the
// others go.
TEST_F(CentralStoreCli, AHostileUuidInAStationsStoreBlocksNothingElse)
{
    {
        core::storage::SessionStore store(m_stationA.toStdString());
        store.database().exec("UPDATE sessions SET uuid = 'x\"y\\z' WHERE id = 1");
    }
    const CliResult r = sync(m_stationA, server("press_a"));
    EXPECT_EQ(r.exitCode, 1) << r.out.toStdString() << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("x\"y\\z"))) << r.err.toStdString();
    EXPECT_EQ(listed(server()).size(), 2U);  // the station's two other sessions
}

// `sessions list` on an unreachable server exited 2 (bad input), unlike
// every other command; a password typed into the address was echoed.
TEST_F(CentralStoreCli, AnUnreachableServerListsNothingExits1AndNeverEchoesAPassword)
{
    const QString address = QStringLiteral("postgresql://press_a:s3cret@%1/site").arg(QStringLiteral("localhost:1"));
    const CliResult r = runCli({"sessions", "--db", address, "list"});
    EXPECT_EQ(r.exitCode, 1) << r.err.toStdString();
    EXPECT_FALSE(r.err.contains(QStringLiteral("s3cret"))) << r.err.toStdString();
    const CliResult keyed =
        runCli({"sessions", "--db", QStringLiteral("host=%1 dbname=site password=s3cret").arg(m_dir.filePath("none")),
                "list"});
    EXPECT_GT(keyed.exitCode, 0);
    EXPECT_FALSE(keyed.err.contains(QStringLiteral("s3cret"))) << keyed.err.toStdString();
}

// A server that stops answering once connected (frozen, its connections
// still open): before, `sync` waited indefinitely (45 s and more); only the
// connect had a timeout. Now a statement's answer is awaited at most
// TACTISCOPE_CENTRAL_ANSWER_S seconds (90 by default), then the connection
// is closed with the reason, and made again by the next statement. (No
// wall clock is asserted: without the deadline this test would not end.)
TEST_F(CentralStoreCli, AServerThatStopsAnsweringIsGivenUpAtTheDeadline)
{
    ::setenv("TACTISCOPE_CENTRAL_ANSWER_S", "2", 1);
    PgConnection connection(s_server->conninfo());
    ::unsetenv("TACTISCOPE_CENTRAL_ANSWER_S");
    s_server->pause();
    std::string message;
    try {
        connection.query("SELECT 1");
    } catch (const StorageError& e) {
        message = e.what();
    }
    s_server->resume();
    EXPECT_NE(message.find("no answer within 2 s after the connection was made"), std::string::npos) << message;
    EXPECT_FALSE(connection.isOpen());
    // The thawed server answers again, on a new connection the next
    // statement makes by itself.
    EXPECT_EQ(connection.query("SELECT 1").text(0, 0), "1");
    EXPECT_EQ(connection.reconnects(), 1);
}

TEST_F(CentralStoreCli, AUuidOnTheServerWithOtherSamplesIsRefusedNotOverwritten)
{
    ASSERT_EQ(sync(m_stationA, server("press_a")).exitCode, 0);
    // Another store holding the palpation session's uuid with other samples.
    const QString uuid = [&] {
        for (const auto& [u, station] : listed(m_stationA))
            if (runCli({"sessions", "--db", m_stationA, "show", u}).out.contains("palpation")) return u;
        return QString();
    }();
    ASSERT_FALSE(uuid.isEmpty());
    const QString forged = m_dir.filePath("forged.tactiscope");
    {
        core::storage::SessionStore store(forged.toStdString());
        const std::vector<core::ChannelDescriptor> channels{{"high", "N", core::ChannelKind::Force}};
        const auto id = store.beginSession({}, channels, 500.0, {uuid.toStdString(), "2026-11-24T09:00:00.000Z", "x"});
        tactiscope::testing::writeSamples(store, id, 1, 1000, 500.0, 99);
        store.endSession(id, core::SessionStatus::Complete);
    }
    const QString before = exported(server("quality"), uuid, "json", "before.json");
    const CliResult r = sync(forged, server("press_a"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(r.err.contains(uuid) && r.err.contains("not overwritten")) << r.err.toStdString();
    EXPECT_EQ(r.out, "synced 0 sessions (0 M samples), 0 already there\n");
    EXPECT_EQ(fileBytes(exported(server("quality"), uuid, "json", "after.json").toStdString()),
              fileBytes(before.toStdString()));
}

// Each forbidden act, done directly through libpq with the product's own
// roles (as psql would), found by an attack on the product: before, a
// station could add a "reviewer" verdict under another person's name, set
// a verdict with no trail row, un-complete a reviewed session to hide it
// from every reviewer, and take future identity values (after which other
// stations' syncs failed on a duplicate key); a reviewer could add an
// "operator" decision. Each is refused now, and what is allowed still
// works: a reviewer's own verdict, which the server makes the session's.
TEST_F(CentralStoreCli, EveryForbiddenActIsRefusedToEachRole)
{
    ASSERT_EQ(sync(m_stationA, server("press_a")).exitCode, 0);
    PgConnection owner = connect();
    const std::string id = owner.query("SELECT min(id) FROM sessions").text(0, 0);
    PgConnection station = connect("press_a");
    PgConnection reviewer = connect("quality");
    const std::string trail =
        "INSERT INTO verdicts (session_id, role, verdict, decided_by, decided_utc) VALUES ($1, $2, 'pass', $3, "
        "'2026-11-25T12:00:00Z') RETURNING id";
    EXPECT_TRUE(refused(station, trail, {id, "reviewer", "quality"}));
    EXPECT_TRUE(refused(station, "UPDATE sessions SET verdict = 'pass' WHERE id = $1 RETURNING id", {id}));
    EXPECT_TRUE(refused(station, "UPDATE sessions SET complete = false WHERE id = $1 RETURNING id", {id}));
    EXPECT_TRUE(refused(station,
                        "INSERT INTO verdicts (session_id, role, verdict, decided_utc, added_by) VALUES ($1, "
                        "'operator', 'pass', '2026-11-25T12:00:00Z', 'quality') RETURNING id",
                        {id}));
    EXPECT_TRUE(refused(station,
                        "INSERT INTO verdicts (id, session_id, role, verdict, decided_utc) OVERRIDING SYSTEM VALUE "
                        "VALUES (1000000, $1, 'operator', 'pass', '2026-11-25T12:00:00Z') RETURNING id",
                        {id}));
    EXPECT_TRUE(refused(station,
                        "INSERT INTO sessions (id, uuid, station, mode, started_utc, status) OVERRIDING SYSTEM VALUE "
                        "VALUES (1000000, '00000000-0000-4000-8000-000000000000', 'press_a', 'panel-scan', "
                        "'2026-11-25T12:00:00Z', 'complete') RETURNING id",
                        {}));
    EXPECT_TRUE(refused(reviewer, trail, {id, "operator", "press_a"}));
    EXPECT_TRUE(refused(reviewer, "UPDATE sessions SET verdict = 'pass' WHERE id = $1 RETURNING id", {id}));

    // Allowed: a reviewer's own decision, which becomes the session's verdict.
    const std::string before = owner.query("SELECT verdict FROM sessions WHERE id = $1", {id}).text(0, 0);
    const std::string decided = before == "pass" ? "defects found" : "pass";
    reviewer.query("INSERT INTO verdicts (session_id, role, verdict, decided_by, decided_utc) VALUES ($1, "
                   "'reviewer', $2, 'Grace', '2099-01-01T00:00:00Z')",
                   {id, decided});
    EXPECT_EQ(owner.query("SELECT verdict FROM sessions WHERE id = $1", {id}).text(0, 0), decided);
    // The station's next sync still goes (no squatted ids, nothing changed by hand).
    EXPECT_EQ(sync(m_stationA, server("press_a")).exitCode, 0);
}

// Two syncs of one store at once: before, both copied exactly but exited 1
// with dozens of false "duplicate key" lines. The second now waits for the
// first (an advisory lock per station) and finds everything there.
TEST_F(CentralStoreCli, TwoSyncsOfOneStoreAtOnceBothSucceed)
{
    QProcess first, second;
    for (QProcess* sync : {&first, &second})
        sync->start(QStringLiteral(TACTISCOPE_CLI), {"sync", "--db", m_stationA, "--server", server("press_a")});
    for (QProcess* sync : {&first, &second}) {
        ASSERT_TRUE(sync->waitForFinished(60000));
        EXPECT_EQ(sync->exitCode(), 0) << sync->readAllStandardError().toStdString();
    }
    EXPECT_EQ(connect().query("SELECT count(*) FROM sessions").text(0, 0), "3");
    expectSameExports(m_stationA, server("quality"));
}

TEST_F(CentralStoreCli, AStationCanNeitherDeleteNorChangeAnothersSession)
{
    ASSERT_EQ(sync(m_stationA, server("press_a")).exitCode, 0);
    const QString uuid = listed(m_stationA).begin()->first;
    // press_b does not even see it; press_a may not delete its own either.
    const CliResult b = runCli({"sessions", "--db", server("press_b"), "delete", uuid});
    EXPECT_NE(b.exitCode, 0);
    EXPECT_TRUE(b.err.contains("no session")) << b.err.toStdString();
    const CliResult a = runCli({"sessions", "--db", server("press_a"), "delete", uuid});
    EXPECT_NE(a.exitCode, 0);
    EXPECT_TRUE(a.err.contains("permission denied")) << a.err.toStdString();
    PgConnection pressB = connect("press_b");
    EXPECT_TRUE(
        refused(pressB, "UPDATE sessions SET subject = 'x' WHERE uuid = $1 RETURNING id", {uuid.toStdString()}));
    EXPECT_TRUE(refused(pressB, "DELETE FROM sessions WHERE uuid = $1 RETURNING id", {uuid.toStdString()}));
    // Nor send sessions in its name.
    const CliResult impersonated = sync(m_stationB, server("press_b"), {"--station", "press_a"});
    EXPECT_EQ(impersonated.exitCode, 1);
    EXPECT_TRUE(impersonated.err.contains("row-level security")) << impersonated.err.toStdString();
    EXPECT_EQ(listed(server("quality")).size(), 3U);
    // The owner deletes.
    const CliResult owner = runCli({"sessions", "--db", server(), "delete", uuid});
    EXPECT_EQ(owner.exitCode, 0) << owner.err.toStdString();
    EXPECT_EQ(listed(server("quality")).size(), 2U);
}

// Schema 5: no station can add a row a reviewer's reader could not bound
// (before, a gap of 2⁶² samples hung reviewers' export and analyze), nor add
// anything to a session once it is finished. What is allowed is tried too,
// so each refusal is the bound's and not some other error's.
TEST_F(CentralStoreCli, AStationCannotAddRowsThatReadersCannotBound)
{
    ASSERT_EQ(sync(m_stationA, server("press_a")).exitCode, 0);
    PgConnection station = connect("press_a");
    const std::string finished = station.query("SELECT min(id) FROM sessions").text(0, 0);
    EXPECT_TRUE(refused(station, "INSERT INTO gaps (session_id, first_index, count) VALUES ($1, 0, 5) RETURNING 1",
                        {finished}));
    EXPECT_TRUE(refused(station,
                        "INSERT INTO events (session_id, kind, start_s, end_s) VALUES ($1, 'marker', 1, 1) "
                        "RETURNING 1",
                        {finished}));

    // A session being sent, as the sync makes one.
    const std::string sending =
        station
            .query("INSERT INTO sessions (uuid, station, mode, started_utc, status, app_version) VALUES "
                   "('00000000-0000-4000-8000-00000000000a', 'press_a', 'panel-scan', '2026-11-25T12:00:00.000Z', "
                   "'complete', 'test') RETURNING id")
            .text(0, 0);
    const auto allowed = [&](const std::string& sql) { EXPECT_NO_THROW(station.query(sql, {sending})) << sql; };
    const auto refusedHere = [&](const std::string& sql) { EXPECT_TRUE(refused(station, sql, {sending})) << sql; };
    refusedHere("INSERT INTO channels (session_id, position, name, unit, kind, sample_rate_hz) VALUES "
                "($1, 0, 'A', 'V', 'raw', 'NaN') RETURNING 1");
    refusedHere("INSERT INTO channels (session_id, position, name, unit, kind, sample_rate_hz) VALUES "
                "($1, 0, 'A', 'V', 'raw', 'Infinity') RETURNING 1");
    allowed("INSERT INTO channels (session_id, position, name, unit, kind, sample_rate_hz) VALUES "
            "($1, 0, 'A', 'V', 'raw', 1000)");
    station.query("SELECT month_ready(started_utc) FROM sessions WHERE id = $1", {sending});
    const std::string month = "(SELECT session_month(started_utc) FROM sessions WHERE id = $1::bigint)";
    const std::string chunk =
        "INSERT INTO chunks (session_id, first_index, first_time_s, count, samples, session_month) VALUES ";
    refusedHere(chunk + "($1, 0, 0, 3, decode('0000000000000000', 'hex'), " + month +
                ") RETURNING 1");  // 8 bytes, not 12
    refusedHere(chunk + "($1, 0, 0, 1099511627776, decode('00000000', 'hex'), " + month + ") RETURNING 1");
    refusedHere(chunk + "($1, -1, 0, 1, decode('00000000', 'hex'), " + month + ") RETURNING 1");
    refusedHere(chunk + "($1, 4000000000000000000, 0, 1, decode('00000000', 'hex'), " + month + ") RETURNING 1");
    refusedHere(chunk + "($1, 0, 'NaN', 1, decode('00000000', 'hex'), " + month + ") RETURNING 1");
    // A chunk or a pyramid row in another month than its session's (which
    // would be detached, or kept, with that month's sessions): the month
    // before, made.
    station.query("SELECT month_ready('2026-10-15T00:00:00.000Z')");
    const std::string monthBefore = "'2026-10-01'";
    for (const std::string& row :
         {chunk + "($1, 0, 0, 2, decode('0000000000000000', 'hex'), " + monthBefore + ")",
          "INSERT INTO lod (session_id, channel, level, first_bucket, count, buckets, session_month) VALUES "
          "($1, 0, 0, 0, 1, decode('0000000000000000', 'hex'), " +
              monthBefore + ")"}) {
        std::string refusal;
        try {
            station.query(row, {sending});
        } catch (const StorageError& e) {
            refusal = e.what();
        }
        EXPECT_NE(refusal.find("belongs to the month 2026-11, not 2026-10"), std::string::npos) << row << refusal;
    }
    allowed(chunk + "($1, 0, 0, 2, decode('0000000000000000', 'hex'), " + month + ")");
    const std::string gap = "INSERT INTO gaps (session_id, first_index, count) VALUES ";
    refusedHere(gap + "($1, 2, 4611686018427387904) RETURNING 1");
    refusedHere(gap + "($1, -5, 5) RETURNING 1");
    allowed(gap + "($1, 2, 1000)");
    refusedHere("INSERT INTO lod (session_id, channel, level, first_bucket, count, buckets, session_month) VALUES "
                "($1, 0, 0, 0, 1099511627776, decode('00', 'hex'), " +
                month + ") RETURNING 1");
    refusedHere("INSERT INTO events (session_id, kind, start_s, end_s) VALUES ($1, 'marker', 'NaN', 'NaN') "
                "RETURNING 1");
    refusedHere("INSERT INTO annotations (session_id, time_s, text, created_utc, modified_utc) VALUES "
                "($1, '-Infinity', 'x', '2026-11-25T12:00:00Z', '2026-11-25T12:00:00Z') RETURNING 1");
}

// Rows older than schema 5's bounds, or the owner's, are the readers' to
// judge: a reviewer meets a gap of 2⁶² samples, or one running past the
// session's end, as damage named with its session (exit 2 at once), not as
// an export writing NaN rows until the disk is full; the other sessions
// still read.
TEST_F(CentralStoreCli, AReviewerMeetsRowsPastTheSessionsBoundsAsDamage)
{
    ASSERT_EQ(sync(m_stationA, server("press_a")).exitCode, 0);
    PgConnection owner = connect();
    const auto sessionIds = owner.query("SELECT id, uuid FROM sessions ORDER BY id");
    ASSERT_EQ(sessionIds.rows(), 3);
    owner.run("ALTER TABLE gaps DROP CONSTRAINT gaps_bounds");  // as a store from before schema 5
    owner.query("INSERT INTO gaps (session_id, first_index, count) VALUES ($1, 4000000, 4611686018427387904)",
                {sessionIds.text(0, 0)});
    // Inside the server's bounds, past this session's end by hours.
    owner.query("INSERT INTO gaps (session_id, first_index, count) VALUES ($1, 4000000, 100000000000)",
                {sessionIds.text(1, 0)});
    for (int row : {0, 1}) {
        const QString uuid = QString::fromStdString(sessionIds.text(row, 1));
        for (const QStringList& command :
             {QStringList{"export", uuid, "--format", "csv", "--output", m_dir.filePath("x.csv")},
              QStringList{"show", uuid}}) {
            const CliResult r = runCli(QStringList{"sessions", "--db", server("quality")} + command);
            EXPECT_EQ(r.exitCode, 2) << command.join(' ').toStdString() << r.out.left(300).toStdString();
            EXPECT_TRUE(r.err.contains("damaged") && r.err.contains("runs past the session's end") &&
                        r.err.contains("session " + QString::fromStdString(sessionIds.text(row, 0))))
                << r.err.toStdString();
        }
        const CliResult analyze = runCli({"analyze", "--db", server("quality"), "--session", uuid});
        EXPECT_EQ(analyze.exitCode, 2) << analyze.err.toStdString();
    }
    const QString intact = QString::fromStdString(sessionIds.text(2, 1));
    EXPECT_EQ(runCli({"sessions", "--db", server("quality"), "show", intact}).exitCode, 0);
}
