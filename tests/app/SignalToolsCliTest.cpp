// `tactiscope-cli spectrum`, `filter` and `health` on files and stored
// sessions, through their contracts' keys, with values checked against
// what was put into the files (a capacitive beam's creep against the
// simulator's parameters).
#include "core/SampleBlock.h"
#include "devices/simulator/CapacitiveWeightsScenario.h"
#include "support/CliRunner.h"
#include "support/PdfText.h"
#include "support/TextFiles.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTextStream>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace tactiscope;
using tactiscope::testing::CliResult;
using tactiscope::testing::jsonOf;
using tactiscope::testing::runCli;
using tactiscope::testing::writeText;

namespace {

// t [s], a [µε] (a 2 Hz signal of 100 µε, 1,000 µε of 50 Hz hum, 300 µε at
// 150 Hz and a little noise), f [mN] (a 37 Hz line of 4 mN), at 1 kHz.
// Rows [gapFrom, gapTo) are left out: the recording's gap.
QString hummedRecording(std::size_t rows, std::size_t gapFrom = 0, std::size_t gapTo = 0)
{
    std::mt19937 random(12);
    std::normal_distribution<double> noise(0.0, 0.5);
    QString text = "t [s],a [µε],f [mN]\n";
    QTextStream out(&text);
    for (std::size_t i = 0; i < rows; ++i) {
        if (i >= gapFrom && i < gapTo) continue;
        const double t = static_cast<double>(i) / 1000.0;
        const double w = 2.0 * std::numbers::pi * t;
        out << QString::number(t, 'f', 3) << ','
            << QString::number(100.0 * std::sin(2.0 * w) + 1000.0 * std::sin(50.0 * w) + 300.0 * std::sin(150.0 * w) +
                                   noise(random),
                               'g', 10)
            << ',' << QString::number(4.0 * std::sin(37.0 * w + 0.2) + 0.01 * noise(random), 'g', 10) << '\n';
    }
    return text;
}

QStringList csvLines(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
}

// The amplitude of a sine of `f` Hz in `values` sampled at 1 kHz.
double amplitudeAt(const std::vector<double>& values, double f, std::size_t first)
{
    double s = 0.0, c = 0.0;
    const std::size_t n = (values.size() - first) / 1000 * 1000;  // whole seconds: whole cycles
    for (std::size_t i = first; i < first + n; ++i) {
        const double phase = 2.0 * std::numbers::pi * f * static_cast<double>(i) / 1000.0;
        s += values[i] * std::sin(phase);
        c += values[i] * std::cos(phase);
    }
    return 2.0 * std::hypot(s, c) / static_cast<double>(n);
}

}  // namespace

TEST(SignalToolsCli, SpectrumPrintsItsContractsKeysAndTheLine)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("hum.csv");
    writeText(csv, hummedRecording(20000));
    const CliResult run = runCli({"spectrum", csv, "--channel", "f", "--window", "hann", "--averages", "16", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonObject o = jsonOf(run);
    EXPECT_EQ(o["unit"].toString(), "mN");
    const QJsonArray f = o["frequency_hz"].toArray();
    const QJsonArray psd = o["psd_per_sqrt_hz"].toArray();
    ASSERT_GT(f.size(), 100);
    EXPECT_EQ(f.size(), psd.size());
    EXPECT_EQ(f.last().toDouble(), 500.0);
    const QJsonArray peaks = o["peaks"].toArray();
    ASSERT_FALSE(peaks.isEmpty());
    EXPECT_NEAR(peaks[0].toObject()["frequency_hz"].toDouble(), 37.0, 0.5);
    EXPECT_NEAR(peaks[0].toObject()["amplitude"].toDouble(), 4.0, 0.04);
    EXPECT_GE(o["averages"].toInt(), 16);
    EXPECT_FALSE(o.contains("note"));
}

TEST(SignalToolsCli, ASpectrumOfARecordingWithAGapSaysItWasCut)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("gap.csv");
    writeText(csv, hummedRecording(20000, 9000, 9500));
    const CliResult json = runCli({"spectrum", csv, "--channel", "a", "--json"});
    ASSERT_EQ(json.exitCode, 0) << json.err.toStdString();
    EXPECT_EQ(jsonOf(json)["stretches"].toInt(), 2);
    EXPECT_NE(jsonOf(json)["note"].toString().indexOf("never across a gap"), -1);
    const CliResult text = runCli({"spectrum", csv, "--channel", "a"});
    ASSERT_EQ(text.exitCode, 0);
    EXPECT_NE(text.out.indexOf("2 gap-free stretches"), -1) << text.out.toStdString();
    EXPECT_NE(text.out.indexOf("50.0"), -1) << text.out.toStdString();
}

TEST(SignalToolsCli, SpectrumReadsAStoredSessionAsItReadsItsFile)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("hum.csv");
    const QString db = dir.filePath("s.tactiscope");
    writeText(csv, hummedRecording(8000));
    ASSERT_EQ(runCli({"import", csv, "--db", db}).exitCode, 0);
    const CliResult file = runCli({"spectrum", csv, "--channel", "a", "--json"});
    const CliResult stored = runCli({"spectrum", "--db", db, "--session", "last", "--channel", "a", "--json"});
    ASSERT_EQ(stored.exitCode, 0) << stored.err.toStdString();
    EXPECT_EQ(file.out, stored.out);
}

TEST(SignalToolsCli, SpectrumRefusesWhatItCannotRead)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("hum.csv");
    writeText(csv, hummedRecording(3000));
    const CliResult noChannel = runCli({"spectrum", csv, "--channel", "b"});
    EXPECT_EQ(noChannel.exitCode, 2);
    EXPECT_NE(noChannel.err.indexOf("it has a, f"), -1) << noChannel.err.toStdString();
    EXPECT_EQ(runCli({"spectrum", csv, "--channel", "a", "--window", "kaiser"}).exitCode, 2);
    EXPECT_EQ(runCli({"spectrum", csv, "--channel", "a", "--averages", "0"}).exitCode, 2);
    EXPECT_EQ(runCli({"spectrum", csv, "--channel", "a", "--db", csv}).exitCode, 2);
    EXPECT_EQ(runCli({"spectrum", dir.filePath("none.csv"), "--channel", "a"}).exitCode, 2);
}

TEST(SignalToolsCli, FilterNotchesOneChannelAndKeepsTheOthersAsWritten)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("hum.csv");
    const QString out = dir.filePath("notched.csv");
    writeText(csv, hummedRecording(20000));
    const CliResult run = runCli({"filter", csv, "--channel", "a", "--notch", "50", "--output", out});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    EXPECT_NE(run.out.indexOf("mains notch 50 Hz"), -1) << run.out.toStdString();
    const QStringList before = csvLines(csv);
    const QStringList after = csvLines(out);
    ASSERT_EQ(after.size(), before.size());
    EXPECT_EQ(after.front(), before.front());  // the header
    std::vector<double> raw, filtered;
    for (int i = 1; i < before.size(); ++i) {
        const QStringList b = before[i].split(',');
        const QStringList a = after[i].split(',');
        ASSERT_EQ(a.size(), 3);
        ASSERT_EQ(a[0], b[0]);  // time and the other channel, to the character
        ASSERT_EQ(a[2], b[2]);
        raw.push_back(b[1].toDouble());
        filtered.push_back(a[1].toDouble());
    }
    EXPECT_LT(amplitudeAt(filtered, 50.0, 5000), 1000.0 * 0.01);  // ≥ 40 dB
    EXPECT_LT(amplitudeAt(filtered, 150.0, 5000), 300.0 * 0.01);
    EXPECT_NEAR(amplitudeAt(filtered, 2.0, 5000), 100.0, 0.5);
    EXPECT_NEAR(amplitudeAt(raw, 50.0, 5000), 1000.0, 1.0);
}

TEST(SignalToolsCli, FilterZeroPhaseAndBandsAndRefusals)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("hum.csv");
    writeText(csv, hummedRecording(6000, 3000, 3010));
    const QString out = dir.filePath("f.csv");
    const CliResult run = runCli({"filter", csv, "--channel", "f", "--lowpass", "20", "--highpass", "0.5", "--order",
                                  "6", "--zero-phase", "--output", out});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    EXPECT_NE(run.out.indexOf("band-pass 0.5–20 Hz (Butterworth, order 6), zero-phase"), -1) << run.out.toStdString();
    EXPECT_EQ(csvLines(out).size(), csvLines(csv).size());
    for (const QStringList& bad :
         {QStringList{"--notch", "55"}, QStringList{"--lowpass", "600"}, QStringList{"--order", "9", "--lowpass", "10"},
          QStringList{"--order", "4"}, QStringList{"--lowpass", "5", "--highpass", "10"}, QStringList{}}) {
        const CliResult refused =
            runCli(QStringList{"filter", csv, "--channel", "f", "--output", dir.filePath("x.csv")} + bad);
        EXPECT_EQ(refused.exitCode, 2) << bad.join(' ').toStdString();
        EXPECT_FALSE(QFile::exists(dir.filePath("x.csv")));
    }
    EXPECT_EQ(runCli({"filter", csv, "--channel", "f", "--notch", "50", "--output", csv}).exitCode, 2);
    const CliResult time = runCli({"filter", csv, "--channel", "t", "--lowpass", "10", "--output", out});
    EXPECT_EQ(time.exitCode, 2);
    EXPECT_NE(time.err.indexOf("is the time column"), -1) << time.err.toStdString();
    // Each refusal says what was wrong with what was given.
    for (const auto& [bad, said] :
         {std::pair{QStringList{"--order", "3.5", "--lowpass", "10"},
                    QStringLiteral("a whole number, 2 to 8, not 3.5")},
          std::pair{QStringList{"--moving-average", "0"}, QStringLiteral("a moving average of 0 s is none")},
          std::pair{QStringList{"--moving-average", "0.001"}, QStringLiteral("shorter than two samples at 1000 Hz")}}) {
        const CliResult refused =
            runCli(QStringList{"filter", csv, "--channel", "f", "--output", dir.filePath("x.csv")} + bad);
        EXPECT_EQ(refused.exitCode, 2) << bad.join(' ').toStdString();
        EXPECT_NE(refused.err.indexOf(said), -1) << refused.err.toStdString();
    }
}

TEST(SignalToolsCli, RatesAStoreCannotHoldAndAveragesThatDoNotFitAreSaid)
{
    QTemporaryDir dir;
    const QString fast = dir.filePath("fast.csv");
    writeText(fast, "t,a\n0,1\n1e-12,2\n2e-12,1\n3e-12,3\n");
    const CliResult refused = runCli({"spectrum", fast, "--channel", "a"});
    EXPECT_EQ(refused.exitCode, 2);
    EXPECT_NE(refused.err.indexOf("sample rate"), -1) << refused.err.toStdString();
    const QString csv = dir.filePath("hum.csv");
    writeText(csv, hummedRecording(3000));
    const CliResult many = runCli({"spectrum", csv, "--channel", "a", "--averages", "5000", "--json"});
    ASSERT_EQ(many.exitCode, 0) << many.err.toStdString();
    EXPECT_NE(jsonOf(many)["note"].toString().indexOf("5000 averages asked"), -1) << many.out.toStdString();
    const CliResult shortHealth = runCli({"health", fast});
    EXPECT_EQ(shortHealth.exitCode, 2);
    // Without a time column, the rate given as import takes it.
    const QString untimed = dir.filePath("untimed.csv");
    QString rows = "a [mN]\n";
    for (int i = 0; i < 4000; ++i) rows += QString::number(std::sin(i * 2.0 * std::numbers::pi * 37.0 / 1000.0)) + "\n";
    writeText(untimed, rows);
    EXPECT_EQ(runCli({"spectrum", untimed, "--channel", "a"}).exitCode, 2);
    const CliResult rated = runCli({"spectrum", untimed, "--channel", "a", "--rate", "1000", "--json"});
    ASSERT_EQ(rated.exitCode, 0) << rated.err.toStdString();
    EXPECT_NEAR(jsonOf(rated)["peaks"].toArray()[0].toObject()["frequency_hz"].toDouble(), 37.0, 0.5);
}

TEST(SignalToolsCli, HealthNamesEachChannelsHumNoiseDriftAndClipping)
{
    QTemporaryDir dir;
    const QString csv = dir.filePath("hum.csv");
    writeText(csv, hummedRecording(30000));
    const CliResult run = runCli({"health", csv, "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonArray channels = QJsonDocument::fromJson(run.out.toUtf8()).array();
    ASSERT_EQ(channels.size(), 2);
    const QJsonObject a = channels[0].toObject();
    for (const char* key :
         {"channel", "unit", "hum_hz", "hum_amplitude", "noise_floor", "drift_per_hour", "drift_per_hour_u", "clipped"})
        EXPECT_TRUE(a.contains(key)) << key;
    EXPECT_EQ(a["channel"].toString(), "a");
    EXPECT_EQ(a["unit"].toString(), "µε");
    EXPECT_EQ(a["hum_hz"].toDouble(), 50.0);
    EXPECT_NEAR(a["hum_amplitude"].toDouble(), 1000.0, 20.0);
    EXPECT_EQ(a["clipped"].toInt(), 0);
    const QJsonObject f = channels[1].toObject();
    EXPECT_EQ(f["unit"].toString(), "mN");
    EXPECT_TRUE(f["hum_hz"].isNull());
    const CliResult text = runCli({"health", csv});
    ASSERT_EQ(text.exitCode, 0);
    EXPECT_NE(text.out.indexOf("hum 50 Hz, "), -1) << text.out.toStdString();
}

TEST(SignalToolsCli, HealthReadsACapacitiveBeamsCreepAfterItsLoadSteps)
{
    // The simulator's weights, placed and taken off one by one, on a beam
    // that creeps 5 % further with a 4 s time constant: the creep's share
    // of a step and its time constant, each with its ±; the time constant
    // is the simulator's parameter, not the fit's.
    devices::simulator::CapacitiveWeightsParameters p;
    p.protocol = devices::simulator::WeightProtocol::Individual;
    p.weights_mgf = {50, 100, 150, 100, 50, 150};
    p.dwell_s = 20.0;
    p.creepFraction = 0.05;
    p.seed = 3;
    devices::simulator::CapacitiveWeightsScenario beam(p);
    core::SampleBlock block(1, static_cast<std::size_t>(beam.duration_s() * p.sampleRate_hz), 0.0,
                            1.0 / p.sampleRate_hz);
    beam.generate(block);
    QString text = "t [s],capacitance [pF]\n";
    for (std::size_t i = 0; i < block.sampleCount(); ++i)
        text += QString::number(static_cast<double>(i) / p.sampleRate_hz, 'f', 1) + ',' +
                QString::number(block.channel(0)[i] * 1e12, 'f', 6) + '\n';
    QTemporaryDir dir;
    const QString csv = dir.filePath("beam.csv");
    writeText(csv, text);
    const CliResult run = runCli({"health", csv, "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QJsonObject c = QJsonDocument::fromJson(run.out.toUtf8()).array()[0].toObject();
    ASSERT_TRUE(c["creep"].isObject()) << run.out.toStdString();
    const QJsonObject creep = c["creep"].toObject();
    EXPECT_EQ(creep["steps"].toInt(), 12);  // each weight on, and off
    EXPECT_NEAR(creep["time_constant_s"].toDouble(), p.creepTime_s, 3.0 * creep["time_constant_s_u"].toDouble());
    EXPECT_LT(creep["time_constant_s_u"].toDouble(), 1.0);
    EXPECT_NEAR(creep["settle_time_s"].toDouble(), p.settleTime_s, 0.05);
    // Of a step: 5 % of the settled load, its slow part referred to the
    // onset (τ_c/(τ_c − τ_s) of it, sampled), over the step's 1.05.
    const double share = 0.05 * p.creepTime_s / (p.creepTime_s - p.settleTime_s) / 1.05;
    EXPECT_NEAR(creep["fraction"].toDouble(), share, 3.0 * creep["fraction_u"].toDouble() + 0.002);
    const CliResult words = runCli({"health", csv});
    ASSERT_EQ(words.exitCode, 0);
    EXPECT_NE(words.out.indexOf("% of a step, τ "), -1) << words.out.toStdString();
    // Imported, its report's signal quality says the same.
    const QString db = dir.filePath("beam.tactiscope");
    ASSERT_EQ(runCli({"import", csv, "--db", db}).exitCode, 0);
    const QString pdf = dir.filePath("beam.pdf");
    const CliResult report = runCli({"report", "--db", db, "--session", "last", "--output", pdf});
    ASSERT_EQ(report.exitCode, 0) << report.err.toStdString();
    const QString said = tactiscope::testing::pdfText(pdf).replace(QLatin1Char('\n'), QLatin1Char(' '));
    EXPECT_TRUE(said.contains("Creep after a load step (capacitance)")) << said.toStdString();
    EXPECT_TRUE(said.contains("% of the step, time constant")) << said.toStdString();
}
