// The same inspection recorded from the workstation and from `tactiscope-cli
// record` gives the same record: one pipeline (devices/session/LivePipeline)
// for both, manual, triggered with limits, and of two devices. Two emulators with the same scenario and
// seed send the same stream; the main window records one, the CLI (a real
// process) the other, at the same time. The GUI's recording starts later in
// the stream (it connects first, then records), so the two sessions are
// aligned by their samples, and over the stretch both hold, the detector's
// events (panel scan) or the stiffness readings (palpation) must be the same,
// to the sample and to the digit: one controller, one analysis.
#include "core/storage/SessionStore.h"
#include "core/trigger/LimitWatch.h"
#include "devices/ReconnectingSource.h"
#include "devices/emulator/ProbeEmulator.h"
#include "devices/session/LiveSession.h"
#include "support/MainWindowHelpers.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/live/LiveStation.h"

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

// A probe emulating `scenario` at the shared rate and seed, streaming behind
// a pty linked at `name` in `dir`.
std::unique_ptr<ProbeEmulator> startedProbe(const QTemporaryDir& dir, const QString& name, const std::string& scenario)
{
    devices::emulator::EmulatorOptions options;
    options.scenario = scenario;
    options.rate_hz = kRate_hz;
    options.seed = kSeed;
    options.linkPath = dir.filePath(name).toStdString();
    auto probe = std::make_unique<ProbeEmulator>(options);
    probe->start();
    return probe;
}

// Records `scenario` from both paths for about `seconds` and aligns them.
TwoRecordings recordBoth(const QTemporaryDir& dir, const std::string& scenario, double seconds)
{
    const auto guiProbe = startedProbe(dir, QStringLiteral("gui-probe"), scenario);
    const auto cliProbe = startedProbe(dir, QStringLiteral("cli-probe"), scenario);
    const QString guiDb = dir.filePath("gui.tactiscope"), cliDb = dir.filePath("cli.tactiscope");

    QProcess cli;
    cli.start(QStringLiteral(TACTISCOPE_CLI), {"record", "--port", dir.filePath("cli-probe"), "--seconds",
                                               QString::number(seconds + 2.0), "--db", cliDb});
    EXPECT_TRUE(cli.waitForStarted());
    {
        ui::MainWindow window;
        window.setStorePath(guiDb);
        window.station().connectDevice(QStringLiteral("probe"), serialOpener(dir.filePath("gui-probe").toStdString()));
        EXPECT_TRUE(waitFor([&] { return window.station().isConnected(); }, 6000));
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

namespace {

// Issue 52: the stroke of a panel line, cut by one trigger with limits,
// from both paths: the GUI's one session must be one of the CLI's, to the
// sample, with the same alarms (the pre-trigger stroke's critical one
// too), defects and verdict.
struct TriggeredPair {
    std::unique_ptr<SessionStore> gui, cli;
};

TriggeredPair recordTriggered(const QTemporaryDir& dir)
{
    const auto guiProbe = startedProbe(dir, QStringLiteral("gui-line"), "panel-line");
    const auto cliProbe = startedProbe(dir, QStringLiteral("cli-line"), "panel-line");
    const QString guiDb = dir.filePath("gui-line.tactiscope"), cliDb = dir.filePath("cli-line.tactiscope");
    const QStringList trigger{"--trigger", "a>20e-6", "--pre",   "0.5",
                              "--post",    "1",       "--limit", "a>warning:20e-6,critical:28e-6"};
    QProcess cli;
    cli.start(QStringLiteral(TACTISCOPE_CLI), QStringList{"record", "--port", dir.filePath("cli-line"), "--seconds",
                                                          "30", "--db", cliDb, "--sessions", "3"} +
                                                  trigger);
    EXPECT_TRUE(cli.waitForStarted());
    {
        ui::MainWindow window;
        window.setStorePath(guiDb);
        window.station().connectDevice(QStringLiteral("line"), serialOpener(dir.filePath("gui-line").toStdString()));
        EXPECT_TRUE(waitFor([&] { return window.station().isConnected(); }, 6000));
        auto& live = *window.station().device();
        EXPECT_FALSE(live.setLimits({*core::trigger::parseLimit("a>warning:20e-6,critical:28e-6").limit}));
        core::trigger::TriggerSettings settings;
        settings.condition = *core::trigger::parseTrigger("a>20e-6").condition;
        settings.pre_s = 0.5;
        settings.post_s = 1.0;
        settings.sessions = 1u;
        EXPECT_FALSE(window.station().armTrigger(settings, {}));
        EXPECT_TRUE(waitFor([&] { return !window.station().armed() || live.triggerStatus().sessionsCut >= 1; }, 25000));
        EXPECT_TRUE(waitFor([&] { return !window.station().isRecording(); }, 10000));
    }
    EXPECT_TRUE(cli.waitForFinished(40000));
    EXPECT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();
    return {std::make_unique<SessionStore>(guiDb.toStdString(), core::storage::Database::Access::ReadOnly),
            std::make_unique<SessionStore>(cliDb.toStdString(), core::storage::Database::Access::ReadOnly)};
}

std::vector<core::storage::SessionEvent> eventsOf(SessionStore& store, std::int64_t session, core::EventKind kind)
{
    auto events = store.events(session);
    std::erase_if(events, [kind](const auto& e) { return e.kind != kind; });
    return events;
}

}  // namespace

TEST(GuiCliEquivalence, ATriggeredSessionWithLimitsIsTheSameFromBothPaths)
{
    QTemporaryDir dir;
    const TriggeredPair r = recordTriggered(dir);
    const auto guiSessions = r.gui->sessions();
    ASSERT_EQ(guiSessions.size(), 1u);
    const auto& gui = guiSessions.front();
    const auto guiSamples = r.gui->readChannel(gui.id, 0, 0, r.gui->sampleCount(gui.id));
    // The CLI's session of the same panel: the same samples from its first to its last.
    std::optional<core::storage::SessionSummary> same;
    for (const auto& cli : r.cli->sessions())
        if (r.cli->readChannel(cli.id, 0, 0, r.cli->sampleCount(cli.id)) == guiSamples) same = cli;
    ASSERT_TRUE(same) << "no CLI session holds the GUI's " << guiSamples.size() << " samples";
    EXPECT_EQ(gui.verdict, same->verdict);
    EXPECT_EQ(gui.metadata.trigger, same->metadata.trigger);
    for (const auto kind : {core::EventKind::Alarm, core::EventKind::Defect, core::EventKind::Trigger}) {
        SCOPED_TRACE(std::string(core::toString(kind)));
        const auto fromGui = eventsOf(*r.gui, gui.id, kind);
        const auto fromCli = eventsOf(*r.cli, same->id, kind);
        ASSERT_EQ(fromGui.size(), fromCli.size());
        for (std::size_t i = 0; i < fromGui.size(); ++i) {
            EXPECT_NEAR(fromGui[i].start_s, fromCli[i].start_s, 1e-9) << i;
            EXPECT_NEAR(fromGui[i].end_s, fromCli[i].end_s, 1e-9) << i;
            EXPECT_EQ(fromGui[i].note, fromCli[i].note) << i;
        }
    }
    EXPECT_FALSE(eventsOf(*r.gui, gui.id, core::EventKind::Alarm).empty());
}

// Issue 52: two devices, a panel probe and a load cell, from both paths:
// one session of two parts named by the same rule, each part in its own
// mode, the session taking its parts' verdict; over the stretch both hold,
// the panel part's defects are the same to the sample.
TEST(GuiCliEquivalence, ASessionOfTwoDevicesIsTheSameFromBothPaths)
{
    QTemporaryDir dir;
    std::vector<std::unique_ptr<ProbeEmulator>> probes;
    for (const char* side : {"gui", "cli"})
        for (const char* scenario : {"panel-scan", "load-cell"})
            probes.push_back(startedProbe(dir, QStringLiteral("%1-%2").arg(side, scenario), scenario));
    const QString guiDb = dir.filePath("gui2.tactiscope"), cliDb = dir.filePath("cli2.tactiscope");
    QProcess cli;
    cli.start(QStringLiteral(TACTISCOPE_CLI), {"record", "--port", dir.filePath("cli-panel-scan"), "--port",
                                               dir.filePath("cli-load-cell"), "--seconds", "9", "--db", cliDb});
    ASSERT_TRUE(cli.waitForStarted());
    {
        ui::MainWindow window;
        window.setStorePath(guiDb);
        window.station().connectDevice(QStringLiteral("probe"),
                                       serialOpener(dir.filePath("gui-panel-scan").toStdString()));
        ASSERT_TRUE(waitFor([&] { return window.station().isConnected(); }, 6000));
        window.station().addSource(
            std::make_unique<devices::ReconnectingSource>(serialOpener(dir.filePath("gui-load-cell").toStdString())));
        ASSERT_EQ(window.station().pipeline().size(), 2u);
        runEventLoopFor(500);
        ASSERT_TRUE(window.startRecording());
        runEventLoopFor(6000);
        window.stopRecording();
    }
    ASSERT_TRUE(cli.waitForFinished(30000));
    ASSERT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();
    SessionStore gui(guiDb.toStdString(), core::storage::Database::Access::ReadOnly);
    SessionStore cliStore(cliDb.toStdString(), core::storage::Database::Access::ReadOnly);
    ASSERT_EQ(gui.sessions().size(), 1u);
    ASSERT_EQ(cliStore.sessions().size(), 1u);
    const auto guiSession = gui.sessions().front(), cliSession = cliStore.sessions().front();
    const auto guiParts = gui.parts(guiSession.id), cliParts = cliStore.parts(cliSession.id);
    ASSERT_EQ(guiParts.size(), 2u);
    ASSERT_EQ(cliParts.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(guiParts[i].deviceName, cliParts[i].deviceName) << i;
        EXPECT_EQ(gui.session(guiParts[i].id)->metadata.mode, cliStore.session(cliParts[i].id)->metadata.mode) << i;
    }
    EXPECT_EQ(guiSession.metadata.mode, core::Mode::PanelScan);
    EXPECT_EQ(guiSession.metadata.mode, cliSession.metadata.mode);
    EXPECT_EQ(guiSession.verdict, cliSession.verdict);
    EXPECT_EQ(guiSession.verdict, gui.session(guiParts[0].id)->verdict);  // the load cell judges nothing
    // The panel part: the GUI's first samples in the CLI's, and the defects between.
    const auto head = gui.readChannel(guiParts[0].id, 0, 0, 100);
    const auto all = cliStore.readChannel(cliParts[0].id, 0, 0, cliStore.sampleCount(cliParts[0].id));
    const auto found = std::ranges::search(all, head);
    ASSERT_FALSE(found.empty());
    const double shift_s = static_cast<double>(found.begin() - all.begin()) / kRate_hz;
    const double end_s = std::min(shift_s + static_cast<double>(gui.sampleCount(guiParts[0].id)) / kRate_hz,
                                  static_cast<double>(all.size()) / kRate_hz);
    const auto inside = [&](std::vector<core::storage::SessionEvent> events, double by_s) {
        std::vector<core::storage::SessionEvent> kept;
        for (auto& e : events)
            if (e.kind == core::EventKind::Defect && e.start_s + by_s > shift_s + 0.2 && e.end_s + by_s < end_s - 0.2)
                kept.push_back(e);
        for (auto& e : kept) e.start_s += by_s;
        return kept;
    };
    const auto fromGui = inside(gui.events(guiParts[0].id), shift_s);
    const auto fromCli = inside(cliStore.events(cliParts[0].id), 0.0);
    ASSERT_GE(fromCli.size(), 3u);
    ASSERT_EQ(fromGui.size(), fromCli.size());
    for (std::size_t i = 0; i < fromGui.size(); ++i) {
        EXPECT_NEAR(fromGui[i].start_s, fromCli[i].start_s, 1e-9) << i;
        EXPECT_EQ(fromGui[i].direction, fromCli[i].direction) << i;
        EXPECT_EQ(fromGui[i].peakR, fromCli[i].peakR) << i;
    }
}
