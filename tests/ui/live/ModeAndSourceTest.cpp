// The session's mode and the connected source agree: a simulator that
// declares its mode switches the window to it, a mode the device cannot feed
// is refused before anything is recorded (with the channels it needs), and
// what is recorded is the mode the device feeds.
#include "core/storage/SessionStore.h"
#include "support/MainWindowHelpers.h"
#include "support/Screenshot.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/live/LiveStation.h"
#include "ui/live/ModeViews.h"
#include "ui/modes/palpation/PalpationView.h"
#include "ui/plot/LivePlotWidget.h"

#include <QComboBox>
#include <QMenuBar>
#include <QMessageBox>
#include <QSplitter>
#include <QStackedWidget>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::testing::child;
using tactiscope::testing::liveSimulator;
using tactiscope::testing::runEventLoopFor;

namespace {

// The Device ▸ Simulator menu's entry for `scenario`, as a user picks it.
void chooseSimulator(ui::MainWindow& window, const QString& scenario)
{
    for (QAction* menu : window.menuBar()->actions()) {
        if (!menu->menu()) continue;
        for (QAction* entry : menu->menu()->actions()) {
            if (!entry->menu()) continue;
            for (QAction* item : entry->menu()->actions())
                if (item->text() == scenario) {
                    item->trigger();
                    return;
                }
        }
    }
    ADD_FAILURE() << "no simulator entry " << scenario.toStdString();
}

}  // namespace

TEST(ModeAndSource, ChoosingTheSimulatorOfAnotherModeSwitchesToIt)
{
    ui::MainWindow window;
    window.show();
    window.setMode(core::Mode::PanelScan);
    chooseSimulator(window, QStringLiteral("palpation"));
    ASSERT_TRUE(window.station().isConnected());
    EXPECT_EQ(window.mode(), core::Mode::Palpation);
    EXPECT_EQ(child<QComboBox>(window, "modeBox")->currentText(), QStringLiteral("Palpation"));
    const auto* views = window.findChild<ui::ModeViews*>();
    ASSERT_NE(views, nullptr);
    EXPECT_TRUE(views->isVisible());
    EXPECT_EQ(views->shown(), window.findChild<ui::PalpationView*>());
}

// `tactiscope --scenario panel-scan --mode general` asks the mode of the
// connected simulator (issue 52, fresh eyes: asked before the connect, the
// device's own mode won and --mode general never showed).
TEST(ModeAndSource, TheGeneralModeAskedAfterConnectingTakesAnySimulator)
{
    ui::MainWindow window;
    window.show();
    window.station().connectSource(liveSimulator("panel-scan"));
    ASSERT_EQ(window.mode(), core::Mode::PanelScan);
    // The detector's marks on the traces go with its mode (they stayed, and
    // new ones came, on a general recording of the panel probe).
    auto* traces = qobject_cast<ui::LivePlotWidget*>(child<QSplitter>(window, "centreSplitter")->widget(0));
    ASSERT_NE(traces, nullptr);
    ASSERT_TRUE(tactiscope::testing::waitFor([&] { return traces->eventCount() > 0; }, 4000));
    EXPECT_TRUE(window.setMode(core::Mode::General));
    EXPECT_EQ(window.mode(), core::Mode::General);
    EXPECT_EQ(window.station().device()->mode(), core::Mode::General);
    runEventLoopFor(1500);  // a defect crossing every 0.7 s or so
    EXPECT_EQ(traces->eventCount(), 0u);
}

TEST(ModeAndSource, AModeTheDeviceCannotFeedIsRefusedAndNothingIsRecordedInIt)
{
    QTemporaryDir dir;
    const QString store = dir.filePath(QStringLiteral("s.tactiscope"));
    ui::MainWindow window;
    window.setStorePath(store);
    window.resize(1200, 720);
    window.show();
    window.station().connectSource(liveSimulator("palpation"));
    ASSERT_EQ(window.mode(), core::Mode::Palpation);

    EXPECT_FALSE(window.setMode(core::Mode::PanelScan));
    EXPECT_EQ(window.mode(), core::Mode::Palpation);  // the bar went back
    EXPECT_EQ(child<QComboBox>(window, "modeBox")->currentText(), QStringLiteral("Palpation"));
    auto* box = child<QMessageBox>(window, "modeRefusedBox");
    ASSERT_NE(box, nullptr);
    EXPECT_TRUE(box->isVisible());
    EXPECT_FALSE(box->isModal());  // the live view goes on behind it
    EXPECT_TRUE(box->informativeText().contains(QStringLiteral("no channel plays cantilever-a, cantilever-b")))
        << box->informativeText().toStdString();
    EXPECT_TRUE(box->informativeText().contains(QStringLiteral("Channel roles")))
        << box->informativeText().toStdString();
    tactiscope::testing::saveScreenshot(*box, QStringLiteral("mode-refused"));

    ASSERT_TRUE(window.startRecording());
    runEventLoopFor(600);
    window.stopRecording();
    core::storage::SessionStore sessions(store.toStdString(), core::storage::Database::Access::ReadOnly);
    ASSERT_EQ(sessions.sessions().size(), 1u);
    EXPECT_EQ(sessions.sessions().front().metadata.mode, core::Mode::Palpation);
}
