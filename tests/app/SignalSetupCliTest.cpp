// `record` with filters and math channels (issue 57), against `emulate`
// over a real pseudo-terminal into a real store: the session keeps its
// setup (show, export's side file, an import of the export), its samples
// stay as they came, the export's math column is the arithmetic of its
// filtered columns in the declared unit, a limit on a math channel is
// stored as an alarm, and what cannot be is refused in words.
#include "core/storage/SessionStore.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/PdfText.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace tactiscope;
using tactiscope::testing::CliResult;
using tactiscope::testing::runCli;
using tactiscope::testing::sessionIdIn;
using tactiscope::testing::startEmulator;
using tactiscope::testing::stopEmulator;

namespace {

// A panel-scan probe with 20 µε of common and 5 µε of differential 50 Hz
// hum, recorded for three seconds through a notch, with a math channel and a
// limit on it every difference passes.
CliResult recordHummed(const QTemporaryDir& dir, const QString& db)
{
    const QString link = dir.filePath("probe");
    QProcess emulator;
    EXPECT_TRUE(startEmulator(emulator, link,
                              {"--scenario", "panel-scan", "--rate", "1000", "--seed", "3", "--hum", "20e-6,5e-6"}));
    const CliResult result = runCli({"record", "--port", link, "--seconds", "3", "--db", db, "--notch", "50",
                                     "--lowpass", "200", "--math", "diff[µε]=a - b", "--limit", "diff>warning:-1000"});
    stopEmulator(emulator);
    return result;
}

QStringList csvLines(const QString& path)
{
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << path.toStdString();
    return QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
}

}  // namespace

TEST(SignalSetupCli, ARecordingKeepsItsFiltersAndMathAndTheExportComputesThemAsLive)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("hum.tactiscope");
    const CliResult recorded = recordHummed(dir, db);
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();
    const std::int64_t id = sessionIdIn(recorded.out);
    ASSERT_GT(id, 0);

    const CliResult shown = runCli({"sessions", "--db", db, "show", QString::number(id)});
    EXPECT_TRUE(shown.out.contains(
        "\nsignal            a: mains notch 50 Hz and harmonics, low-pass 200 Hz (Butterworth, order 4); b: mains "
        "notch 50 Hz and harmonics, low-pass 200 Hz (Butterworth, order 4); diff[µε]=a - b\n"))
        << shown.out.toStdString();
    // The limit on the math channel raised at once and held: its alarm is stored.
    EXPECT_TRUE(shown.out.contains("alarm    diff above its warning limit -1000 µε")) << shown.out.toStdString();

    const QString csv = dir.filePath("out.csv");
    // The export's own math channel reads the filtered channels, as the
    // recorded one did live: the same values.
    const CliResult exported = runCli({"sessions", "--db", db, "export", QString::number(id), "--format", "csv",
                                       "--output", csv, "--math", "again[µε]=a - b"});
    ASSERT_EQ(exported.exitCode, 0) << exported.err.toStdString();
    const QStringList lines = csvLines(csv);
    ASSERT_EQ(lines.front(),
              "t [s],a [strain],b [strain],a.filtered [strain],b.filtered [strain],diff [µε],again [µε]");
    ASSERT_EQ(lines.size(), 3001);
    // The 50 Hz amplitude of the raw and of the filtered difference over
    // the last 2 s (100 whole cycles), by projection on its sine and cosine:
    // the notch, 2 Hz wide, has settled on the hum by then.
    double rawSin = 0.0, rawCos = 0.0, filteredSin = 0.0, filteredCos = 0.0;
    for (int i = 1; i < lines.size(); ++i) {
        const QStringList v = lines[i].split(',');
        ASSERT_EQ(v.size(), 7);
        const double difference = (v[3].toDouble() - v[4].toDouble()) * 1e6;
        EXPECT_NEAR(v[5].toDouble(), difference, 1e-12 * std::abs(difference) + 1e-15) << i;
        EXPECT_EQ(v[6], v[5]) << i;
        if (i > 1000) {
            const double phase = 2.0 * M_PI * 50.0 * v[0].toDouble();
            const double raw = (v[1].toDouble() - v[2].toDouble()) * 1e6;
            rawSin += raw * std::sin(phase);
            rawCos += raw * std::cos(phase);
            filteredSin += v[5].toDouble() * std::sin(phase);
            filteredCos += v[5].toDouble() * std::cos(phase);
        }
    }
    const double rawHum = 2.0 / 2000.0 * std::hypot(rawSin, rawCos);
    const double filteredHum = 2.0 / 2000.0 * std::hypot(filteredSin, filteredCos);
    // 5 µε of opposite sign on a and b: 10 µε in their difference, kept in
    // the stored samples and 40 dB down through the notch.
    EXPECT_NEAR(rawHum, 10.0, 0.5);
    EXPECT_LT(filteredHum, 0.1);

    // health and spectrum read the filtered and math channels too, computed
    // again as the report computes them (fresh eyes: "has no channel").
    const CliResult health = runCli({"health", "--db", db, "--session", QString::number(id), "--json"});
    ASSERT_EQ(health.exitCode, 0) << health.err.toStdString();
    std::map<QString, double> humOf;
    for (const auto& row : QJsonDocument::fromJson(health.out.toUtf8()).array())
        humOf[row.toObject()["channel"].toString()] = row.toObject()["hum_amplitude"].toDouble();
    ASSERT_EQ(humOf.size(), 5u) << health.out.toStdString();
    EXPECT_LT(humOf["a.filtered"], 0.1 * humOf["a"]);
    const CliResult spectrum =
        runCli({"spectrum", "--db", db, "--session", QString::number(id), "--channel", "diff", "--json"});
    ASSERT_EQ(spectrum.exitCode, 0) << spectrum.err.toStdString();
    EXPECT_EQ(QJsonDocument::fromJson(spectrum.out.toUtf8()).object()["unit"].toString(), QStringLiteral("µε"));

    // The export's side file keeps the setup, and an import of it brings it back.
    QFile meta(dir.filePath("out.meta.json"));
    ASSERT_TRUE(meta.open(QIODevice::ReadOnly));
    const auto session = QJsonDocument::fromJson(meta.readAll()).object()["session"].toObject();
    EXPECT_TRUE(session["signal_setup"].toString().contains("\"notch_hz\":50.0"));
    const QString other = dir.filePath("other.tactiscope");
    const CliResult imported = runCli({"import", csv, "--db", other});
    ASSERT_EQ(imported.exitCode, 0) << imported.err.toStdString();
    core::storage::SessionStore store(other.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto back = store.session(store.lastSession().value_or(0));
    ASSERT_TRUE(back);
    EXPECT_EQ(back->metadata.signalSetup, session["signal_setup"].toString().toStdString());
    EXPECT_EQ(store.channels(back->id).size(), 2u) << "the computed columns are not imported as channels";

    // The report's signal quality: the hum each gauge carries (20 µε common
    // and ±5 µε differential: 25 on a, 15 on b), and the filters used.
    if (*tactiscope::testing::pdfTextMissing()) return;
    const QString pdf = dir.filePath("report.pdf");
    const CliResult report = runCli({"report", "--db", db, "--session", QString::number(id), "--output", pdf});
    ASSERT_EQ(report.exitCode, 0) << report.err.toStdString();
    const QString text = tactiscope::testing::pdfText(pdf).simplified();
    EXPECT_TRUE(text.contains("Signal quality")) << text.toStdString();
    EXPECT_TRUE(text.contains("a: mains notch 50 Hz and harmonics, low-pass 200 Hz (Butterworth, order 4)"))
        << text.toStdString();
    // Recorded through the notch, the detector read the gauges as stored: the verdict says so.
    EXPECT_TRUE(text.contains("The mode's analysis read the channels as stored, not through the"))
        << text.toStdString();
    const QRegularExpression hum(QStringLiteral("\\b([ab]) ([0-9.]+) µε at 50 Hz"));
    std::map<QString, double> found;
    for (auto it = hum.globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        found[m.captured(1)] = m.captured(2).toDouble();
    }
    ASSERT_EQ(found.size(), 2u) << text.toStdString();
    EXPECT_NEAR(found["a"], 25.0, 0.5);  // within 2 %
    EXPECT_NEAR(found["b"], 15.0, 0.3);
    // The filtered channels beside them, as they were live: the notch took
    // most of the hum (the recording begins as the notch settles, so less
    // than its 40 dB of steady state), and the math channel is judged too.
    // (pdftotext writes "fi" as its ligature.)
    const QRegularExpression filteredHumText(QString::fromUtf8("\\b([ab])\\.(?:fi|ﬁ)ltered ([0-9.]+) µε at 50 Hz"));
    for (auto it = filteredHumText.globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        EXPECT_LT(m.captured(2).toDouble(), 0.1 * found[m.captured(1)]) << m.captured(0).toStdString();
        found[m.captured(1) + ".filtered"] = m.captured(2).toDouble();
    }
    EXPECT_EQ(found.size(), 4u) << text.toStdString();
    EXPECT_TRUE(QRegularExpression(QString::fromUtf8("\\b(?:diff|diﬀ) [0-9.]+ µε at 50 Hz")).match(text).hasMatch())
        << text.toStdString();
    tactiscope::testing::savePdfPage(pdf, QStringLiteral("report-signal-quality"), 0);
}

TEST(SignalSetupCli, WhatCannotBeFilteredOrComputedIsRefusedBeforeAnythingIsRecorded)
{
    QTemporaryDir dir;
    const QString link = dir.filePath("probe");
    const QString db = dir.filePath("refused.tactiscope");
    QProcess emulator;
    ASSERT_TRUE(startEmulator(emulator, link, {"--scenario", "panel-scan", "--rate", "1000"}));
    const auto refusal = [&](const QStringList& more) {
        const CliResult r = runCli(QStringList{"record", "--port", link, "--seconds", "0.2", "--db", db} + more);
        EXPECT_EQ(r.exitCode, 2) << r.out.toStdString();
        return r.err;
    };
    EXPECT_TRUE(refusal({"--notch", "50", "--filter-channel", "c"}).contains("the device has no channel 'c'"));
    EXPECT_TRUE(refusal({"--filter-channel", "a"}).contains("give --notch, --lowpass"));
    EXPECT_TRUE(refusal({"--math", "x[mN]=a + 1"}).contains("x"));
    EXPECT_TRUE(refusal({"--lowpass", "600"}).contains("Hz"));
    EXPECT_TRUE(refusal({"--math", "d[µε]=a - b", "--limit", "e>warning:1"}).contains("nothing called 'e'"));
    stopEmulator(emulator);
    EXPECT_FALSE(QFile::exists(db)) << "nothing recorded, no store left behind";
}

// The modes beside the panel scan: a palpation probe recorded through a
// low-pass with its analysis on the filtered channels still reads its
// presses' stiffness, and keeps the setup; a capacitive beam at 10 Hz
// gets a math channel over a constant ((C − C0)/C0, C0 defined before it),
// and its export's column is that arithmetic of the filtered capacitance.
// A notch the beam's rate cannot carry is refused in words.
TEST(SignalSetupCli, PalpationAndTheCapacitiveBeamRecordThroughTheirFiltersAndMath)
{
    QTemporaryDir dir;
    {
        const QString link = dir.filePath("palpation");
        const QString db = dir.filePath("palpation.tactiscope");
        QProcess emulator;
        ASSERT_TRUE(startEmulator(emulator, link, {"--scenario", "palpation"}));
        const auto r = runCli({"record", "--port", link, "--seconds", "6", "--db", db, "--mode", "palpation",
                               "--lowpass", "20", "--analyze-filtered", "--math", "ratio[]=high / low"});
        stopEmulator(emulator);
        ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
        const auto readings = QRegularExpression(QStringLiteral("palpation: ([0-9]+) stiffness reading")).match(r.out);
        ASSERT_TRUE(readings.hasMatch()) << r.out.toStdString();
        EXPECT_GE(readings.captured(1).toInt(), 1);
        core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
        const auto setup =
            QJsonDocument::fromJson(QByteArray::fromStdString(store.sessions().front().metadata.signalSetup)).object();
        EXPECT_TRUE(setup.value("analysis_filtered").toBool());
        EXPECT_EQ(setup.value("filters").toArray().size(), 3);  // high, low and the displacement
        if (!*tactiscope::testing::pdfTextMissing()) {
            const QString pdf = dir.filePath("palpation.pdf");
            ASSERT_EQ(runCli({"report", "--db", db, "--session", "last", "--output", pdf}).exitCode, 0);
            const QString text = tactiscope::testing::pdfText(pdf).simplified();
            EXPECT_TRUE(text.contains("the mode analyses the")) << text.toStdString();
            EXPECT_FALSE(text.contains("The mode's analysis read the channels as stored")) << text.toStdString();
        }
    }
    {
        const QString link = dir.filePath("beam");
        const QString db = dir.filePath("beam.tactiscope");
        QProcess emulator;
        ASSERT_TRUE(startEmulator(emulator, link, {"--scenario", "capacitive-weights"}));
        const QStringList record{"record", "--port", link, "--seconds", "4", "--db", db, "--mode", "capacitive"};
        const auto notched = runCli(record + QStringList{"--notch", "50"});
        EXPECT_EQ(notched.exitCode, 2);
        EXPECT_TRUE(notched.err.contains(QStringLiteral("a 50 Hz notch needs a sample rate above")))
            << notched.err.toStdString();
        const auto r = runCli(record + QStringList{"--lowpass", "1", "--math", "c0[pF]=51.44", "--math",
                                                   "rel[]=(capacitance - c0) / c0"});
        stopEmulator(emulator);
        ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
        const QString csv = dir.filePath("beam.csv");
        ASSERT_EQ(runCli({"sessions", "--db", db, "export", "last", "--format", "csv", "--output", csv}).exitCode, 0);
        QFile file(csv);
        ASSERT_TRUE(file.open(QIODevice::ReadOnly));
        EXPECT_EQ(QString::fromUtf8(file.readLine()).trimmed(),
                  QStringLiteral("t [s],capacitance [F],capacitance.filtered [F],c0 [pF],rel"));
        int rows = 0;
        while (!file.atEnd()) {
            const QStringList cells = QString::fromUtf8(file.readLine()).trimmed().split(QLatin1Char(','));
            ASSERT_EQ(cells.size(), 5);
            const double filtered_F = cells[2].toDouble(), c0_F = 51.44e-12;
            EXPECT_NEAR(cells[4].toDouble(), (filtered_F - c0_F) / c0_F, 1e-12) << rows;
            ++rows;
        }
        EXPECT_GE(rows, 35);  // 4 s at 10 Hz
    }
}
