// A stored gauge-factor calibration is the one the palpation view reads its
// beam with (the newest of each beam), goes into every session recorded in
// palpation mode (copied and linked), and the wizard opens from the Tools
// menu on the simulator's calibration rig.
#include "core/calibration/CalibrationRecord.h"
#include "core/compliance/LivePalpation.h"
#include "core/storage/SessionStore.h"
#include "support/MainWindowHelpers.h"
#include "support/TempDirectory.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/live/LiveStation.h"
#include "ui/modes/palpation/GaugeFactorWizard.h"
#include "ui/modes/palpation/PalpationView.h"
#include "ui/profiles/ActiveProfiles.h"

#include <QAction>
#include <QComboBox>
#include <QDateTime>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMenuBar>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::testing::child;

namespace {

class GaugeCalibrationInUseTest : public tactiscope::testing::TempDirectoryTest {
protected:
    QString store() const { return QString::fromStdString(file("sessions.tactiscope")); }

    static core::calibration::CalibrationRecord gaugeRecord(bool stiff, double gaugeFactor, const char* when)
    {
        const auto probe = std::get<core::sensors::CompliancePairProfile>(
            ui::readProfile(ui::builtInProfilePath(QStringLiteral("palpation"))));
        core::calibration::CalibrationRecord r;
        r.kind = "gauge_factor";
        r.sensorName = tactiscope::core::calibration::beamSensorName(probe.name, stiff);
        r.operatorName = "Ada";
        r.timestampUtc = when;
        r.values = {{"gauge_factor", gaugeFactor}, {"nominal_gauge_factor", 2.0}};
        return r;
    }

    // A menu action by its text, in any menu or submenu.
    static QAction* menuAction(const QList<QAction*>& actions, const QString& text)
    {
        for (QAction* action : actions) {
            if (action->text() == text) return action;
            if (action->menu())
                if (QAction* found = menuAction(action->menu()->actions(), text)) return found;
        }
        return nullptr;
    }
};

}  // namespace

TEST_F(GaugeCalibrationInUseTest, TheNewestCalibrationOfEachBeamIsReadAndRecorded)
{
    std::int64_t newest = 0;
    {
        core::storage::SessionStore calibrations(store().toStdString());
        calibrations.addCalibration(gaugeRecord(true, 2.30, "2026-11-01T08:00:00Z"));  // superseded
        newest = calibrations.addCalibration(gaugeRecord(true, 2.14, "2026-11-20T08:00:00Z"));
    }
    ui::MainWindow window;
    window.setStorePath(store());
    window.setMode(tactiscope::core::Mode::Palpation);
    window.station().connectSource(tactiscope::testing::liveSimulator("palpation"));
    const QString probe = child<QLabel>(*window.findChild<ui::PalpationView*>(), "probeLabel")->text();
    // The calibration's date on screen in the locale's words, never the stored ISO text.
    const QString day = QLocale().toString(QDateTime(QDate(2026, 11, 20), QTime(8, 0), Qt::UTC).toLocalTime().date(),
                                           QLocale::ShortFormat);
    // The label says "stored"; its tooltip which, when and by whom.
    const QString which = child<QLabel>(*window.findChild<ui::PalpationView*>(), "probeLabel")->toolTip();
    EXPECT_TRUE(probe.contains(QStringLiteral("Calibration: stored"))) << probe.toStdString();
    EXPECT_TRUE(which.contains(QStringLiteral("stiff beam, calibrated %1 ").arg(day))) << which.toStdString();
    EXPECT_TRUE(which.contains(QStringLiteral(" by Ada"))) << which.toStdString();
    EXPECT_FALSE(which.contains(QStringLiteral("08:00:00Z"))) << which.toStdString();
    EXPECT_TRUE(probe.contains(QStringLiteral("gauge factors 2.14 (stiff) and 2 (soft)"))) << probe.toStdString();

    ASSERT_TRUE(window.startRecording());
    window.stopRecording();
    core::storage::SessionStore sessions(store().toStdString(), core::storage::Database::Access::ReadOnly);
    const auto session = sessions.sessions().front();
    EXPECT_NE(session.metadata.calibrationsJson.find("2026-11-20T08:00:00Z"), std::string::npos);
    EXPECT_EQ(session.metadata.calibrationsJson.find("2026-11-01T08:00:00Z"), std::string::npos);
    EXPECT_EQ(sessions.calibrationsOfSession(session.id), std::vector<std::int64_t>{newest});
}

TEST_F(GaugeCalibrationInUseTest, TheToolsMenuOpensTheWizardOnTheConnectedRig)
{
    ui::MainWindow window;
    window.setStorePath(store());
    QAction* calibrate = menuAction(window.menuBar()->actions(), QStringLiteral("Calibrate the &gauge factor…"));
    ASSERT_NE(calibrate, nullptr);
    calibrate->trigger();  // nothing connected: says so, opens nothing
    EXPECT_EQ(window.findChild<ui::GaugeFactorWizard*>(), nullptr);

    QAction* rig = menuAction(window.menuBar()->actions(), QStringLiteral("gauge-calibration"));
    ASSERT_NE(rig, nullptr);
    rig->trigger();
    ASSERT_TRUE(window.station().isConnected());
    calibrate->trigger();
    auto* wizard = window.findChild<ui::GaugeFactorWizard*>();
    ASSERT_NE(wizard, nullptr);
    // The rig holds the palpation probe's stiff beam, and says so.
    EXPECT_EQ(child<QComboBox>(*wizard, "channelBox")->currentText(), QStringLiteral("high"));
    EXPECT_EQ(child<QComboBox>(*wizard, "beamBox")->currentIndex(), 0);
    wizard->next();
    wizard->next();
    ASSERT_EQ(wizard->currentId(), ui::GaugeFactorWizard::ZeroPage);
    EXPECT_TRUE(tactiscope::testing::waitFor([&] { return wizard->currentPage()->isComplete(); }, 10000));
    wizard->reject();

    // The soft beam's rig: the wizard calibrates the soft beam.
    window.station().disconnectDevices();
    QAction* softRig = menuAction(window.menuBar()->actions(), QStringLiteral("gauge-calibration-soft"));
    ASSERT_NE(softRig, nullptr);
    softRig->trigger();
    calibrate->trigger();
    ui::GaugeFactorWizard* soft = nullptr;  // the first one may wait for its deletion
    for (auto* open : window.findChildren<ui::GaugeFactorWizard*>())
        if (child<QComboBox>(*open, "channelBox")->currentText() == QStringLiteral("low")) soft = open;
    ASSERT_NE(soft, nullptr);
    EXPECT_EQ(child<QComboBox>(*soft, "beamBox")->currentIndex(), 1);
    soft->reject();
}
