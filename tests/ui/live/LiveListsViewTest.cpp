// The main window's live views show the live session's lists, on one clock,
// and agree with the record (the simulator sped up tenfold): the defect
// table after *Stop* is the stored defects, then a new list since connect;
// the press table while recording has the stored times, the grid map the
// site selected before *Record*; and a device that declares nothing records
// in general mode until its channels get roles in the device panel, which
// are remembered for the device.
#include "core/storage/SessionStore.h"
#include "support/MainWindowHelpers.h"
#include "support/RelabelledSource.h"
#include "support/Screenshot.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/device/ChannelRolesBox.h"
#include "ui/device/DevicePanel.h"
#include "ui/live/LiveStation.h"
#include "ui/live/ModeViews.h"
#include "ui/modes/palpation/PalpationView.h"
#include "ui/modes/palpation/SiteGridMap.h"
#include "ui/modes/panelscan/PanelScanView.h"

#include <QAction>
#include <QComboBox>
#include <QDialog>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::testing::child;
using tactiscope::testing::waitFor;

namespace {

std::unique_ptr<devices::BlockSource> spedUp(const char* scenario)
{
    devices::simulator::SimulatorOptions options;
    options.speed = 10.0;
    return std::make_unique<devices::simulator::SimulatorSource>(devices::simulator::makeScenario(scenario), options);
}

// A maker's board streaming the panel probe's signals as "a" and "b",
// plain numbers or labelled as strains, without a mode, identified by its
// serial number.
std::unique_ptr<devices::BlockSource> makerBoard(bool labelsStrains = false)
{
    return std::make_unique<tactiscope::testing::RelabelledSource>(
        "panel-scan",
        labelsStrains ? std::vector<std::string>{"a[strain]", "b[strain]"} : std::vector<std::string>{"a", "b"}, 10.0,
        devices::DeviceIdentity{"Nano 33", "MK-0042", "1.0"});
}

QString headerOf(const QTableWidget& table)
{
    return table.horizontalHeaderItem(0)->text();
}

}  // namespace

TEST(LiveListsView, AfterStopTheDefectTableIsWhatWasStoredThenANewListStartsSinceConnect)
{
    QTemporaryDir dir;
    const QString store = dir.filePath("s.tactiscope");
    ui::MainWindow window;
    window.setStorePath(store);
    window.resize(1366, 768);
    window.station().connectSource(spedUp("panel-scan"));
    window.show();
    auto* table = child<QTableWidget>(*window.findChild<ui::PanelScanView*>(), "defectTable");
    auto* count = child<QLabel>(*window.findChild<ui::PanelScanView*>(), "defectCountLabel");
    ASSERT_TRUE(waitFor([&] { return table->rowCount() >= 2; }, 20000));
    EXPECT_EQ(headerOf(*table), QStringLiteral("Since connect (s)"));
    EXPECT_TRUE(count->text().contains(QStringLiteral("since connect — not recorded"))) << count->text().toStdString();

    ASSERT_TRUE(window.startRecording());
    ASSERT_TRUE(waitFor([&] { return table->rowCount() == 0; }, 2000));  // a new panel
    EXPECT_EQ(headerOf(*table), QStringLiteral("Recording (s)"));
    ASSERT_TRUE(waitFor([&] { return table->rowCount() >= 3; }, 20000));
    window.stopRecording();
    if (auto* verdict = window.findChild<QDialog*>(QStringLiteral("verdictBox"))) verdict->close();

    core::storage::SessionStore sessions(store.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto session = sessions.sessions().front();
    auto stored = sessions.events(session.id);
    std::erase_if(stored, [](const auto& e) { return e.kind != core::EventKind::Defect; });
    ASSERT_EQ(table->rowCount(), static_cast<int>(stored.size()));
    for (int row = 0; row < table->rowCount(); ++row)
        EXPECT_NEAR(QLocale().toDouble(table->item(row, 0)->text()), stored[static_cast<std::size_t>(row)].start_s,
                    0.005)
            << row;
    EXPECT_EQ(headerOf(*table), QStringLiteral("Recording (s)"));
    EXPECT_TRUE(count->text().contains(QStringLiteral("recorded on this panel"))) << count->text().toStdString();
    tactiscope::testing::saveScreenshot(window, QStringLiteral("panel-scan-after-stop"));

    // The next defect: a list of its own, since connect, with no recorded row.
    ASSERT_TRUE(waitFor([&] { return headerOf(*table) == QStringLiteral("Since connect (s)"); }, 20000));
    EXPECT_TRUE(count->text().contains(QStringLiteral("since connect — not recorded"))) << count->text().toStdString();
    for (int row = 0; row < table->rowCount(); ++row)
        EXPECT_GT(QLocale().toDouble(table->item(row, 0)->text()), stored.back().start_s) << row;
}

// Issue 52: the operator starts on the simulator, sees defects listed, then
// picks another source from the Device menu (the connector's real path):
// the new device's lists start empty instead of being read past their end.
TEST(LiveListsView, ConnectingAnotherDeviceAfterDefectsWereListedStartsItsListEmpty)
{
    QTemporaryDir dir;
    ui::MainWindow window;
    window.setStorePath(dir.filePath("s.tactiscope"));
    window.resize(1366, 768);
    window.station().connectSource(spedUp("panel-scan"));
    window.show();
    auto* view = window.findChild<ui::PanelScanView*>();
    auto* table = child<QTableWidget>(*view, "defectTable");
    ASSERT_TRUE(waitFor([&] { return table->rowCount() >= 1; }, 20000));

    QAction* panelLine = nullptr;
    for (QAction* action : window.findChildren<QAction*>())
        if (action->text() == QStringLiteral("panel-line")) panelLine = action;
    ASSERT_NE(panelLine, nullptr);
    panelLine->trigger();
    ASSERT_TRUE(window.station().isConnected());
    QTest::qWait(300);  // a few frames of the new device's views
    EXPECT_EQ(table->rowCount(), 0);
    EXPECT_TRUE(child<QLabel>(*view, "defectCountLabel")->text().startsWith(QStringLiteral("0 defects")))
        << child<QLabel>(*view, "defectCountLabel")->text().toStdString();
}

TEST(LiveListsView, PressesAreListedOnTheRecordingsClockAndTheGridStartsAtTheSiteSelectedBeforeRecord)
{
    QTemporaryDir dir;
    const QString store = dir.filePath("p.tactiscope");
    ui::MainWindow window;
    window.setStorePath(store);
    window.resize(1366, 768);
    window.station().connectSource(spedUp("palpation"));
    window.show();
    ui::PalpationView* view = window.findChild<ui::PalpationView*>();
    ui::SiteGridMap* grid = view->siteGrid();
    grid->setActive(true);
    grid->selectSite(0, 0);  // A1, before anything is recorded
    auto* table = child<QTableWidget>(*view, "pressTable");
    ASSERT_TRUE(waitFor([&] { return table->rowCount() >= 2; }, 20000));
    EXPECT_EQ(headerOf(*table), QStringLiteral("Since connect (s)"));
    // Presses outside a recording are neither mapped nor moved on.
    EXPECT_EQ(grid->currentSite(), QStringLiteral("A1"));
    EXPECT_FALSE(grid->valueAt(0, 0));

    ASSERT_TRUE(window.startRecording());
    ASSERT_TRUE(waitFor([&] { return table->rowCount() == 0; }, 2000));
    EXPECT_EQ(headerOf(*table), QStringLiteral("Recording (s)"));
    ASSERT_TRUE(waitFor([&] { return table->rowCount() >= 2 && grid->valueAt(0, 1).has_value(); }, 20000));
    window.stopRecording();
    tactiscope::testing::saveScreenshot(window, QStringLiteral("palpation-after-stop"));

    core::storage::SessionStore sessions(store.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto readings = sessions.readings(sessions.sessions().front().id);
    ASSERT_GE(readings.size(), 2u);
    EXPECT_EQ(readings[0].site, "A1");
    EXPECT_EQ(readings[1].site, "A2");
    for (int row = 0; row < 2; ++row) {
        EXPECT_NEAR(QLocale().toDouble(table->item(row, 0)->text()), readings[static_cast<std::size_t>(row)].start_s,
                    0.05)
            << row;
        EXPECT_EQ(table->item(row, 5)->text().toStdString(), readings[static_cast<std::size_t>(row)].site);
    }
    ASSERT_TRUE(grid->valueAt(0, 0));
    EXPECT_NEAR(*grid->valueAt(0, 0), readings[0].value, 1e-9);
}

TEST(LiveListsView, ABoardThatSaysNothingRecordsInGeneralModeAndItsRolesAreRememberedForWhenItSaysItsUnits)
{
    QTemporaryDir dir;
    const QString store = dir.filePath("m.tactiscope");
    ui::MainWindow window;
    window.setStorePath(store);
    window.resize(1366, 768);
    window.station().connectSource(makerBoard());
    window.show();
    EXPECT_EQ(window.mode(), core::Mode::General);
    EXPECT_FALSE(window.findChild<ui::PanelScanView*>()->isVisible());
    EXPECT_FALSE(window.setMode(core::Mode::PanelScan));  // refused: no roles yet
    auto* roles = window.devicePanel()->rolesBox();
    ASSERT_TRUE(roles->isVisible());
    EXPECT_TRUE(roles->isOpen());  // the device feeds no mode by itself
    EXPECT_EQ(child<QComboBox>(*roles, "a")->currentText(), QStringLiteral("by kind (other)"));

    // A general recording: the channels as they come.
    ASSERT_TRUE(window.startRecording());
    EXPECT_FALSE(child<QComboBox>(*roles, "a")->isEnabled());  // a recording keeps its roles
    waitFor([] { return false; }, 600);
    window.stopRecording();
    if (auto* verdict = window.findChild<QDialog*>(QStringLiteral("verdictBox"))) verdict->close();

    roles->chooseRole(QStringLiteral("a"), core::ChannelRole::CantileverA);
    roles->chooseRole(QStringLiteral("b"), core::ChannelRole::CantileverB);
    tactiscope::testing::saveScreenshot(*window.devicePanel(), QStringLiteral("device-panel-roles"));
    // Roles make no plain number a strain (issue 53): still refused.
    EXPECT_FALSE(window.setMode(core::Mode::PanelScan));
    EXPECT_EQ(window.mode(), core::Mode::General);

    // The board again, now printing its values as strains: the roles
    // chosen come back, and the panel scan runs.
    window.station().disconnectDevices();
    EXPECT_FALSE(roles->isVisible());
    window.station().connectSource(makerBoard(true));
    EXPECT_EQ(roles->roles(),
              (core::RoleAssignment{{"a", core::ChannelRole::CantileverA}, {"b", core::ChannelRole::CantileverB}}));
    ASSERT_TRUE(window.setMode(core::Mode::PanelScan));
    ASSERT_TRUE(window.findChild<ui::PanelScanView*>()->isVisible());
    ASSERT_TRUE(window.startRecording());
    auto* table = child<QTableWidget>(*window.findChild<ui::PanelScanView*>(), "defectTable");
    ASSERT_TRUE(waitFor([&] { return table->rowCount() >= 2; }, 20000));
    window.stopRecording();
    if (auto* verdict = window.findChild<QDialog*>(QStringLiteral("verdictBox"))) verdict->close();

    {
        core::storage::SessionStore sessions(store.toStdString(), core::storage::Database::Access::ReadOnly);
        const auto all = sessions.sessions();
        ASSERT_EQ(all.size(), 2u);
        const auto& general = all[0].metadata.mode == core::Mode::General ? all[0] : all[1];
        const auto& scan = all[0].metadata.mode == core::Mode::PanelScan ? all[0] : all[1];
        EXPECT_EQ(general.metadata.mode, core::Mode::General);
        EXPECT_GT(general.sampleCount, 100u);
        EXPECT_EQ(scan.metadata.mode, core::Mode::PanelScan);
        EXPECT_EQ(scan.verdict, core::Verdict::DefectsFound);
        EXPECT_EQ(sessions.channels(scan.id)[0].descriptor.role, core::ChannelRole::CantileverA);
        EXPECT_EQ(sessions.channels(general.id)[0].descriptor.kind, core::ChannelKind::Other);
    }
}
