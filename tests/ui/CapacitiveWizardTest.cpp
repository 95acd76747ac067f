// The C0 and sensitivity wizard completed from the keyboard against the
// simulator's capacitive calibration rig (the paper's sensor No. 1, 10 Hz,
// ten times faster than real time): weights on in 30 mgf steps to 150 mgf
// and off again, then a final baseline. The simulator's truth is its beam
// model: C0 = 51.44 pF and ΔC/F from eq. 13, which the slow creep of the
// silicone (1 % at most, τ = 4 s) can only raise.
#include "ui/calibration/CapacitiveWizard.h"

#include "core/storage/SessionStore.h"
#include "devices/Acquisition.h"
#include "devices/simulator/CapacitiveWeightsScenario.h"
#include "devices/simulator/SimulatorSource.h"
#include "support/MainWindowHelpers.h"
#include "support/Screenshot.h"
#include "support/TempDirectory.h"
#include "support/WaitFor.h"

#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QTest>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::testing::child;
using tactiscope::testing::waitFor;

namespace {

class CapacitiveWizardTest : public tactiscope::testing::TempDirectoryTest {
protected:
    void SetUp() override
    {
        TempDirectoryTest::SetUp();
        devices::simulator::CapacitiveWeightsParameters parameters;
        parameters.protocol = devices::simulator::WeightProtocol::Manual;
        auto scenario = std::make_unique<devices::simulator::CapacitiveWeightsScenario>(parameters);
        m_sensitivity_f_per_n = scenario->beam().capacitancePerNewton_f_per_n();
        m_rig = scenario->loadRig();
        m_context.channels = scenario->channels();
        m_context.sampleRate_hz = scenario->sampleRate_hz();
        devices::simulator::SimulatorOptions options;
        options.speed = 10.0;
        m_acquisition = std::make_unique<devices::Acquisition>(
            std::make_unique<devices::simulator::SimulatorSource>(std::move(scenario), options));
        auto buffer = std::make_shared<core::LiveBuffer>(1, 10000);
        m_acquisition->addSink(buffer);
        m_acquisition->start();
        m_context.buffer = buffer;
        m_context.rig = m_rig;
        m_context.storePath = QString::fromStdString(file("sessions.tsdb"));
        m_context.operatorName = QStringLiteral("Grace");
        m_context.profileDirectory = QString::fromStdString(file("profiles"));
    }

    void TearDown() override
    {
        m_acquisition->stop();
        TempDirectoryTest::TearDown();
    }

    // A mnemonic (Alt+letter) clicks its button with a short animation.
    static void press(QWidget& wizard, Qt::Key key)
    {
        QTest::keyClick(&wizard, key, Qt::AltModifier);
        tactiscope::testing::runEventLoopFor(250);
    }

    static bool pageComplete(const QWizard& wizard) { return wizard.currentPage()->isComplete(); }

    static void toSteps(ui::CapacitiveWizard& wizard)
    {
        wizard.show();
        wizard.activateWindow();
        ASSERT_TRUE(QTest::qWaitForWindowActive(&wizard));
        ASSERT_TRUE(pageComplete(wizard));
        press(wizard, Qt::Key_N);
        ASSERT_EQ(wizard.currentId(), ui::CapacitiveWizard::BaselinePage);
        ASSERT_TRUE(waitFor([&] { return pageComplete(wizard); }, 15000)) << "no stable baseline";
        press(wizard, Qt::Key_N);
        ASSERT_EQ(wizard.currentId(), ui::CapacitiveWizard::StepsPage);
    }

    // Types the total load in mgf and captures it; `placed` is what the rig
    // really carries when the operator miscounts the weights.
    void capture(ui::CapacitiveWizard& wizard, double mgf, std::optional<double> placed = std::nullopt)
    {
        auto* value = child<QDoubleSpinBox>(wizard, "loadValue");
        auto* button = child<QPushButton>(wizard, "captureButton");
        value->setFocus();
        value->selectAll();
        QTest::keyClicks(value, QLocale().toString(mgf));
        QMetaObject::Connection swap;
        if (placed)
            swap = QObject::connect(button, &QPushButton::clicked,
                                    [this, placed] { m_rig->place(*placed * core::calibration::kMilligramForce_n); });
        press(wizard, Qt::Key_C);
        QObject::disconnect(swap);
        ASSERT_TRUE(waitFor([&] { return button->isEnabled(); }, 15000));
    }

    ui::CalibrationContext m_context;
    double m_sensitivity_f_per_n = 0.0;
    std::shared_ptr<devices::simulator::LoadRig> m_rig;
    std::unique_ptr<devices::Acquisition> m_acquisition;
};

}  // namespace

TEST_F(CapacitiveWizardTest, LoadAndUnloadOnTheSimulatorStoresItsC0AndSensitivity)
{
    ui::CapacitiveWizard wizard(m_context);
    ASSERT_NO_FATAL_FAILURE(toSteps(wizard));
    for (double mgf : {30.0, 60.0, 90.0, 120.0, 150.0, 120.0, 90.0, 60.0, 30.0})
        ASSERT_NO_FATAL_FAILURE(capture(wizard, mgf));
    press(wizard, Qt::Key_F);  // the final baseline
    ASSERT_TRUE(waitFor([&] { return child<QPushButton>(wizard, "captureButton")->isEnabled(); }, 15000));
    auto* table = child<QTableWidget>(wizard, "stepsTable");
    ASSERT_EQ(table->rowCount(), 9);
    EXPECT_EQ(table->item(4, 1)->text(), QStringLiteral("loading"));
    EXPECT_EQ(table->item(5, 1)->text(), QStringLiteral("unloading"));
    tactiscope::testing::saveScreenshot(wizard, QStringLiteral("capacitive-wizard"));
    press(wizard, Qt::Key_N);
    ASSERT_EQ(wizard.currentId(), ui::CapacitiveWizard::ResultPage);
    ASSERT_TRUE(pageComplete(wizard)) << child<QLabel>(wizard, "problemsText")->text().toStdString();
    press(wizard, Qt::Key_A);
    EXPECT_FALSE(wizard.isVisible());

    core::storage::SessionStore store(m_context.storePath.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto all = store.calibrations();
    ASSERT_EQ(all.size(), 1u);
    const auto& r = all.front().record;
    EXPECT_EQ(r.kind, "capacitive");
    EXPECT_EQ(r.operatorName, "Grace");
    EXPECT_NEAR(*r.value("c0_pf"), 51.44, 0.01);
    const double model_pf_per_mn = m_sensitivity_f_per_n * 1e9;
    EXPECT_GE(*r.value("sensitivity_pf_per_mn"), 0.995 * model_pf_per_mn);
    EXPECT_LE(*r.value("sensitivity_pf_per_mn"), 1.015 * model_pf_per_mn);
    EXPECT_NEAR(*r.value("baseline_sigma_pf"), 0.004, 0.002);  // the simulator's white noise
    ASSERT_TRUE(r.value("hysteresis_fraction"));
    EXPECT_LT(*r.value("hysteresis_fraction"), 0.02);
    EXPECT_GT(*r.value("r_squared"), 0.999);
    // 3σ/S: about 0.012 pF / 1.8 pF/mN ≈ 7 µN, and through k a few µm.
    EXPECT_NEAR(*r.value("detection_limit_mn"), 3 * *r.value("baseline_sigma_pf") / *r.value("sensitivity_pf_per_mn"),
                1e-9);
    ASSERT_TRUE(r.value("detection_limit_mm"));
    EXPECT_NE(*r.value("drift_pf_per_s"), 0.0);  // the final baseline was used
}

TEST_F(CapacitiveWizardTest, AMiscountedStepIsRefusedAndCancelStoresNothing)
{
    ui::CapacitiveWizard wizard(m_context);
    ASSERT_NO_FATAL_FAILURE(toSteps(wizard));
    for (double mgf : {30.0, 60.0}) ASSERT_NO_FATAL_FAILURE(capture(wizard, mgf));
    ASSERT_NO_FATAL_FAILURE(capture(wizard, 90.0, 150.0));  // "90 mgf" with 150 on the beam
    for (double mgf : {120.0, 150.0}) ASSERT_NO_FATAL_FAILURE(capture(wizard, mgf));
    press(wizard, Qt::Key_N);
    ASSERT_EQ(wizard.currentId(), ui::CapacitiveWizard::ResultPage);
    EXPECT_FALSE(pageComplete(wizard));
    const QString problems = child<QLabel>(wizard, "problemsText")->text();
    EXPECT_TRUE(problems.contains(QStringLiteral("Step 3 (90 mgf, loading)"))) << problems.toStdString();
    QTest::keyClick(&wizard, Qt::Key_Escape);
    EXPECT_FALSE(wizard.isVisible());
    EXPECT_FALSE(QFileInfo::exists(m_context.storePath));
}
