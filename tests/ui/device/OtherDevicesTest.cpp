// Several devices recorded from the main window (issue 40), as a user
// would: the panel-scan simulator connected, then the simulator's reference
// load cell added from the Device panel as another device of the session.
// It streams into its own live plot under its name (View ▸ Other devices);
// Record records both into one session of several devices, each its part
// at its own rate and on its own clock; the simulators time their samples
// by the host's clock, so each part's stored mapping is exact and both
// parts begin within a block of the session's start; live, the load cell's
// plot reads the probe's time axis. Devices cannot be
// added or removed while recording, nor a trigger armed with them; Remove
// takes one away afterwards, and the next recording is of one device.
#include "ui/device/OtherDevices.h"
#include "core/storage/SessionStore.h"
#include "core/timing/ClockMappingJson.h"
#include "support/MainWindowHelpers.h"
#include "support/Screenshot.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/device/DevicePanel.h"
#include "ui/live/LiveStation.h"
#include "ui/plot/LivePlotWidget.h"
#include "ui/signal/SignalDialog.h"

#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::testing::child;
using tactiscope::testing::liveSimulator;
using tactiscope::testing::runEventLoopFor;
using tactiscope::testing::waitFor;

TEST(OtherDevices, ALoadCellAddedBesideTheProbeIsRecordedWithItIntoOneSessionOnOneClock)
{
    QTemporaryDir dir;
    const QString store = dir.filePath("lab.tactiscope");
    ui::MainWindow window;
    window.setStorePath(store);
    window.resize(1600, 900);
    window.show();
    auto* add = child<QPushButton>(window, "addDeviceButton");
    window.devicePanel()->selectSimulator(QStringLiteral("load-cell"));
    EXPECT_FALSE(add->isEnabled());  // nothing to add it to yet
    window.station().connectSource(liveSimulator());
    runEventLoopFor(700);  // the load cell comes later: its own time runs 0.7 s behind
    window.devicePanel()->selectSimulator(QStringLiteral("load-cell"));
    ASSERT_TRUE(add->isEnabled());
    QTest::mouseClick(add, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return window.otherDevices()->names().size() == 1; }, 5000));
    EXPECT_EQ(window.otherDevices()->names().front(), "tactiscope-simulator-reference-load-cell");
    EXPECT_TRUE(child<QDockWidget>(window, "otherDevicesDock")->isVisible());
    runEventLoopFor(1500);  // its trace fills
    // Both plots on the window's device's clock: the newest samples of two
    // devices streaming in real time show at one time (within a block and
    // a status tick), though the load cell connected later.
    const auto newest = [](const devices::session::LiveSession& live, const ui::LivePlotWidget& plot) {
        return static_cast<double>(live.buffer()->samplesWritten()) / live.source().nominalSampleRate_hz() -
               plot.timeOrigin_s();
    };
    EXPECT_NEAR(newest(*window.station().device(), *window.livePlot()),
                newest(window.otherDevices()->session(0), window.otherDevices()->plot(0)), 0.08);
    EXPECT_NEAR(window.otherDevices()->plot(0).timeOrigin_s(), -0.7, 0.15);  // it connected 0.7 s after the probe
    EXPECT_EQ(window.otherDevices()->plot(0).timeAxisLabel(), window.livePlot()->timeAxisLabel());
    tactiscope::testing::saveScreenshot(window, QStringLiteral("other-devices"));

    QTest::keyClicks(child<QLineEdit>(window, "subjectEdit"), QStringLiteral("beam-3"));
    ASSERT_TRUE(window.startRecording());
    QTest::mouseClick(add, Qt::LeftButton);  // refused while recording
    QTest::mouseClick(child<QPushButton>(window, "removeDeviceButton"), Qt::LeftButton);
    runEventLoopFor(3000);
    EXPECT_EQ(window.otherDevices()->names().size(), 1u);
    window.stopRecording();
    ASSERT_FALSE(window.isRecording());

    {
        core::storage::SessionStore sessions(store.toStdString(), core::storage::Database::Access::ReadOnly);
        const auto list = sessions.sessions();
        ASSERT_EQ(list.size(), 1u);  // the parts are not listed of their own
        const auto& session = list.front();
        EXPECT_EQ(session.metadata.subject, "beam-3");
        EXPECT_EQ(session.status, core::SessionStatus::Complete);
        const auto parts = sessions.parts(session.id);
        ASSERT_EQ(parts.size(), 2u);
        EXPECT_EQ(parts[0].deviceName, "tactiscope-simulator");
        EXPECT_EQ(parts[1].deviceName, "tactiscope-simulator-reference-load-cell");
        std::vector<double> durations;
        std::vector<core::ChannelKind> kinds;
        for (const auto& part : parts) {
            EXPECT_EQ(part.status, core::SessionStatus::Complete) << part.deviceName;
            const auto clock = core::timing::clockMappingFromJson(part.clockJson);
            ASSERT_TRUE(clock) << part.deviceName << ": " << part.clockJson;
            EXPECT_EQ(clock->basis, core::timing::ClockUncertaintyBasis::Exact);
            EXPECT_EQ(clock->uncertainty_s(0.0).value_or(-1.0), 0.0);
            // Both begin with the session: within a block (10 samples) of
            // its t = 0, plus the time the record press took to reach both.
            EXPECT_GE(clock->host_s(0.0), -0.05) << part.deviceName;
            EXPECT_LT(clock->host_s(0.0), 0.25) << part.deviceName;
            const auto channels = sessions.channels(part.id);
            ASSERT_FALSE(channels.empty());
            durations.push_back(static_cast<double>(sessions.sampleCount(part.id)) / channels.front().sampleRate_hz);
            kinds.push_back(channels.front().descriptor.kind);
        }
        ASSERT_EQ(durations.size(), 2u);
        EXPECT_GT(durations.front(), 2.5);
        EXPECT_NEAR(durations.front(), durations.back(), 0.3);
        EXPECT_EQ(kinds.back(), core::ChannelKind::Force);
    }

    // Removed, the next recording is the probe's alone.
    QTest::mouseClick(child<QPushButton>(window, "removeDeviceButton"), Qt::LeftButton);
    EXPECT_TRUE(window.otherDevices()->empty());
    ASSERT_TRUE(window.startRecording());
    runEventLoopFor(500);
    window.stopRecording();
    core::storage::SessionStore sessions(store.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto list = sessions.sessions();
    ASSERT_EQ(list.size(), 2u);
    EXPECT_TRUE(sessions.parts(list.front().id).empty());
}

// Each device its own filters and math channels (issue 57): the signal
// dialog opens on the window's device and, with another added, chooses
// between them; what is applied to one is that device's alone, and each
// part of the recording keeps its own.
TEST(OtherDevices, EachDeviceSetsItsOwnFiltersAndMathChannelsInTheSignalDialog)
{
    QTemporaryDir dir;
    const QString store = dir.filePath("lab.tactiscope");
    ui::MainWindow window;
    window.setStorePath(store);
    window.resize(1366, 768);
    window.show();
    window.station().connectSource(liveSimulator());
    ASSERT_TRUE(waitFor([&] { return window.station().device() != nullptr; }, 5000));
    window.devicePanel()->selectSimulator(QStringLiteral("load-cell"));
    QTest::mouseClick(child<QPushButton>(window, "addDeviceButton"), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return window.otherDevices()->names().size() == 1; }, 5000));

    window.findChild<QAction*>(QStringLiteral("signalAction"))->trigger();
    auto* dialog = window.findChild<ui::SignalDialog*>(QStringLiteral("signalDialog"));
    ASSERT_NE(dialog, nullptr);
    auto* chooser = child<QComboBox>(*dialog, "signalDevice");
    ASSERT_EQ(chooser->count(), 2);
    EXPECT_EQ(chooser->currentText(), QStringLiteral("tactiscope-simulator"));
    // The load cell's own: its channel in the rows, a math channel over it.
    chooser->setCurrentIndex(1);
    emit chooser->activated(1);
    ASSERT_TRUE(waitFor(
        [&] {
            auto* now = window.findChild<ui::SignalDialog*>(QStringLiteral("signalDialog"));
            return now && now != dialog && now->isVisible();
        },
        3000));
    QTest::qWait(50);  // the first dialog deleted
    dialog = window.findChild<ui::SignalDialog*>(QStringLiteral("signalDialog"));
    ASSERT_NE(dialog, nullptr);
    EXPECT_EQ(child<QComboBox>(*dialog, "signalDevice")->currentIndex(), 1);
    auto* filters = child<QTableWidget>(*dialog, "signalFilters");
    const auto& cell = window.station().pipeline().device(1);
    ASSERT_EQ(filters->rowCount(), static_cast<int>(cell.channels().size()));
    const QString force = QString::fromStdString(cell.channels().front().name);
    EXPECT_EQ(filters->item(0, 0)->text(), force);
    child<QPlainTextEdit>(*dialog, "signalMath")->setPlainText(QStringLiteral("twice[mN]=2 * ") + force);
    tactiscope::testing::saveScreenshot(*dialog, QStringLiteral("signal-dialog-devices"));
    QTest::mouseClick(child<QPushButton>(*dialog, "signalApply"), Qt::LeftButton);
    EXPECT_TRUE(child<QLabel>(*dialog, "signalProblem")->text().isEmpty())
        << child<QLabel>(*dialog, "signalProblem")->text().toStdString();
    dialog->close();
    EXPECT_EQ(window.station().pipeline().device(1).signalSetup().math.size(), 1u);
    EXPECT_TRUE(window.station().device()->signalSetup().empty());  // the probe's untouched

    ASSERT_TRUE(window.startRecording());
    runEventLoopFor(1000);
    window.stopRecording();
    core::storage::SessionStore sessions(store.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto parts = sessions.parts(sessions.sessions().front().id);
    ASSERT_EQ(parts.size(), 2u);
    EXPECT_TRUE(sessions.session(parts[0].id)->metadata.signalSetup.empty());
    EXPECT_NE(sessions.session(parts[1].id)->metadata.signalSetup.find("twice[mN]=2 * " + force.toStdString()),
              std::string::npos)
        << sessions.session(parts[1].id)->metadata.signalSetup;
}

// Issue 52: two devices made the window 1716 px wide at least, four more;
// the gauge-factor rig 1392 px. The other devices scroll in their dock, so
// on a 1366×768 laptop the window keeps to 1280 px whatever is connected.
TEST(OtherDevices, TheWindowFitsALaptopWithTwoAndFourDevicesAndEveryBuiltInSimulator)
{
    QTemporaryDir dir;
    ui::MainWindow window;
    window.setStorePath(dir.filePath("s.tactiscope"));
    window.resize(1366, 768);
    window.show();
    constexpr int kLaptopWidth = 1280;
    for (const std::string& scenario : devices::simulator::scenarioIds()) {
        window.station().connectSource(liveSimulator(scenario));
        runEventLoopFor(300);
        EXPECT_LE(window.minimumSizeHint().width(), kLaptopWidth) << scenario;
        EXPECT_LE(window.minimumSize().width(), kLaptopWidth) << scenario;
    }
    window.station().connectSource(liveSimulator());
    for (int added = 1; added <= 3; ++added) {
        window.station().addSource(liveSimulator(added % 2 ? "load-cell" : "capacitive-weights"));
        runEventLoopFor(300);
        if (added == 1 || added == 3) {
            SCOPED_TRACE(added + 1);
            ASSERT_EQ(window.otherDevices()->size(), static_cast<std::size_t>(added));
            EXPECT_TRUE(child<QDockWidget>(window, "otherDevicesDock")->isVisible());
            EXPECT_LE(window.minimumSizeHint().width(), kLaptopWidth);
            EXPECT_LE(window.width(), 1366);
        }
    }
    tactiscope::testing::saveScreenshot(window, QStringLiteral("other-devices-laptop"));
}
