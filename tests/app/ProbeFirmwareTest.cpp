// The probe's detector on three emulated Cortex-M cores (issue 38): the
// kernel built with arm-none-eabi-gcc for the M4F, M7 and M33, run in QEMU
// on generated scans (firmware/probe-detector/qemu-detect.sh), writes the
// same bytes as the workstation's build of the same file (`detect --engine
// probe`), and decides as the workstation's double-precision detector
// (`detect`) on every sample. Needs the ARM toolchain and QEMU, which the
// install script installs; missing, the test fails with the script's reason.
#include "support/CliRunner.h"
#include "support/GeneratedScans.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using tactiscope::testing::runCli;

namespace {

QStringList linesOf(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
}

QByteArray bytesOf(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// The decision column of `detect --output` rows.
QStringList decisionsOf(const QString& path)
{
    QStringList decisions;
    for (const QString& line : linesOf(path).mid(1)) decisions << line.section(QLatin1Char(','), 1, 1);
    return decisions;
}

// The environment the script finds this build's CLI in.
QProcessEnvironment withTheCli()
{
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("TACTISCOPE_CLI"), QStringLiteral(TACTISCOPE_CLI));
    return environment;
}

class ProbeFirmware : public ::testing::TestWithParam<const char*> {};

}  // namespace

TEST_P(ProbeFirmware, DecidesAsTheWorkstationAndWritesTheHostBuildsBytes)
{
    const QString core = QString::fromLatin1(GetParam());
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    for (const auto& scan : tactiscope::testing::generatedScans(138)) {
        SCOPED_TRACE(scan.name);
        const QString csv = dir.filePath(QString::fromStdString(scan.name) + ".csv");
        tactiscope::testing::writeScanCsv(csv.toStdString(), scan);
        const QString onProbe = dir.filePath(QStringLiteral("%1-%2.csv").arg(core, scan.name.c_str()));
        const QString onHost = dir.filePath(QStringLiteral("host-%1.csv").arg(scan.name.c_str()));
        const QString workstation = dir.filePath(QStringLiteral("ws-%1.csv").arg(scan.name.c_str()));
        QProcess qemu;
        qemu.setProcessEnvironment(withTheCli());
        qemu.start(QStringLiteral(TACTISCOPE_SOURCE_DIR "/firmware/probe-detector/qemu-detect.sh"),
                   {csv, onProbe, core});
        ASSERT_TRUE(qemu.waitForFinished(600000));
        ASSERT_EQ(qemu.exitCode(), 0) << qemu.readAllStandardError().toStdString();
        const auto host = runCli({"detect", csv, "--engine", "probe", "--output", onHost});
        ASSERT_EQ(host.exitCode, 0) << host.err.toStdString();
        const auto reference = runCli({"detect", csv, "--output", workstation});
        ASSERT_EQ(reference.exitCode, 0) << reference.err.toStdString();

        // Bit for bit: every R and lag of every sample as the host build wrote it.
        const QByteArray probeBytes = bytesOf(onProbe);
        ASSERT_EQ(linesOf(onProbe).size(), static_cast<qsizetype>(scan.t.size()) + 1);
        EXPECT_TRUE(probeBytes == bytesOf(onHost))
            << "the emulated " << core.toStdString() << " and the host build differ";
        // The face-to-face scan goes in as it is (the script takes the paper's settings):
        // its decisions are compared all the same.
        const QStringList probe = decisionsOf(onProbe), ws = decisionsOf(workstation);
        ASSERT_EQ(probe.size(), ws.size());
        qsizetype differing = 0, decided = 0;
        for (qsizetype i = 0; i < probe.size(); ++i) {
            differing += probe[i] != ws[i];
            decided += ws[i] != QStringLiteral("0");
        }
        EXPECT_EQ(differing, 0) << decided << " decisions by the workstation";
        if (scan.direction != 0 && !scan.faceToFace) {
            EXPECT_GT(decided, 5);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Cores, ProbeFirmware, ::testing::Values("m4", "m7", "m33"));

// What the script says instead of a result: for a scan `detect` refuses,
// exactly what detect says, with its exit code 2 (before, the script read
// scans with a host tool of its own and exited 0 on a 1e300 sample, empty
// cells read as 0, time going back, "0.002s" and "1e-6abc"); and, on a
// machine without the ARM toolchain or QEMU, what to install (exit 3).
TEST(ProbeFirmwareScript, RefusesWhatDetectRefusesWithItsWords)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString script = QStringLiteral(TACTISCOPE_SOURCE_DIR "/firmware/probe-detector/qemu-detect.sh");
    const std::vector<std::pair<const char*, const char*>> scans{
        {"no-columns", "time,x,y\n0,1,2\n0.002,1,2\n"},
        {"huge", "t,a,b\n0,0,0\n0.002,1e300,0\n0.004,0,0\n"},
        {"empty-cell", "t,a,b\n0,0,0\n0.002,,0\n0.004,0,0\n"},
        {"time-back", "t,a,b\n0,0,0\n0.004,0,0\n0.002,0,0\n"},
        {"unit-in-cell", "t,a,b\n0,0,0\n0.002s,0,0\n0.004,0,0\n"},
        {"trailing-text", "t,a,b\n0,0,0\n0.002,1e-6abc,0\n0.004,0,0\n"},
    };
    for (const auto& [name, text] : scans) {
        SCOPED_TRACE(name);
        const QString bad = dir.filePath(QString::fromLatin1(name) + ".csv");
        QFile file(bad);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(text);
        file.close();
        const auto detect = runCli({"detect", bad});
        EXPECT_EQ(detect.exitCode, 2);
        QProcess run;
        run.setProcessEnvironment(withTheCli());
        run.start(script, {bad, dir.filePath("out.csv")});
        ASSERT_TRUE(run.waitForFinished(120000));
        EXPECT_EQ(run.exitCode(), 2);
        const QString said = QString::fromUtf8(run.readAllStandardError());
        EXPECT_FALSE(detect.err.isEmpty());
        EXPECT_EQ(said, detect.err);
        EXPECT_FALSE(QFile::exists(dir.filePath("out.csv")));
    }

    // Without OUT.csv: its usage, exit 2 like any command's.
    QProcess usage;
    usage.setProcessEnvironment(withTheCli());
    usage.start(script, {dir.filePath("huge.csv")});
    ASSERT_TRUE(usage.waitForFinished(60000));
    EXPECT_EQ(usage.exitCode(), 2);
    EXPECT_EQ(usage.readAllStandardError(), "usage: qemu-detect.sh SCAN.csv OUT.csv [m4|m7|m33]\n");

    // A PATH with only what the script needs before it looks for its tools.
    const QString bin = dir.filePath("bin");
    ASSERT_TRUE(QDir().mkpath(bin));
    ASSERT_TRUE(QFile::link(QStringLiteral("/usr/bin/dirname"), bin + QStringLiteral("/dirname")));
    QProcess bare;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("PATH"), bin);
    environment.insert(QStringLiteral("TACTISCOPE_CLI"), dir.filePath("no-such-cli"));
    bare.setProcessEnvironment(environment);
    bare.start(QStringLiteral("/bin/bash"), {script, dir.filePath("huge.csv"), dir.filePath("out.csv")});
    ASSERT_TRUE(bare.waitForFinished(60000));
    EXPECT_EQ(bare.exitCode(), 3);
    const QByteArray said = bare.readAllStandardError();
    EXPECT_TRUE(said.contains("gcc-arm-none-eabi") && said.contains("qemu-system-arm") &&
                said.contains("tactiscope-cli"))
        << said.toStdString();
}
