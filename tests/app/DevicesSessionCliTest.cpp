// Several probes in one session (issue 40), end to end: two `emulate`
// processes behind real ptys, one with its crystal 80 ppm slow and its
// clock already at 0.5 s, both marking one instant of the host's steady
// clock (a ramp through zero on their first channel), recorded by one
// `record --port a=… --port b=…` for 60 s. The review's time axis is the
// export's: each device's samples at its own times mapped onto the
// session's clock. The marks must lie within 0.2 ms of each other (the
// issue's target after 60 s); where each mark lies is found from the
// samples alone, by the ramp's zero crossing.
#include "devices/SteadyClock.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/TextBoard.h"

#include "core/storage/SessionStore.h"
#include "core/timing/ClockMappingJson.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

using tactiscope::testing::runCli;
using tactiscope::testing::sessionIdIn;
using tactiscope::testing::startEmulator;
using tactiscope::testing::stopEmulator;

namespace {

// Where the ramp crosses zero, by linear interpolation between the two
// samples around it, on the times given; none without a ramp.
std::optional<double> markTime_s(const QJsonArray& t, const QJsonArray& values)
{
    for (qsizetype i = 0; i + 1 < values.size(); ++i) {
        const double a = values[i].toDouble(), b = values[i + 1].toDouble();
        // Within the ramp: a step of a tenth of its height (1e-3 over 10 ms
        // is 2e-4 per 2 ms sample), far beyond the scenario's strains.
        if (a < 0.0 && b >= 0.0 && b - a > 1e-4) {
            const double ta = t[i].toDouble(), tb = t[i + 1].toDouble();
            return ta + (0.0 - a) / (b - a) * (tb - ta);
        }
    }
    return std::nullopt;
}

}  // namespace

TEST(DevicesSessionCli, TwoProbesOnTheirOwnClocksMarkOneInstantWithinATenthOfAMillisecondOnTheSessionsAxis)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope");
    const QString mark = QString::number(tactiscope::devices::steadySeconds() + 30.0, 'f', 6);
    QProcess a, b;
    ASSERT_TRUE(startEmulator(a, dir.filePath("a"), {"--scenario", "panel-scan", "--seed", "3", "--mark-at", mark}));
    ASSERT_TRUE(startEmulator(
        b, dir.filePath("b"),
        {"--scenario", "panel-scan", "--seed", "4", "--mark-at", mark, "--drift-ppm", "80", "--clock-offset", "0.5"}));
    const auto recorded = runCli({"record", "--port", "a=" + dir.filePath("a"), "--port", "b=" + dir.filePath("b"),
                                  "--seconds", "60", "--db", db});
    stopEmulator(a);
    stopEmulator(b);
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();
    const auto session = sessionIdIn(recorded.out);
    ASSERT_GT(session, 0) << recorded.out.toStdString();
    EXPECT_TRUE(recorded.out.contains(QStringLiteral(": 2 devices"))) << recorded.out.toStdString();

    // The store: one session listed, two parts, each with a mapping whose
    // uncertainty is stated, the drifts as emulated.
    {
        tactiscope::core::storage::SessionStore store(db.toStdString(),
                                                      tactiscope::core::storage::Database::Access::ReadOnly);
        ASSERT_EQ(store.sessions().size(), 1u);
        EXPECT_EQ(store.sessions().front().devices, 2u);
        const auto parts = store.parts(session);
        ASSERT_EQ(parts.size(), 2u);
        EXPECT_EQ(parts[0].deviceName, "a");
        EXPECT_EQ(parts[1].deviceName, "b");
        for (const auto& part : parts) {
            const auto clock = tactiscope::core::timing::clockMappingFromJson(part.clockJson);
            ASSERT_TRUE(clock) << part.clockJson;
            ASSERT_TRUE(clock->uncertainty_s(0.0)) << part.clockJson;
            EXPECT_GT(*clock->uncertainty_s(0.0), 0.0);
            EXPECT_NEAR(clock->drift, part.deviceName == "b" ? 80e-6 : 0.0, 10e-6) << part.clockJson;
            EXPECT_GT(clock->span_s, 55.0);
        }
        // Issue 52: the session carries its parts' verdict (defects found
        // when either found any, else pass) and counts their events.
        std::optional<tactiscope::core::Verdict> worst;
        std::uint64_t events = 0;
        for (const auto& part : parts) {
            const auto summary = store.session(part.id);
            ASSERT_TRUE(summary && summary->verdict) << part.deviceName;
            if (!worst || *summary->verdict == tactiscope::core::Verdict::DefectsFound) worst = summary->verdict;
            events += summary->eventCount;
        }
        const auto whole = store.session(session);
        EXPECT_EQ(whole->verdict, worst);
        EXPECT_EQ(whole->eventCount, events);
        EXPECT_GT(events, 0u);
    }
    {
        const auto listed = runCli(
            {"sessions", "--db", db, "list", "--json", "--verdict",
             QString::fromStdString(std::string(tactiscope::core::toString(tactiscope::core::Verdict::DefectsFound)))
                 .replace(QLatin1Char(' '), QLatin1Char('-'))});
        ASSERT_EQ(listed.exitCode, 0) << listed.err.toStdString();
        tactiscope::core::storage::SessionStore store(db.toStdString(),
                                                      tactiscope::core::storage::Database::Access::ReadOnly);
        const bool defectsFound = store.session(session)->verdict == tactiscope::core::Verdict::DefectsFound;
        EXPECT_EQ(QJsonDocument::fromJson(listed.out.toUtf8()).array().size(), defectsFound ? 1 : 0)
            << listed.out.toStdString();
    }

    // The review's axis, as exported: both marks where the host made them.
    const QString exported = dir.filePath("x.json");
    const auto exportRun =
        runCli({"sessions", "--db", db, "export", QString::number(session), "--format", "json", "--output", exported});
    ASSERT_EQ(exportRun.exitCode, 0) << exportRun.err.toStdString();
    QFile file(exported);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const auto json = QJsonDocument::fromJson(file.readAll()).object();
    const auto samples = json.value(QStringLiteral("samples")).toObject();
    const auto markA = markTime_s(samples.value("a").toObject().value("t").toArray(),
                                  samples.value("a").toObject().value("a").toArray());
    const auto markB = markTime_s(samples.value("b").toObject().value("t").toArray(),
                                  samples.value("b").toObject().value("a").toArray());
    ASSERT_TRUE(markA && markB);
    EXPECT_LE(std::abs(*markA - *markB), 0.2e-3) << "a at " << *markA << " s, b at " << *markB << " s";
    RecordProperty("mark_difference_us", std::to_string(std::llround((*markA - *markB) * 1e6)));
    std::printf("marks: a at %.6f s, b at %.6f s: %.1f µs apart\n", *markA, *markB, (*markA - *markB) * 1e6);

    // The CSV export: rows in time order on the session's clock, each
    // device's columns in its own rows; an import refuses it as a whole.
    const QString csv = dir.filePath("x.csv");
    ASSERT_EQ(runCli({"sessions", "--db", db, "export", QString::number(session), "--format", "csv", "--output", csv})
                  .exitCode,
              0);
    QFile csvFile(csv);
    ASSERT_TRUE(csvFile.open(QIODevice::ReadOnly));
    EXPECT_EQ(QString::fromUtf8(csvFile.readLine()).trimmed(),
              QStringLiteral("t [s],a/a [strain],a/b [strain],b/a [strain],b/b [strain]"));
    double previous = -1e9;
    int rows = 0, disordered = 0;
    while (!csvFile.atEnd()) {
        const double t = QString::fromUtf8(csvFile.readLine()).section(QLatin1Char(','), 0, 0).toDouble();
        disordered += t < previous;
        previous = t;
        ++rows;
    }
    EXPECT_EQ(disordered, 0);
    EXPECT_GT(rows, 2 * 29000);  // both devices' samples, 60 s at 500 Hz each
    const auto imported = runCli({"import", "--db", dir.filePath("t.tactiscope"), csv});
    EXPECT_EQ(imported.exitCode, 2);
    EXPECT_TRUE(imported.err.contains(QStringLiteral("a session of several devices"))) << imported.err.toStdString();

    // What reads one device's samples names the parts instead.
    for (const QStringList& oneDevice :
         {QStringList{"report", "--db", db, "--session", QString::number(session), "--output", dir.filePath("r.pdf")},
          QStringList{"analyze", "--db", db, "--session", QString::number(session)}}) {
        const auto refused = runCli(oneDevice);
        EXPECT_EQ(refused.exitCode, 2) << oneDevice.front().toStdString();
        EXPECT_TRUE(refused.err.contains(
            QStringLiteral("holds 2 devices (a: session %1, b: session %2)").arg(session + 1).arg(session + 2)))
            << refused.err.toStdString();
    }

    // `sessions show` lists the devices and their clocks.
    const auto shown = runCli({"sessions", "--db", db, "show", QString::number(session)});
    ASSERT_EQ(shown.exitCode, 0) << shown.err.toStdString();
    EXPECT_TRUE(shown.out.contains(QRegularExpression(QStringLiteral("part +a \\(session"))))
        << shown.out.toStdString();
    EXPECT_TRUE(shown.out.contains(QRegularExpression(QStringLiteral("part +b \\(session"))));
    EXPECT_TRUE(
        shown.out.contains(QRegularExpression(QStringLiteral("clock +\\+?-?[0-9.]+ s at the start ± [0-9.]+ ms, "
                                                             "[0-9.]+ ± [0-9.]+ ppm slow"))))
        << shown.out.toStdString();
    // Its verdict is said as its parts' verdicts, and its events are theirs.
    EXPECT_TRUE(shown.out.contains(QStringLiteral("(the worst of its parts': a "))) << shown.out.toStdString();
    int partEvents = 0;
    for (const auto& m : QRegularExpression(QStringLiteral("\nevents +([0-9]+) live\n")).globalMatch(shown.out))
        partEvents += m.captured(1).toInt();
    EXPECT_GT(partEvents, 0);
    EXPECT_TRUE(shown.out.contains(QStringLiteral("events            %1 with its parts'").arg(partEvents)))
        << shown.out.toStdString();
}

// Each device its own filters and math channels (issue 57): --filter-channel
// and --math say whose as DEVICE/…; each part stores its own setup, and the
// session's CSV export carries each part's filtered and math channels in
// its own rows, the math channel's values being its expression over that
// device's stored samples.
TEST(DevicesSessionCli, EachDeviceFiltersAndComputesItsOwnSignalAndTheExportCarriesThem)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope");
    QProcess a, b;
    ASSERT_TRUE(startEmulator(a, dir.filePath("a"), {"--scenario", "panel-scan", "--seed", "3"}));
    ASSERT_TRUE(startEmulator(b, dir.filePath("b"), {"--scenario", "panel-scan", "--seed", "4"}));
    const QStringList ports{"--port", "a=" + dir.filePath("a"), "--port", "b=" + dir.filePath("b")};
    const QStringList record = QStringList{"record", "--db", db, "--seconds", "2"} + ports;
    // Without its device a channel or a math channel is refused, naming them.
    for (const auto& [extra, said] :
         {std::pair{QStringList{"--notch", "50", "--filter-channel", "a"},
                    "--filter-channel 'a': with several devices, "
                    "say whose as DEVICE/CHANNEL (the devices: "
                    "a, b)"},
          std::pair{QStringList{"--math", "d[µε]=a - b"}, "say whose as DEVICE/NAME[UNIT]=EXPR"},
          std::pair{QStringList{"--notch", "50", "--filter-channel", "c/a"},
                    "no device is named 'c' (the devices: a, b)"},
          std::pair{QStringList{"--notch", "50", "--filter-channel", "b/z"}, "b: --filter-channel: the device has no "
                                                                             "channel 'z'"},
          // A filter of one device's own: DEVICE=VALUE, a device that is here.
          std::pair{QStringList{"--lowpass", "c=20"}, "--lowpass: no device is named 'c' (the devices: a, b)"},
          std::pair{QStringList{"--lowpass", "b=20", "--order", "a=6"}, "a: --order is the Butterworth filters'"},
          std::pair{QStringList{"--lowpass", "b=20", "--filter-channel", "a/a"}, "--filter-channel a/a: a has no "
                                                                                 "filter"},
          // Another device's channel in a math channel would be a division.
          std::pair{QStringList{"--math", "b/diff[]=a/a - b"}, "'a/a' would read as a division"}}) {
        const auto refused = runCli(record + extra);
        EXPECT_EQ(refused.exitCode, 2) << extra.join(' ').toStdString();
        EXPECT_TRUE(refused.err.contains(QString::fromUtf8(said))) << refused.err.toStdString();
    }
    const auto recorded = runCli(record + QStringList{"--notch", "a=50", "--filter-channel", "a/a", "--lowpass", "b=40",
                                                      "--math", "b/diff[µε]=a - b"});
    stopEmulator(a);
    stopEmulator(b);
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();
    const auto session = sessionIdIn(recorded.out);
    {
        tactiscope::core::storage::SessionStore store(db.toStdString(),
                                                      tactiscope::core::storage::Database::Access::ReadOnly);
        const auto parts = store.parts(session);
        ASSERT_EQ(parts.size(), 2u);
        const auto setupOf = [&](std::size_t p) {
            return QJsonDocument::fromJson(QByteArray::fromStdString(store.session(parts[p].id)->metadata.signalSetup))
                .object();
        };
        const auto aSetup = setupOf(0), bSetup = setupOf(1);
        ASSERT_EQ(aSetup.value("filters").toArray().size(), 1);
        EXPECT_EQ(aSetup.value("filters").toArray()[0].toObject().value("channel").toString(), "a");
        EXPECT_TRUE(aSetup.value("math").toArray().isEmpty());
        // b's own filter, with none of its channels named, is on each of them.
        ASSERT_EQ(bSetup.value("filters").toArray().size(), 2);
        EXPECT_EQ(bSetup.value("filters").toArray()[1].toObject().value("channel").toString(), "b");
        EXPECT_EQ(bSetup.value("math").toArray(), QJsonArray{QStringLiteral("diff[µε]=a - b")});
    }
    const auto shown = runCli({"sessions", "--db", db, "show", QString::number(session)});
    EXPECT_TRUE(shown.out.contains(QStringLiteral("a: mains notch 50 Hz"))) << shown.out.toStdString();
    EXPECT_TRUE(shown.out.contains(QStringLiteral("diff[µε]=a - b"))) << shown.out.toStdString();

    // The export's own math channel over b reads b's channels filtered, as
    // the recorded one did.
    const QString csv = dir.filePath("x.csv");
    const auto exported = runCli({"sessions", "--db", db, "export", QString::number(session), "--format", "csv",
                                  "--output", csv, "--math", "b/q[µε]=a - b"});
    ASSERT_EQ(exported.exitCode, 0) << exported.err.toStdString();
    QFile csvFile(csv);
    ASSERT_TRUE(csvFile.open(QIODevice::ReadOnly));
    EXPECT_EQ(QString::fromUtf8(csvFile.readLine()).trimmed(),
              QString::fromUtf8("t [s],a/a [strain],a/b [strain],a/a.filtered [strain],b/a [strain],b/b [strain],"
                                "b/a.filtered [strain],b/b.filtered [strain],b/diff [µε],b/q [µε]"));
    int aRows = 0, bRows = 0;
    while (!csvFile.atEnd()) {
        const QStringList cells = QString::fromUtf8(csvFile.readLine()).trimmed().split(QLatin1Char(','));
        ASSERT_EQ(cells.size(), 10);
        if (!cells[1].isEmpty()) {  // a's row: its filtered channel beside its samples, b's cells empty
            ++aRows;
            EXPECT_FALSE(cells[3].isEmpty());
            EXPECT_TRUE(cells[4].isEmpty() && cells[8].isEmpty() && cells[9].isEmpty());
            continue;
        }
        ++bRows;
        // Computed values keep every digit: the math of the filtered values
        // to a rounding, the export's the recorded one's exactly.
        const double filteredA = cells[6].toDouble(), filteredB = cells[7].toDouble();
        EXPECT_NEAR(cells[8].toDouble(), (filteredA - filteredB) * 1e6,
                    1e-12 * (std::abs(filteredA) + std::abs(filteredB)) * 1e6);
        EXPECT_EQ(cells[9], cells[8]);
    }
    EXPECT_GT(aRows, 900);  // 2 s at 500 Hz each
    EXPECT_GT(bRows, 900);
    QFile meta(dir.filePath("x.meta.json"));
    ASSERT_TRUE(meta.open(QIODevice::ReadOnly));
    const QJsonObject metadata = QJsonDocument::fromJson(meta.readAll()).object();
    QStringList computed;
    for (const auto& column : metadata.value("computed_columns").toArray())
        computed << column.toObject().value("column").toString();
    EXPECT_EQ(computed, (QStringList{"a/a.filtered [strain]", "b/a.filtered [strain]", "b/b.filtered [strain]",
                                     QString::fromUtf8("b/diff [µε]"), QString::fromUtf8("b/q [µε]")}));
    // The whole session holds no samples of its own: each device's count is its own.
    EXPECT_FALSE(metadata.value("session").toObject().contains("samples_per_channel"));
    EXPECT_FALSE(metadata.contains("exported_range"));
    for (const auto& device : metadata.value("devices").toArray())
        EXPECT_EQ(device.toObject().value("exported_range").toObject().value("count").toInt(),
                  device.toObject().value("session").toObject().value("samples_per_channel").toInt());
    // A math channel over the whole session would mix two clocks: refused, naming the parts.
    const auto mathRefused = runCli({"sessions", "--db", db, "export", QString::number(session), "--format", "csv",
                                     "--output", dir.filePath("m.csv"), "--math", "q[µε]=a - b"});
    EXPECT_EQ(mathRefused.exitCode, 2);
    EXPECT_TRUE(mathRefused.err.contains(QStringLiteral("say whose as DEVICE/NAME[UNIT]=EXPR (the devices: a, b)")))
        << mathRefused.err.toStdString();
}

// A probe that goes while the other records on: a gap at the end of its
// part only; the other's part is whole.
TEST(DevicesSessionCli, AProbeLostMidSessionIsAGapInItsOwnPartOnly)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope");
    QProcess a, b;
    ASSERT_TRUE(startEmulator(a, dir.filePath("a"), {"--scenario", "panel-scan", "--seconds", "2"}));
    ASSERT_TRUE(startEmulator(b, dir.filePath("b"), {"--scenario", "panel-scan"}));
    const auto recorded = runCli({"record", "--port", "a=" + dir.filePath("a"), "--port", "b=" + dir.filePath("b"),
                                  "--seconds", "6", "--db", db});
    stopEmulator(a);
    stopEmulator(b);
    EXPECT_EQ(recorded.exitCode, 1) << recorded.out.toStdString() << recorded.err.toStdString();
    EXPECT_TRUE(recorded.err.contains(QStringLiteral("a: the probe was lost at"))) << recorded.err.toStdString();
    tactiscope::core::storage::SessionStore store(db.toStdString(),
                                                  tactiscope::core::storage::Database::Access::ReadOnly);
    const auto parts = store.parts(sessionIdIn(recorded.out));
    ASSERT_EQ(parts.size(), 2u);
    std::uint64_t lostA = 0;
    for (const auto& gap : store.gaps(parts[0].id)) lostA += gap.count;
    EXPECT_GT(lostA, 1000u);  // about 4 s at 500 Hz
    EXPECT_TRUE(store.gaps(parts[1].id).empty());
    EXPECT_GT(store.sampleCount(parts[1].id), 2500u);
}

TEST(DevicesSessionCli, RefusesWhatASessionOfSeveralDevicesCannotTake)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope");
    const auto usage = [&](const QStringList& extra, const char* said) {
        const auto result = runCli(QStringList{"record", "--db", db, "--seconds", "1"} + extra);
        EXPECT_EQ(result.exitCode, 2) << extra.join(' ').toStdString();
        EXPECT_TRUE(result.err.contains(QString::fromUtf8(said))) << result.err.toStdString();
    };
    usage({"--port", "a=/dev/null", "--port", "a=/dev/zero"}, "each name given once");
    usage({"--port", "a/b=/dev/null", "--port", "c=/dev/zero"}, "a word without '/'");
    usage({"--port", "a=/dev/null", "--port", "b=/dev/zero", "--mode", "general"}, "for one device");
    // Each port's link: one value for every port, or once for each named.
    usage({"--port", "a=/dev/null", "--port", "b=/dev/zero", "--protocol", "c=text"},
          "--protocol: no port is named 'c'");
    usage({"--port", "a=/dev/null", "--port", "b=/dev/zero", "--baud", "9600", "--baud", "115200"},
          "--baud: give one value for every port, or NAME=VALUE once for each port named");
    usage({"--port", "a=/dev/null", "--port", "b=/dev/zero", "--rate", "a=10", "--rate", "a=20"},
          "--rate: 'a' is given twice");
    usage({"--port", "a=/dev/null", "--port", "b=/dev/zero", "--protocol", "a=lines"},
          "--protocol must be binary or text");
    EXPECT_TRUE(QDir(dir.path()).entryList({"*.tactiscope"}).size() <= 1);
    if (QFile::exists(db)) {
        tactiscope::core::storage::SessionStore store(db.toStdString(),
                                                      tactiscope::core::storage::Database::Access::ReadOnly);
        EXPECT_TRUE(store.sessions().empty()) << "nothing was recorded";
    }
}

// A maker's board printing lines and a TSP/1 probe in one session, each
// over its own link (--protocol board=text; --rate p=500 is asked of the
// probe, the board's is timed): both parts begin at the session's
// instant, although the probe streamed while the board was timed, and
// last as long.
TEST(DevicesSessionCli, ABoardPrintingLinesAndATsp1ProbeRecordIntoOneSessionEachOverItsOwnLink)
{
    QTemporaryDir dir;
    QProcess probe;
    ASSERT_TRUE(startEmulator(probe, dir.filePath("probe"), {"--scenario", "panel-scan"}));
    tactiscope::testing::TextBoard board(
        dir.filePath("board").toStdString(),
        {100.0, [](std::uint64_t n) { return "force[mN]:" + std::to_string(static_cast<double>(n % 100)) + "\r\n"; }, 2,
         1e-3, false});
    ASSERT_TRUE(board.ok());
    const QString db = dir.filePath("s.tactiscope");
    const auto recorded =
        runCli({"record", "--port", "p=" + dir.filePath("probe"), "--port", "board=" + dir.filePath("board"),
                "--protocol", "board=text", "--baud", "board=115200", "--rate", "p=500", "--seconds", "2", "--db", db,
                "--units", "board/force=mN"});
    stopEmulator(probe);
    ASSERT_EQ(recorded.exitCode, 0) << recorded.out.toStdString() << recorded.err.toStdString();
    tactiscope::core::storage::SessionStore store(db.toStdString(),
                                                  tactiscope::core::storage::Database::Access::ReadOnly);
    const auto parts = store.parts(sessionIdIn(recorded.out));
    ASSERT_EQ(parts.size(), 2u);
    for (const auto& part : parts) {
        SCOPED_TRACE(part.deviceName);
        const auto channels = store.channels(part.id);
        ASSERT_FALSE(channels.empty());
        const double seconds = static_cast<double>(store.sampleCount(part.id)) / channels[0].sampleRate_hz;
        EXPECT_NEAR(seconds, 2.0, 0.1) << "from the session's instant, for as long as the other part";
        if (part.deviceName == "board") {
            EXPECT_EQ(channels[0].descriptor.name, "force");
            EXPECT_EQ(channels[0].descriptor.unit, "N");
            EXPECT_NEAR(channels[0].sampleRate_hz, 100.0, 0.1);
        } else {
            EXPECT_EQ(part.deviceName, "p");
            EXPECT_EQ(store.session(part.id)->metadata.mode, tactiscope::core::Mode::PanelScan);
        }
    }
}
