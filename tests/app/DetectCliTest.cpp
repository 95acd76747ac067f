// `tactiscope-cli detect` as other tools use it: a generated recording with
// known defects in, events and per-sample output out; every bad input gives
// exit code 2 and one line on stderr.
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/TextFiles.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTextStream>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using tactiscope::testing::CliResult;
using tactiscope::testing::readBytes;
using tactiscope::testing::runCli;
using tactiscope::testing::writeText;

namespace {

// 6 s at 500 Hz of quiet gauges (σ = 1 µε, well below ε = 7 µε) with two
// passes over a defect: from 1 s to 2 s b repeats a 40 ms later (A then B),
// from 4 s to 5 s a repeats b 60 ms later (B then A).
void writeRecording(const QString& path)
{
    std::mt19937_64 random(99);
    std::normal_distribution<double> quiet(0.0, 1e-6), loud(0.0, 3e-4);
    const int n = 3000;
    std::vector<double> a(n), b(n);
    for (int i = 0; i < n; ++i) {
        a[static_cast<std::size_t>(i)] = quiet(random);
        b[static_cast<std::size_t>(i)] = quiet(random);
    }
    for (int i = 500; i < 1000; ++i) a[static_cast<std::size_t>(i)] = loud(random);
    for (int i = 520; i < 1020; ++i) b[static_cast<std::size_t>(i)] = a[static_cast<std::size_t>(i - 20)];
    for (int i = 2000; i < 2500; ++i) b[static_cast<std::size_t>(i)] = loud(random);
    for (int i = 2030; i < 2530; ++i) a[static_cast<std::size_t>(i)] = b[static_cast<std::size_t>(i - 30)];
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    QTextStream out(&file);
    out << "t,a,b\n";
    for (int i = 0; i < n; ++i)
        out << QString::number(i / 500.0, 'g', 17) << ',' << QString::number(a[static_cast<std::size_t>(i)], 'g', 17)
            << ',' << QString::number(b[static_cast<std::size_t>(i)], 'g', 17) << '\n';
}

QStringList lines(const QString& path)
{
    return QString::fromUtf8(readBytes(path)).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
}

class DetectCli : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_TRUE(m_dir.isValid());
        writeRecording(path("scan.csv"));
    }
    QString path(const char* name) const { return m_dir.filePath(QString::fromLatin1(name)); }

    QTemporaryDir m_dir;
};

}  // namespace

TEST_F(DetectCli, FindsBothPassesWithTheirDirectionLagAndSpeed)
{
    const CliResult run = runCli({"detect", path("scan.csv"), "--json", "--spacing-mm", "20"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonObject result = QJsonDocument::fromJson(run.out.toUtf8()).object();
    EXPECT_EQ(result["samples"].toInt(), 3000);
    EXPECT_EQ(result["lags"].toInt(), 75);
    EXPECT_GT(result["elapsed_s"].toDouble(), 0.0);
    EXPECT_GT(result["samples_per_s"].toDouble(), 0.0);

    const QJsonArray events = result["events"].toArray();
    ASSERT_EQ(events.size(), 2) << run.out.toStdString();
    const QJsonObject first = events[0].toObject(), second = events[1].toObject();
    EXPECT_EQ(first["direction"].toInt(), 1);
    EXPECT_DOUBLE_EQ(first["lag_ms"].toDouble(), 40.0);
    EXPECT_DOUBLE_EQ(first["speed_mm_s"].toDouble(), 500.0);  // 20 mm in 40 ms
    // An event may outlast its burst: the exponential weights remember the
    // burst's covariance (≈ 9·10⁻⁸) until ε² = 4.9·10⁻¹¹ dominates, about
    // ln(9e-8 / 4.9e-11) ≈ 7.5 λ later (λ = c: 0.30 s here, 0.45 s below).
    EXPECT_GE(first["start_s"].toDouble(), 1.0);
    EXPECT_LE(first["end_s"].toDouble(), 2.04 + 0.30);
    EXPECT_GT(first["peak_r"].toDouble(), 0.99);
    EXPECT_EQ(second["direction"].toInt(), -1);
    EXPECT_DOUBLE_EQ(second["lag_ms"].toDouble(), 60.0);
    EXPECT_NEAR(second["speed_mm_s"].toDouble(), 20.0 / 0.060, 1e-9);
    EXPECT_GE(second["start_s"].toDouble(), 4.0);
    EXPECT_LE(second["end_s"].toDouble(), 5.06 + 0.45);
}

TEST_F(DetectCli, WritesOneOutputRowPerSampleAndThreadsChangeNothing)
{
    ASSERT_EQ(runCli({"detect", path("scan.csv"), "--output", path("one.csv")}).exitCode, 0);
    ASSERT_EQ(runCli({"detect", path("scan.csv"), "--output", path("two.csv"), "--threads", "2"}).exitCode, 0);
    const QStringList rows = lines(path("one.csv"));
    ASSERT_EQ(rows.size(), 3001);
    EXPECT_EQ(rows.front(), "t,out,rab,rba,lag_ab_ms,lag_ba_ms");
    EXPECT_EQ(lines(path("two.csv")), rows);
    // Mid-way through the first pass: A then B at the 40 ms lag.
    const QStringList middle = rows[751].split(',');  // sample 750, t = 1.5 s
    EXPECT_EQ(middle[0], "1.5");
    EXPECT_EQ(middle[1], "1");
    EXPECT_EQ(middle[4], "40");
    EXPECT_EQ(rows[1].split(',')[1], "0");  // quiet at the start
}

// A scan whose rows skip whole intervals (an export of a session that lost
// samples leaves their rows out) is detected in gap-free stretches: cut
// between the passes, the events are the whole file's; cut inside a pass,
// no event spans the cut; the per-sample rows are the file's own, none
// made up in a gap. Half an interval off is still an irregular time base.
TEST_F(DetectCli, AScanWithGapsIsDetectedInStretchesNeverBridgingOne)
{
    const QStringList rows = lines(path("scan.csv"));
    const auto without = [&](const char* name, int from, int to) {  // samples [from, to) left out
        QStringList kept{rows.front()};
        for (int i = 0; i + 1 < rows.size(); ++i)
            if (i < from || i >= to) kept << rows[i + 1];
        writeText(path(name), kept.join('\n') + '\n');
    };
    without("between.csv", 1500, 1600);  // 3.0 to 3.2 s, quiet
    without("inside.csv", 700, 750);     // 1.4 to 1.5 s, in the first pass
    const auto events = [&](const char* name) {
        const CliResult run = runCli({"detect", path(name), "--json"});
        EXPECT_EQ(run.exitCode, 0) << run.err.toStdString();
        return std::pair{QJsonDocument::fromJson(run.out.toUtf8()).object(), run.err};
    };
    const auto [whole, quiet] = events("scan.csv");
    const auto [between, said] = events("between.csv");
    EXPECT_TRUE(quiet.isEmpty()) << quiet.toStdString();
    EXPECT_TRUE(said.contains(QStringLiteral("skips whole intervals: 1 gap (100 samples missing")))
        << said.toStdString();
    // Where: the rows either side (500 Hz, samples 1500 to 1599 out) and the line after it.
    EXPECT_TRUE(said.contains(QStringLiteral("Between t = 2.998 and 3.2 s (line 1502)."))) << said.toStdString();
    EXPECT_EQ(between["samples"].toInt(), 2900);
    // The same events; after the restart the detector's memory of the quiet
    // before the gap is gone, which moves the second pass's R in its last digits.
    const QJsonArray cut = between["events"].toArray(), all = whole["events"].toArray();
    ASSERT_EQ(cut.size(), 2);
    ASSERT_EQ(all.size(), 2);
    for (qsizetype e = 0; e < 2; ++e) {
        const QJsonObject a = cut[e].toObject(), b = all[e].toObject();
        for (const char* key : {"direction", "lag_ms", "start_s", "end_s"}) EXPECT_EQ(a[key], b[key]) << key;
        EXPECT_NEAR(a["peak_r"].toDouble(), b["peak_r"].toDouble(), 1e-9);
    }

    const auto [inside, told] = events("inside.csv");
    EXPECT_TRUE(told.contains(QStringLiteral("(50 samples missing"))) << told.toStdString();
    for (const auto& value : inside["events"].toArray()) {
        const QJsonObject event = value.toObject();
        EXPECT_FALSE(event["start_s"].toDouble() < 1.4 && event["end_s"].toDouble() > 1.5)
            << "an event across the gap: " << QJsonDocument(event).toJson().toStdString();
    }
    ASSERT_EQ(runCli({"detect", path("inside.csv"), "--output", path("inside-rows.csv")}).exitCode, 0);
    const QStringList written = lines(path("inside-rows.csv"));
    EXPECT_EQ(written.size(), 1 + 2950);
    for (const QString& row : written.mid(1)) {
        const double t = row.section(QLatin1Char(','), 0, 0).toDouble();
        EXPECT_FALSE(t > 1.399 && t < 1.5) << row.toStdString();
    }

    writeText(path("half.csv"), "t,a,b\n0,0,0\n0.002,0,0\n0.004,0,0\n0.009,0,0\n0.011,0,0\n0.013,0,0\n");
    const CliResult half = runCli({"detect", path("half.csv")});
    EXPECT_EQ(half.exitCode, 2);
    EXPECT_TRUE(half.err.contains(QStringLiteral("line 5: time is irregular"))) << half.err.toStdString();
}

TEST_F(DetectCli, OtherColumnNamesTheSlidingWindowAndFaceToFaceGauges)
{
    // Same data under other names, b negated as a face-to-face mount gives.
    QStringList renamed{"time,left,right"};
    for (const QString& row : lines(path("scan.csv")).mid(1)) {
        const QStringList cells = row.split(',');
        renamed << cells[0] + ',' + cells[1] + ',' + QString::number(-cells[2].toDouble(), 'g', 17);
    }
    writeText(path("renamed.csv"), renamed.join('\n') + '\n');
    const CliResult run = runCli({"detect", path("renamed.csv"), "--columns", "time,left,right", "--face-to-face",
                                  "--window-ms", "100", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonArray events = QJsonDocument::fromJson(run.out.toUtf8()).object()["events"].toArray();
    ASSERT_EQ(events.size(), 2);
    EXPECT_EQ(events[0].toObject()["direction"].toInt(), 1);
    EXPECT_EQ(events[1].toObject()["direction"].toInt(), -1);
}

TEST_F(DetectCli, BadInputExitsWithCodeTwoAndOneClearLine)
{
    writeText(path("empty.csv"), "");
    writeText(path("header.csv"), "t,a,b\n");
    writeText(path("word.csv"), "t,a,b\n0,1e-6,2e-6\n0.002,oops,1e-6\n");
    writeText(path("backwards.csv"), "t,a,b\n0,0,0\n0.002,0,0\n0.001,0,0\n");
    writeText(path("irregular.csv"), "t,a,b\n0,0,0\n0.002,0,0\n0.004,0,0\n0.009,0,0\n0.011,0,0\n");
    writeText(path("ragged.csv"), "t,a,b\n0,0,0\n0.002,0\n");
    const std::vector<std::pair<QStringList, QString>> cases{
        {{"detect", path("missing.csv")}, "cannot open"},
        {{"detect", path("empty.csv")}, "is empty"},
        {{"detect", path("header.csv")}, "no data rows"},
        {{"detect", path("scan.csv"), "--columns", "t,a,c"}, "no column 'c'"},
        {{"detect", path("word.csv")}, "line 3, column 'a': 'oops' is not a number"},
        {{"detect", path("backwards.csv")}, "line 4: time is not increasing"},
        {{"detect", path("irregular.csv")}, "line 5: time is irregular"},
        {{"detect", path("ragged.csv")}, "line 3 has 2 fields"},
        {{"detect", path("scan.csv"), "--lags-ms", "10:2:2"}, "--lags-ms"},
        {{"detect", path("scan.csv"), "--lags-ms", "2-150"}, "START:STOP:STEP"},
        {{"detect", path("scan.csv"), "--threshold", "1.5"}, "threshold"},
        {{"detect", path("scan.csv"), "--epsilon", "abc"}, "--epsilon"},
        {{"detect", path("scan.csv"), "--threads", "0"}, "--threads"},
        {{"detect"}, "exactly one INPUT.csv"},
    };
    for (const auto& [arguments, message] : cases) {
        const CliResult run = runCli(arguments);
        EXPECT_EQ(run.exitCode, 2) << arguments.join(' ').toStdString();
        const QString firstLine = run.err.section('\n', 0, 0);
        EXPECT_TRUE(firstLine.startsWith("tactiscope-cli: ")) << run.err.toStdString();
        EXPECT_TRUE(firstLine.contains(message)) << firstLine.toStdString() << " lacks " << message.toStdString();
        EXPECT_TRUE(run.out.isEmpty());
    }
    // Data errors are one line: no usage dump for a problem in the file.
    EXPECT_EQ(runCli({"detect", path("word.csv")}).err.count('\n'), 1);
}

TEST_F(DetectCli, AValueTheDetectorCannotSquareIsRefusedNamingItsCell)
{
    // b = 1e308 on line 101: before, it was accepted and every output after
    // it was inf or NaN, so nothing more was reported, exit 0 (issue 19).
    QStringList rows = lines(path("scan.csv"));
    QStringList cells = rows[100].split(QLatin1Char(','));
    cells[2] = QStringLiteral("1e308");
    rows[100] = cells.join(QLatin1Char(','));
    writeText(path("poisoned.csv"), rows.join(QLatin1Char('\n')) + QLatin1Char('\n'));
    const CliResult run = runCli({"detect", path("poisoned.csv")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.err.contains(QStringLiteral("line 101, column 'b': 1e+308 is beyond what the detector can use")))
        << run.err.toStdString();
}

TEST_F(DetectCli, AFaultLateInALongFileLeavesNoOutputBehind)
{
    // 150 000 rows: the detector has streamed two blocks of output rows when
    // the bad cell on line 140 002 comes. The output file must not exist.
    QString text = QStringLiteral("t,a,b\n");
    for (int i = 0; i < 150000; ++i) {
        const QString b = i == 140000 ? QStringLiteral("oops") : QStringLiteral("0");
        text += QStringLiteral("%1,0,%2\n").arg(QString::number(i / 500.0, 'g', 17), b);
    }
    writeText(path("long.csv"), text);
    const CliResult run = runCli({"detect", path("long.csv"), "--output", path("out.csv")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.err.contains(QStringLiteral("line 140002, column 'b': 'oops' is not a number")))
        << run.err.toStdString();
    EXPECT_FALSE(QFile::exists(path("out.csv")));
    EXPECT_TRUE(QDir(QFileInfo(path("out.csv")).path())
                    .entryList({QStringLiteral(".out.csv.*")}, QDir::Files | QDir::Hidden)
                    .isEmpty())
        << "a temporary was left";
}

// The sites contract (other tools read it): `detect --json` lists the
// simulator's one dent (at +30 mm along cantilever A's stroke, +37.5 mm for
// the probe's centre) as one site of every crossing, and `sessions show
// --json` of the same scan imported as a panel scan lists the same site.
TEST(DetectSitesCli, JsonListsTheDefectSitesAndSessionsShowTheSame)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("scan.csv");
    ASSERT_EQ(runCli({"simulate", "--seconds", "20", "--seed", "3", "--output", csv}).exitCode, 0);
    const CliResult detect = runCli({"detect", csv, "--json", "--spacing-mm", "15"});
    ASSERT_EQ(detect.exitCode, 0) << detect.err.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(detect.out.toUtf8()).object();
    const QJsonArray sites = o["sites"].toArray();
    ASSERT_EQ(sites.size(), 1) << detect.out.toStdString();
    const QJsonObject site = sites[0].toObject();
    // Issue 55's keys: the kind, and the place's standard uncertainty
    // (k = 1), which covers the dent.
    EXPECT_EQ(site["kind"].toString(), QStringLiteral("site"));
    ASSERT_TRUE(site["position_u_mm"].isDouble()) << detect.out.toStdString();
    EXPECT_GT(site["position_u_mm"].toDouble(), 0.0);
    EXPECT_LE(std::abs(site["position_mm"].toDouble() - 37.5), 2.0 * site["position_u_mm"].toDouble());
    EXPECT_FALSE(site.contains("from_mm"));
    EXPECT_GE(site["spread_mm"].toDouble(), 0.0);
    EXPECT_EQ(site["crossings"].toInt(), o["events"].toArray().size());
    EXPECT_EQ(site["a_then_b"].toInt() + site["b_then_a"].toInt(), site["crossings"].toInt());
    EXPECT_LT(site["first_s"].toDouble(), site["last_s"].toDouble());
    EXPECT_TRUE(o["sites_method"].toString().startsWith(QStringLiteral("scan speed")))
        << o["sites_method"].toString().toStdString();

    // A panel scan recorded live: its stored defects' sites.
    const QString db = dir.filePath("s.tactiscope");
    const CliResult record = tactiscope::testing::recordEmulated(dir.path(), db, QStringLiteral("panel-scan"), 8);
    ASSERT_EQ(record.exitCode, 0) << record.err.toStdString();
    const CliResult show = runCli({"sessions", "--db", db, "show", "last", "--json"});
    ASSERT_EQ(show.exitCode, 0) << show.err.toStdString();
    const QJsonObject shown = QJsonDocument::fromJson(show.out.toUtf8()).object();
    ASSERT_TRUE(shown.contains("sites")) << show.out.toStdString();
    int crossings = 0;
    for (const auto stored : shown["sites"].toArray()) {
        const QJsonObject entry = stored.toObject();
        crossings += entry["crossings"].toInt();
        const QString kind = entry["kind"].toString();
        EXPECT_TRUE(kind == "site" || kind == "span" || kind == "unplaced") << kind.toStdString();
        // A place has its uncertainty; an unplaced site has neither.
        EXPECT_EQ(entry["position_u_mm"].isNull(), entry["position_mm"].isNull()) << show.out.toStdString();
        EXPECT_EQ(entry.contains("from_mm"), kind == "span");
    }
    EXPECT_GE(crossings, 1) << show.out.toStdString();
}

// A panel line's recording through TSP/1 carries the line's encoder (the
// emulator's channel "x", of the kind position): `sessions show --json`
// places the dent (at +30 mm on the encoder's scale) from it within 1 mm,
// and says so (the phases alone placed it at 448 mm on a ±100 mm stroke).
TEST(DetectSitesCli, APanelLinesPositionChannelPlacesItsDentWithinAMillimetre)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("line.tactiscope");
    const CliResult record = tactiscope::testing::recordEmulated(dir.path(), db, QStringLiteral("panel-line"), 16);
    ASSERT_EQ(record.exitCode, 0) << record.err.toStdString();
    const CliResult show = runCli({"sessions", "--db", db, "show", "last", "--json"});
    ASSERT_EQ(show.exitCode, 0) << show.err.toStdString();
    const QJsonObject shown = QJsonDocument::fromJson(show.out.toUtf8()).object();
    EXPECT_EQ(shown["sites_method"].toString(), QStringLiteral("from the position channel")) << show.out.toStdString();
    const QJsonArray sites = shown["sites"].toArray();
    ASSERT_EQ(sites.size(), 1) << show.out.toStdString();
    const QJsonObject site = sites[0].toObject();
    EXPECT_EQ(site["kind"].toString(), QStringLiteral("site"));
    EXPECT_NEAR(site["position_mm"].toDouble(), 30.0, 1.0) << show.out.toStdString();
    EXPECT_GE(site["crossings"].toInt(), 6);
    // The text says so too, a line per site under the method (fresh eyes).
    const CliResult text = runCli({"sessions", "--db", db, "show", "last"});
    EXPECT_TRUE(text.out.contains(
        QRegularExpression(QStringLiteral("\\nsites +1 \\(from the position channel\\)\\n +1: (29|30)\\.\\d+ ± "))))
        << text.out.toStdString();

    // A re-analysis of the stored session places its sites the same way
    // (fresh eyes: `analyze` said "not placed … as on a panel line").
    const CliResult analyze = runCli({"analyze", "--db", db, "--session", "last", "--json"});
    ASSERT_EQ(analyze.exitCode, 0) << analyze.err.toStdString();
    const QJsonObject analysed = QJsonDocument::fromJson(analyze.out.toUtf8()).object();
    EXPECT_EQ(analysed["sites_method"].toString(), QStringLiteral("from the position channel"))
        << analyze.out.toStdString();
    ASSERT_EQ(analysed["sites"].toArray().size(), 1) << analyze.out.toStdString();
    EXPECT_NEAR(analysed["sites"].toArray()[0].toObject()["position_mm"].toDouble(), 30.0, 1.0);
}

// A CSV of a panel line with its encoder's column: `detect --position x`
// places the dent (at +30 mm on the encoder's scale) within 1 mm and says
// so, in the JSON and in the summary; the phases alone cannot place it (the
// line rests between panels); a column that is not there is refused.
TEST(DetectSitesCli, APositionColumnPlacesTheDentOfACsvWithinAMillimetre)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("line.csv");
    ASSERT_EQ(
        runCli({"simulate", "--scenario", "panel-line", "--seconds", "20", "--seed", "3", "--output", csv}).exitCode,
        0);
    const CliResult placed = runCli({"detect", csv, "--json", "--spacing-mm", "15", "--position", "x"});
    ASSERT_EQ(placed.exitCode, 0) << placed.err.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(placed.out.toUtf8()).object();
    EXPECT_EQ(o["sites_method"].toString(), QStringLiteral("from the position channel")) << placed.out.toStdString();
    const QJsonArray sites = o["sites"].toArray();
    ASSERT_EQ(sites.size(), 1) << placed.out.toStdString();
    EXPECT_EQ(sites[0].toObject()["kind"].toString(), QStringLiteral("site"));
    EXPECT_NEAR(sites[0].toObject()["position_mm"].toDouble(), 30.0, 1.0) << placed.out.toStdString();
    EXPECT_EQ(sites[0].toObject()["crossings"].toInt(), o["events"].toArray().size());

    const CliResult summary = runCli({"detect", csv, "--spacing-mm", "15", "--position", "x"});
    ASSERT_EQ(summary.exitCode, 0) << summary.err.toStdString();
    EXPECT_TRUE(summary.out.contains(QStringLiteral("1 site (from the position channel):\n  1: 30.")))
        << summary.out.toStdString();

    const CliResult phases = runCli({"detect", csv, "--json", "--spacing-mm", "15"});
    ASSERT_EQ(phases.exitCode, 0) << phases.err.toStdString();
    EXPECT_TRUE(QJsonDocument::fromJson(phases.out.toUtf8())
                    .object()["sites_method"]
                    .toString()
                    .startsWith(QStringLiteral("not placed")))
        << phases.out.toStdString();

    const CliResult missing = runCli({"detect", csv, "--position", "encoder"});
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_TRUE(missing.err.contains(QStringLiteral("has no column 'encoder'"))) << missing.err.toStdString();

    // Fresh eyes: a column that holds no length, or a length not in m
    // (named with its unit too), is refused; one not used is named.
    const CliResult time = runCli({"detect", csv, "--position", "t"});
    EXPECT_EQ(time.exitCode, 2);
    EXPECT_TRUE(time.err.contains(QStringLiteral("the column 't [s]' holds no length"))) << time.err.toStdString();
    EXPECT_TRUE(phases.err.contains(QStringLiteral("--position x places each site"))) << phases.err.toStdString();
    const QString text = QString::fromUtf8(readBytes(csv));
    const QString inMillimetres = dir.filePath("mm.csv");
    writeText(inMillimetres, QString(text).replace(QStringLiteral("x [m]"), QStringLiteral("x [mm]")));
    const QString inMicrostrain = dir.filePath("ustrain.csv");
    writeText(inMicrostrain, QString(text).replace(QStringLiteral("a [strain]"), QStringLiteral("a [ustrain]")));
    for (const QString named : {"x", "x [mm]"}) {
        const CliResult mm = runCli({"detect", inMillimetres, "--position", named});
        EXPECT_EQ(mm.exitCode, 2) << named.toStdString();
        EXPECT_TRUE(mm.err.contains(QStringLiteral("is in 'mm'"))) << mm.err.toStdString();
    }
    const CliResult columnsWithUnit = runCli({"detect", inMicrostrain, "--columns", "t,a [ustrain],b"});
    EXPECT_EQ(columnsWithUnit.exitCode, 2);
    EXPECT_TRUE(columnsWithUnit.err.contains(QStringLiteral("is in 'ustrain'"))) << columnsWithUnit.err.toStdString();
}
