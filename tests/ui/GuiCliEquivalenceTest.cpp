// The same inspection recorded from the workstation and from `tactiscope-cli
// record` gives the same record. Two emulators with the same scenario and
// seed send the same stream; the main window records one, the CLI (a real
// process) the other, at the same time. The GUI's recording starts later in
// the stream (it connects first, then records), so the two sessions are
// aligned by their samples, and over the stretch both hold, the detector's
// events (panel scan) or the stiffness readings (palpation) must be the same,
// to the sample and to the digit: one controller, one analysis.
#include "core/storage/SessionStore.h"
#include "devices/emulator/ProbeEmulator.h"
#include "support/MainWindowHelpers.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"

#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <algorithm>

using namespace tactiscope;
using core::storage::SessionStore;
using devices::emulator::ProbeEmulator;
using tactiscope::testing::runEventLoopFor;
using tactiscope::testing::serialOpener;
using tactiscope::testing::waitFor;

namespace {

constexpr double kRate_hz = 500.0;
constexpr std::uint64_t kSeed = 5;

struct TwoRecordings {
    std::unique_ptr<SessionStore> gui, cli;
    core::storage::SessionSummary guiSession, cliSession;
    double guiStart_s = 0.0;    // where the GUI's session starts in the CLI's
    double overlapEnd_s = 0.0;  // in the CLI's session time
};

// Records `scenario` from both paths for about `seconds` and aligns them.
TwoRecordings recordBoth(const QTemporaryDir& dir, const std::string& scenario, double seconds)
{
    devices::emulator::EmulatorOptions options;
    options.scenario = scenario;
    options.rate_hz = kRate_hz;
    options.seed = kSeed;
    options.linkPath = dir.filePath("gui-probe").toStdString();
    ProbeEmulator guiProbe(options);
    options.linkPath = dir.filePath("cli-probe").toStdString();
    ProbeEmulator cliProbe(options);
    guiProbe.start();
    cliProbe.start();
    const QString guiDb = dir.filePath("gui.tactiscope"), cliDb = dir.filePath("cli.tactiscope");

    QProcess cli;
    cli.start(QStringLiteral(TACTISCOPE_CLI), {"record", "--port", QString::fromStdString(options.linkPath),
                                               "--seconds", QString::number(seconds + 2.0), "--db", cliDb});
    EXPECT_TRUE(cli.waitForStarted());
    {
        ui::MainWindow window;
        window.setStorePath(guiDb);
        window.connectDevice(QStringLiteral("probe"), serialOpener(dir.filePath("gui-probe").toStdString()));
        EXPECT_TRUE(waitFor([&] { return window.isConnected(); }, 6000));
        runEventLoopFor(500);  // the GUI records a stretch that starts later in the stream
        EXPECT_TRUE(window.startRecording());
        runEventLoopFor(static_cast<int>(seconds * 1000.0));
        window.stopRecording();
    }
    EXPECT_TRUE(cli.waitForFinished(30000));
    EXPECT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();

    TwoRecordings r;
    r.gui = std::make_unique<SessionStore>(guiDb.toStdString(), core::storage::Database::Access::ReadOnly);
    r.cli = std::make_unique<SessionStore>(cliDb.toStdString(), core::storage::Database::Access::ReadOnly);
    EXPECT_EQ(r.gui->sessions().size(), 1u);
    EXPECT_EQ(r.cli->sessions().size(), 1u);
    if (r.gui->sessions().empty() || r.cli->sessions().empty()) return r;
    r.guiSession = r.gui->sessions().front();
    r.cliSession = r.cli->sessions().front();
    // The GUI's first 100 samples, found in the CLI's (the same stream).
    const auto head = r.gui->readChannel(r.guiSession.id, 0, 0, 100);
    const auto all = r.cli->readChannel(r.cliSession.id, 0, 0, r.cli->sampleCount(r.cliSession.id));
    const auto found = std::ranges::search(all, head);
    EXPECT_FALSE(found.empty()) << "the GUI's samples are not in the CLI's recording";
    const auto offset = static_cast<double>(found.begin() - all.begin());
    r.guiStart_s = offset / kRate_hz;
    r.overlapEnd_s = std::min(r.guiStart_s + static_cast<double>(r.guiSession.sampleCount) / kRate_hz,
                              static_cast<double>(all.size()) / kRate_hz);
    return r;
}

// The records (events or readings) that `wanted` keeps, moved by `shift_s`
// onto the CLI's clock, and lying wholly inside the stretch both sessions hold.
template <typename Record, typename Wanted>
std::vector<Record> inShared(const TwoRecordings& r, std::vector<Record> records, double shift_s, Wanted wanted)
{
    std::vector<Record> kept;
    for (auto& record : records) {
        record.start_s += shift_s;
        record.end_s += shift_s;
        if (wanted(record) && record.start_s > r.guiStart_s + 0.2 && record.end_s < r.overlapEnd_s - 0.2)
            kept.push_back(std::move(record));
    }
    return kept;
}

}  // namespace

TEST(GuiCliEquivalence, APanelScanGivesTheSameDefectsAndVerdictFromBothPaths)
{
    QTemporaryDir dir;
    const TwoRecordings r = recordBoth(dir, "panel-scan", 7.0);
    ASSERT_TRUE(r.gui && r.cli);
    ASSERT_GT(r.guiStart_s, 0.0);  // the GUI did start later: the alignment was needed
    EXPECT_EQ(r.guiSession.metadata.mode, core::Mode::PanelScan);
    EXPECT_EQ(r.guiSession.verdict, r.cliSession.verdict);
    EXPECT_EQ(r.guiSession.metadata.deviceModel, r.cliSession.metadata.deviceModel);
    EXPECT_EQ(r.guiSession.metadata.deviceSerial, r.cliSession.metadata.deviceSerial);
    EXPECT_EQ(r.guiSession.metadata.deviceFirmware, r.cliSession.metadata.deviceFirmware);
    const auto defects = [](const auto& e) { return e.kind == core::EventKind::Defect; };
    const auto gui = inShared(r, r.gui->events(r.guiSession.id), r.guiStart_s, defects);
    const auto cli = inShared(r, r.cli->events(r.cliSession.id), 0.0, defects);
    ASSERT_GE(cli.size(), 4u);  // one crossing a second
    ASSERT_EQ(gui.size(), cli.size());
    for (std::size_t i = 0; i < gui.size(); ++i) {
        EXPECT_NEAR(gui[i].start_s, cli[i].start_s, 1e-9) << i;
        EXPECT_NEAR(gui[i].end_s, cli[i].end_s, 1e-9) << i;
        EXPECT_EQ(gui[i].direction, cli[i].direction) << i;
        EXPECT_EQ(gui[i].peakR, cli[i].peakR) << i;
        EXPECT_EQ(gui[i].lag_s, cli[i].lag_s) << i;
    }
}

TEST(GuiCliEquivalence, APalpationGivesTheSameStiffnessReadingsFromBothPaths)
{
    QTemporaryDir dir;
    const TwoRecordings r = recordBoth(dir, "palpation", 10.0);
    ASSERT_TRUE(r.gui && r.cli);
    EXPECT_EQ(r.guiSession.metadata.mode, core::Mode::Palpation);
    const auto any = [](const auto&) { return true; };
    const auto gui = inShared(r, r.gui->readings(r.guiSession.id), r.guiStart_s, any);
    const auto cli = inShared(r, r.cli->readings(r.cliSession.id), 0.0, any);
    ASSERT_GE(cli.size(), 2u);
    ASSERT_EQ(gui.size(), cli.size());
    for (std::size_t i = 0; i < gui.size(); ++i) {
        EXPECT_NEAR(gui[i].start_s, cli[i].start_s, 1e-9) << i;
        EXPECT_NEAR(gui[i].end_s, cli[i].end_s, 1e-9) << i;
        EXPECT_EQ(gui[i].quantity, cli[i].quantity) << i;
        EXPECT_EQ(gui[i].value, cli[i].value) << i;
        EXPECT_EQ(gui[i].unit, cli[i].unit) << i;
        EXPECT_EQ(gui[i].detailsJson, cli[i].detailsJson) << i;
    }
}
