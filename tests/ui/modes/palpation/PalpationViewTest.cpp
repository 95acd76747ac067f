// Palpation mode against the live simulator: each completed press appears
// as a row, lands in the selected grid cell and is stored in the session
// with the stiffness the core reads from the recorded samples; the large
// readout and the reference scale show it; tare takes a new zero.
#include "ui/modes/palpation/PalpationView.h"
#include "devices/session/modes/PalpationUnit.h"

#include "core/compliance/StiffnessReadings.h"
#include "core/storage/SessionStore.h"
#include "devices/session/LiveSession.h"
#include "devices/simulator/PalpationScenario.h"
#include "support/LiveUnit.h"
#include "support/MainWindowHelpers.h"
#include "support/Screenshot.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/live/LiveStation.h"
#include "ui/modes/palpation/SiteGridMap.h"
#include "ui/modes/panelscan/PanelScanView.h"
#include "ui/plot/XYPlotWidget.h"

#include <QComboBox>
#include <QDockWidget>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <cmath>

using namespace tactiscope;
using tactiscope::devices::session::PalpationUnit;
using tactiscope::testing::child;
using tactiscope::testing::liveSimulator;
using tactiscope::testing::liveUnit;
using tactiscope::testing::runEventLoopFor;
using tactiscope::testing::waitFor;

namespace {

void choosePalpationMode(ui::MainWindow& window)
{
    auto* mode = child<QComboBox>(window, "modeBox");
    mode->setCurrentIndex(mode->findData(QStringLiteral("palpation")));
}

}  // namespace

TEST(PalpationView, PressesAreListedMappedStoredAndMatchTheCoreReading)
{
    QTemporaryDir dir;
    const QString store = dir.filePath("s.tactiscope");
    ui::MainWindow window;
    window.setStorePath(store);
    window.resize(1366, 768);  // the smallest screen the workstation is made for
    choosePalpationMode(window);
    // Recording starts with the stream, while the simulated hand still holds
    // the probe lifted (its first press comes after 1 s).
    window.station().connectSource(liveSimulator("palpation"));
    ASSERT_TRUE(window.startRecording());
    window.show();
    ui::PalpationView* view = window.findChild<ui::PalpationView*>();
    ASSERT_TRUE(view->isVisible());
    EXPECT_FALSE(window.findChild<ui::PanelScanView*>()->isVisible());
    ui::SiteGridMap* grid = view->siteGrid();
    grid->setActive(true);
    grid->selectSite(1, 1);  // B2

    auto* table = child<QTableWidget>(*view, "pressTable");
    ASSERT_TRUE(waitFor([&] { return table->rowCount() >= 2; }, 12000));
    runEventLoopFor(300);
    tactiscope::testing::saveScreenshot(window, QStringLiteral("palpation"));
    tactiscope::testing::saveScreenshotAtSize(window, QStringLiteral("palpation"), {1920, 1080});
    // Every column is in view: the table never scrolls sideways.
    EXPECT_LE(table->horizontalHeader()->length(), table->viewport()->width());
    window.stopRecording();

    // The simulated specimen is 117 N/m: every press reads it within 5 %.
    const double truth = devices::simulator::PalpationParameters{}.objectStiffness_n_per_m;
    for (int row = 0; row < table->rowCount(); ++row)
        EXPECT_NEAR(QLocale().toDouble(table->item(row, 1)->text()), truth, 0.05 * truth) << row;
    EXPECT_EQ(table->item(0, 5)->text(), QStringLiteral("B2"));
    EXPECT_EQ(table->item(1, 5)->text(), QStringLiteral("B3"));
    ASSERT_TRUE(grid->valueAt(1, 1).has_value());
    EXPECT_NEAR(*grid->valueAt(1, 1), QLocale().toDouble(table->item(0, 1)->text()), 0.05);
    EXPECT_TRUE(child<QLabel>(*view, "stiffnessLabel")->text().endsWith(QStringLiteral("N/m")));
    // The probe and what turns its counts into forces are always in view.
    const QString probe = child<QLabel>(*view, "probeLabel")->text();
    EXPECT_TRUE(probe.contains(QStringLiteral("Perspex two-beam probe"))) << probe.toStdString();
    EXPECT_TRUE(probe.contains(QStringLiteral("none, nominal — gauge factors 2 (stiff) and 2 (soft)")))
        << probe.toStdString();

    core::storage::SessionStore sessions(store.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto session = sessions.sessions().front();
    EXPECT_EQ(session.metadata.mode, tactiscope::core::Mode::Palpation);
    EXPECT_NE(session.metadata.profileJson.find("compliance_pair"), std::string::npos);
    const auto readings = sessions.readings(session.id);
    ASSERT_GE(readings.size(), 2u);
    EXPECT_EQ(readings[0].site, "B2");
    EXPECT_EQ(readings[0].unit, "N/m");
    EXPECT_NE(readings[0].detailsJson.find("displacement_slope_n_per_m_per_m"), std::string::npos);

    // The core's reading of the recorded samples of each press: counts →
    // strain → force with the zero of the session's first half second.
    const devices::simulator::PalpationParameters p;
    const std::uint64_t n = session.sampleCount;
    const auto high = sessions.readChannel(session.id, 0, 0, n);
    const auto low = sessions.readChannel(session.id, 1, 0, n);
    const auto displacement = sessions.readChannel(session.id, 2, 0, n);
    devices::simulator::PalpationScenario scenario;
    auto highChain = scenario.chain(), lowChain = scenario.chain();
    const std::size_t tare = 500;
    double zeroHigh = 0.0, zeroLow = 0.0;
    for (std::size_t i = 0; i < tare; ++i) {
        zeroHigh += high[i] / tare;
        zeroLow += low[i] / tare;
    }
    // Each zero's standard error, σ/√n of its half second, in counts.
    double squaresHigh = 0.0, squaresLow = 0.0;
    for (std::size_t i = 0; i < tare; ++i) {
        squaresHigh += (high[i] - zeroHigh) * (high[i] - zeroHigh);
        squaresLow += (low[i] - zeroLow) * (low[i] - zeroLow);
    }
    const double zeroHighU_counts = std::sqrt(squaresHigh / (tare - 1.0) / tare);
    const double zeroLowU_counts = std::sqrt(squaresLow / (tare - 1.0) / tare);
    highChain.tare(zeroHigh);
    lowChain.tare(zeroLow);
    const core::sensors::CantileverBeam highBeam(p.high), lowBeam(p.low);
    const double zeroHighU_n = highChain.strain(zeroHigh + zeroHighU_counts) / highBeam.rootStrainPerNewton();
    const double zeroLowU_n = lowChain.strain(zeroLow + zeroLowU_counts) / lowBeam.rootStrainPerNewton();
    const core::sensors::CompliancePair pair(highBeam, lowBeam);
    for (const auto& stored : readings) {
        std::vector<double> x, fh, fl;
        const auto first = static_cast<std::size_t>(std::llround(stored.start_s * p.sampleRate_hz));
        const auto last = static_cast<std::size_t>(std::llround(stored.end_s * p.sampleRate_hz));
        for (std::size_t i = first; i <= last && i < n; ++i) {
            const double forceHigh = highChain.strain(high[i]) / highBeam.rootStrainPerNewton();
            const double forceLow = lowChain.strain(low[i]) / lowBeam.rootStrainPerNewton();
            if (forceHigh <= 0.01 || forceLow <= 0.01) continue;
            x.push_back(displacement[i]);
            fh.push_back(forceHigh);
            fl.push_back(forceLow);
        }
        const auto expected = core::compliance::readPress(pair, x, fh, fl);
        EXPECT_NEAR(stored.value, expected.stiffness.objectStiffness_n_per_m, 0.005 * stored.value) << stored.start_s;
        // The stored uncertainty adds the zero's: an offset δ of F_H moves
        // k_o by (dk/dQ)·δ/F̄_L, one of F_L by (dk/dQ)·Q·δ/F̄_L, with dk/dQ
        // the inverse of eq. 5 (k_h = 1620, k_l = 60 N/m).
        double sumHigh = 0.0, sumLow = 0.0;
        for (std::size_t i = 0; i < fh.size(); ++i) {
            sumHigh += fh[i];
            sumLow += fl[i];
        }
        const double q = sumHigh / sumLow, meanLow = sumLow / static_cast<double>(fl.size());
        const double k = stored.value;
        const double dkDq = 60.0 * (k + 1620.0) * (k + 1620.0) / (1620.0 * (1620.0 - 60.0));
        const double zeroPart = std::hypot(dkDq * zeroHighU_n / meanLow, dkDq * q * zeroLowU_n / meanLow);
        const double combined = std::hypot(expected.standardError_n_per_m, zeroPart);
        EXPECT_NEAR(*stored.standardError, combined, 0.2 * combined);
    }
}

TEST(PalpationView, TareTakesANewZeroFromTheButtonOrCtrlTAndTheXYPlotShowsTheForces)
{
    ui::MainWindow window;
    choosePalpationMode(window);
    window.station().connectSource(liveSimulator("palpation"));
    window.show();
    auto* status = child<QLabel>(*window.findChild<ui::PalpationView*>(), "palpationStatus");
    ASSERT_TRUE(waitFor([&] { return status->text().startsWith(QStringLiteral("Ready")); }, 3000));
    // Lifted and still for half a second: taken at once from that stretch
    // (the simulator presses every few seconds, so the button is tried until then).
    auto* tareButton = child<QPushButton>(*window.findChild<ui::PalpationView*>(), "tareButton");
    EXPECT_TRUE(waitFor(
        [&] {
            QTest::mouseClick(tareButton, Qt::LeftButton);
            return window.statusBar()->currentMessage().startsWith(QStringLiteral("Tared"));
        },
        8000));
    // At a press the rule refuses it, with the reason, and the zero stays.
    ASSERT_TRUE(waitFor([&] { return status->text().startsWith(QStringLiteral("Pressing")); }, 8000));
    runEventLoopFor(600);  // half a second into the press, so the rule sees it whole
    ASSERT_TRUE(status->text().startsWith(QStringLiteral("Pressing")));
    QTest::keyClick(&window, Qt::Key_T, Qt::ControlModifier);
    const QString refused = window.statusBar()->currentMessage();
    EXPECT_TRUE(refused.startsWith(QStringLiteral("Not tared: the probe is pressing"))) << refused.toStdString();
    EXPECT_FALSE(liveUnit<PalpationUnit>(*window.station().device()).palpation()->state().taring);

    // The mode's XY plot (F_H against F_L), on request.
    child<QDockWidget>(window, "xyDock")->show();
    auto* xy = child<ui::XYPlotWidget>(window, "xyPlot");
    EXPECT_TRUE(waitFor([&] { return xy->drawnPointCount() > 100; }, 2000));
    EXPECT_LE(xy->drawnPointCount(), static_cast<int>(ui::XYPlotWidget::kMaxPoints));
    // Its slope is Q: 1620·(117 + 60)/(60·(117 + 1620)) = 2.751 (eq. 1) for the simulated specimen.
    ASSERT_TRUE(xy->slope().has_value());
    EXPECT_NEAR(*xy->slope(), 2.7513, 0.05);
    EXPECT_TRUE(xy->slopeText().startsWith(QStringLiteral("Q = "))) << xy->slopeText().toStdString();
    EXPECT_GE(xy->width(), 300) << "the dock opens at a usable width";
}

TEST(PalpationView, APanelScanProbeHasNoPalpationView)
{
    ui::MainWindow window;
    choosePalpationMode(window);
    window.station().connectSource(liveSimulator("panel-scan"));
    window.show();
    EXPECT_FALSE(window.findChild<ui::PalpationView*>()->isVisible());
}
