// Tools ▸ Shunt check… from the main window: on the simulated panel probe at
// rest (quarter bridges, 350 Ω, GF 2, a 100 kΩ shunt) the check passes for
// GF 2 and fails for 2.1 (+5.00 %, computed by hand: y/GF with
// y = −350/100350), both kept in the calibration history; while recording,
// the result is a marker in the session; an in-process emulated probe
// without the shunt command is refused with the reason, as the GUI says it.
#include "core/calibration/CalibrationRecord.h"
#include "core/storage/SessionStore.h"
#include "devices/emulator/ProbeEmulator.h"
#include "support/MainWindowHelpers.h"
#include "support/Screenshot.h"
#include "support/TempPath.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/calibration/ShuntCheckDialog.h"
#include "ui/live/LiveStation.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QLocale>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::testing::child;
using tactiscope::testing::liveSimulator;
using tactiscope::testing::waitFor;

namespace {

ui::ShuntCheckDialog* openShuntCheck(ui::MainWindow& window)
{
    window.findChild<QAction*>(QStringLiteral("shuntCheckAction"))->trigger();
    return window.findChild<ui::ShuntCheckDialog*>(QStringLiteral("shuntCheckDialog"));
}

}  // namespace

TEST(ShuntCheck, ThePanelProbesBridgePassesForItsGaugeFactorAndFailsForAnother)
{
    QTemporaryDir dir;
    const QString store = dir.filePath("checks.tactiscope");
    ui::MainWindow window;
    window.setStorePath(store);
    window.show();
    window.station().connectSource(liveSimulator("panel-rest"));
    QTest::mouseClick(child<QPushButton>(window, "recordButton"), Qt::LeftButton);
    ASSERT_TRUE(window.isRecording());
    auto* dialog = openShuntCheck(window);
    ASSERT_NE(dialog, nullptr);
    QTest::mouseClick(child<QPushButton>(*dialog, "shuntRun"), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return !dialog->running(); }, 8000));
    EXPECT_TRUE(dialog->resultText().contains(QStringLiteral("PASS"))) << dialog->resultText().toStdString();
    const QString expected = QStringLiteral("expected %1 µε").arg(QLocale().toString(-1743.9, 'f', 1));
    EXPECT_TRUE(dialog->resultText().contains(expected)) << dialog->resultText().toStdString();
    tactiscope::testing::saveScreenshot(*dialog, QStringLiteral("shunt-check"));
    // The dialog takes the ranges the CLI takes (docs/user-guide.md): a
    // tolerance of 0.01 to 50 %, a gauge factor of 0.1 to 200.
    EXPECT_EQ(child<QDoubleSpinBox>(*dialog, "shuntTolerance")->minimum(), 0.01);
    EXPECT_EQ(child<QDoubleSpinBox>(*dialog, "shuntTolerance")->maximum(), 50.0);
    EXPECT_EQ(child<QDoubleSpinBox>(*dialog, "shuntGaugeFactor")->maximum(), 200.0);
    child<QDoubleSpinBox>(*dialog, "shuntGaugeFactor")->setValue(2.1);
    QTest::mouseClick(child<QPushButton>(*dialog, "shuntRun"), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return !dialog->running(); }, 8000));
    EXPECT_TRUE(dialog->resultText().contains(QStringLiteral("FAIL"))) << dialog->resultText().toStdString();
    EXPECT_TRUE(dialog->resultText().contains(QStringLiteral("deviation +5.00 %")))
        << dialog->resultText().toStdString();
    QTest::mouseClick(child<QPushButton>(window, "recordButton"), Qt::LeftButton);  // stop
    ASSERT_FALSE(window.isRecording());

    core::storage::SessionStore checks(store.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto history = checks.calibrations();
    ASSERT_EQ(history.size(), 2u);
    int passed = 0;
    for (const auto& stored : history) {
        EXPECT_EQ(stored.record.kind, core::calibration::kShuntCheckKind);
        passed += stored.record.value("shunt_passed") == 1.0 ? 1 : 0;
    }
    EXPECT_EQ(passed, 1);
    // The session holds both results as markers, beside the steps they made.
    auto events = checks.events(checks.sessions().front().id);
    std::erase_if(events, [](const auto& e) { return e.kind != core::EventKind::Marker; });
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].note.rfind("shunt check a: PASS", 0), 0u) << events[0].note;
    EXPECT_EQ(events[1].note.rfind("shunt check a: FAIL, deviation +5.00 %", 0), 0u) << events[1].note;
}

TEST(ShuntCheck, AProbeThatCannotSwitchAShuntIsToldSo)
{
    const std::string link = tactiscope::testing::uniqueTempPath("noshunt");
    devices::emulator::EmulatorOptions options;
    options.linkPath = link;
    options.scenario = "panel-rest";
    options.shunt = false;
    devices::emulator::ProbeEmulator emulator(options);
    emulator.start();
    QTemporaryDir dir;
    ui::MainWindow window;
    window.setStorePath(dir.filePath("s.tactiscope"));
    window.show();
    window.station().connectDevice(QString::fromStdString(link), tactiscope::testing::serialOpener(link));
    ASSERT_TRUE(waitFor([&] { return window.station().isConnected(); }, 6000));
    auto* dialog = openShuntCheck(window);
    ASSERT_NE(dialog, nullptr);
    QTest::mouseClick(child<QPushButton>(*dialog, "shuntRun"), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return !dialog->running(); }, 8000));
    EXPECT_TRUE(dialog->resultText().contains(QStringLiteral("Not checked")));
    EXPECT_TRUE(dialog->resultText().contains(QStringLiteral("it cannot switch a shunt")))
        << dialog->resultText().toStdString();
}
