// Capacitive mode against the live simulator with weights placed quickly:
// the readouts follow the stored calibration (ΔC = C − C0, F = ΔC/S,
// w = ΔC/(S·k_s), checked on the numbers shown), the calibration in use is
// named, linked to the session and copied into it, and tare re-takes C0.
#include "ui/modes/capacitive/CapacitiveView.h"

#include "core/storage/SessionStore.h"
#include "devices/simulator/CapacitiveWeightsScenario.h"
#include "devices/simulator/SimulatorSource.h"
#include "support/MainWindowHelpers.h"
#include "support/Screenshot.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/live/LiveStation.h"

#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <cmath>

using namespace tactiscope;
using tactiscope::testing::child;
using tactiscope::testing::runEventLoopFor;
using tactiscope::testing::waitFor;

namespace {

constexpr double kSensitivity_pf_per_mn = 3.0;  // the calibration the store holds
const std::string kSensor = "Uniform-strength beam No. 1 (seed 002: Eco-flex 0050, 15 mm)";

std::unique_ptr<devices::BlockSource> quickWeights()
{
    devices::simulator::CapacitiveWeightsParameters p;
    p.baseline_s = 1.5;
    p.dwell_s = 1.5;
    return std::make_unique<devices::simulator::SimulatorSource>(
        std::make_unique<devices::simulator::CapacitiveWeightsScenario>(p));
}

// The number at the start of a readout such as "1,234.5 µN".
double number(const QLabel* label)
{
    return QLocale().toDouble(label->text().section(QLatin1Char(' '), 0, 0));
}

}  // namespace

TEST(CapacitiveView, ReadoutsFollowTheStoredCalibrationWhichTheSessionRecords)
{
    QTemporaryDir dir;
    const QString store = dir.filePath("s.tactiscope");
    std::int64_t calibration = 0;
    {
        core::storage::SessionStore sessions(store.toStdString());
        core::calibration::CalibrationRecord record;
        record.kind = "capacitive";
        record.sensorName = kSensor;
        record.operatorName = "Dr Calibrator";
        record.timestampUtc = "2026-11-20T09:00:00Z";
        record.values = {
            {"c0_pf", 51.44}, {"baseline_sigma_pf", 0.004}, {"sensitivity_pf_per_mn", kSensitivity_pf_per_mn}};
        calibration = sessions.addCalibration(record);
    }
    ui::MainWindow window;
    window.setStorePath(store);
    window.resize(1366, 768);  // the smallest screen the workstation is made for
    auto* mode = child<QComboBox>(window, "modeBox");
    mode->setCurrentIndex(mode->findData(QStringLiteral("capacitive")));
    window.station().connectSource(quickWeights());
    window.show();
    ui::CapacitiveView* view = window.findChild<ui::CapacitiveView*>();
    ASSERT_TRUE(view->isVisible());
    EXPECT_TRUE(child<QLabel>(*view, "calibrationLabel")->text().contains(QStringLiteral("Dr Calibrator")));
    ASSERT_TRUE(window.startRecording());

    // Weights go on after 1.5 s; wait for a clear force.
    auto* force = child<QLabel>(*view, "forceReadout");
    ASSERT_TRUE(waitFor([&] { return number(force) > 20.0; }, 6000)) << force->text().toStdString();
    runEventLoopFor(300);
    tactiscope::testing::saveScreenshot(window, QStringLiteral("capacitive"));
    tactiscope::testing::saveScreenshotAtSize(window, QStringLiteral("capacitive"), {1920, 1080});
    const double c_pf = number(child<QLabel>(*view, "capacitanceReadout"));
    const double deltaC_pf = number(child<QLabel>(*view, "deltaCReadout"));
    const double c0_pf =
        QLocale().toDouble(child<QLabel>(*view, "baselineLabel")->text().section(QLatin1Char(' '), 2, 2));
    const double force_un = number(force);
    const double deflection_mm = number(child<QLabel>(*view, "displacementReadout"));
    const double relative_percent = number(child<QLabel>(*view, "relativeReadout"));
    EXPECT_NEAR(deltaC_pf, c_pf - c0_pf, 0.0011);  // three decimals shown
    // F = ΔC/S: pF over pF/mN gives mN, ×1000 for µN.
    EXPECT_NEAR(force_un, deltaC_pf / kSensitivity_pf_per_mn * 1e3, 0.5);
    // w = F/k_s.
    const double k = devices::simulator::CapacitiveWeightsScenario().beam().stiffness_n_per_m();
    EXPECT_NEAR(deflection_mm, force_un * 1e-6 / k * 1e3, 0.0011);
    // Each shown to three decimals: ΔC/C0 from the shown ΔC and C0 is off
    // by their rounding too (0.0005 pF of ΔC is 0.0012 % of a 40 pF C0).
    const double rounding = 0.0005 + 0.0005 / c0_pf * 100.0 + std::abs(deltaC_pf) * 0.0005 / (c0_pf * c0_pf) * 100.0;
    EXPECT_NEAR(relative_percent, deltaC_pf / c0_pf * 100.0, rounding * 1.01);
    window.stopRecording();

    core::storage::SessionStore sessions(store.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto session = sessions.sessions().front();
    EXPECT_EQ(session.metadata.mode, tactiscope::core::Mode::Capacitive);
    EXPECT_NE(session.metadata.calibrationsJson.find("Dr Calibrator"), std::string::npos);
    EXPECT_NE(session.metadata.profileJson.find("capacitive_beam"), std::string::npos);
    EXPECT_EQ(sessions.calibrationsOfSession(session.id), std::vector<std::int64_t>{calibration});
}

TEST(CapacitiveView, WithoutACalibrationTheBeamModelIsUsedAndSaid)
{
    QTemporaryDir dir;
    ui::MainWindow window;
    window.setStorePath(dir.filePath("empty.tactiscope"));  // does not exist yet
    auto* mode = child<QComboBox>(window, "modeBox");
    mode->setCurrentIndex(mode->findData(QStringLiteral("capacitive")));
    window.station().connectSource(quickWeights());
    window.show();
    EXPECT_TRUE(
        child<QLabel>(*window.findChild<ui::CapacitiveView*>(), "calibrationLabel")->text().contains("uncalibrated"));
    // Tare while unloaded: ΔC goes to the noise (σ = 4 fF).
    auto* deltaC = child<QLabel>(*window.findChild<ui::CapacitiveView*>(), "deltaCReadout");
    ASSERT_TRUE(waitFor([&] { return deltaC->text() != QStringLiteral("—"); }, 3000));
    QTest::mouseClick(child<QPushButton>(*window.findChild<ui::CapacitiveView*>(), "tareButton"), Qt::LeftButton);
    runEventLoopFor(600);
    EXPECT_LT(std::abs(number(deltaC)), 0.02) << deltaC->text().toStdString();
}
