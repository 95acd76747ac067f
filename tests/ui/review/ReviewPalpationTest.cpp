// The review window of a palpation recorded from the emulator opens on
// the physical quantities (F_H, F_L, Q, k_o, then the displacement), the
// beams' counts are one click away and back, and zoomed on a press the
// forces are what the derived channels give for those samples; its presses
// are listed with site, k_o ± u and depth, and summed up per site. A
// capacitive session opens on its capacitance, ΔC, force and deflection,
// beside the calibration its readings went through.
#include "ui/review/ReviewWindow.h"

#include "core/capacitive/CapacitiveReadout.h"
#include "core/derived/PalpationChannels.h"
#include "core/sensors/BuiltInProfiles.h"
#include "core/storage/SessionStore.h"
#include "ui/modes/palpation/PalpationReanalysisBox.h"
#include "ui/modes/palpation/PressesPanel.h"
#include "ui/review/ReviewPlot.h"

#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/Screenshot.h"
#include "support/WaitFor.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QLocale>
#include <QTemporaryDir>
#include <QTreeWidget>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace tactiscope;

TEST(ReviewPalpation, OpensOnTheForcesAndTheCountsAreOneClickAway)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("clinic.tactiscope");
    const auto recorded =
        tactiscope::testing::recordEmulated(dir.path(), db, "palpation", 7, {"--site", "B2", "--subject", "phantom-1"});
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();

    QString error;
    auto* window = ui::ReviewWindow::open(db, 1, nullptr, error);
    ASSERT_NE(window, nullptr) << error.toStdString();
    window->setAttribute(Qt::WA_DeleteOnClose, false);
    window->show();
    window->plot()->reload();
    EXPECT_EQ(window->plot()->laneNames(),
              (std::vector<std::string>{"force_high", "force_low", "Q", "stiffness", "displacement"}));

    // Zoomed on the first press: the exact forces of those samples.
    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto readings = store.readings(1);
    ASSERT_FALSE(readings.empty());
    window->plot()->setRange(readings[0].start_s, readings[0].start_s + 1.0);
    window->plot()->reload();
    const auto& shown = window->plot()->shown(0);
    ASSERT_TRUE(shown.exact);
    core::derived::PalpationChannels derived(store, 1);
    const auto want = derived.read(shown.firstIndex, shown.low.size())[0];
    ASSERT_EQ(want.size(), shown.low.size());
    int pressing = 0;
    for (std::size_t i = 0; i < want.size(); ++i) {
        EXPECT_DOUBLE_EQ(shown.low[i], want[i]) << i;
        pressing += want[i] > 0.05;  // newtons: the press is on screen
    }
    EXPECT_GT(pressing, 100);

    // The presses in the clinician's terms: each stored reading, at its
    // site, with its depth; the site summed up and on the grid map.
    ASSERT_NE(qobject_cast<ui::PressesPanel*>(window->account()), nullptr);
    QTreeWidget* presses = qobject_cast<ui::PressesPanel*>(window->account())->pressList();
    ASSERT_EQ(presses->topLevelItemCount(), static_cast<int>(readings.size()));
    double sum = 0.0;
    for (int i = 0; i < presses->topLevelItemCount(); ++i) {
        const auto* row = presses->topLevelItem(i);
        const auto& r = readings[static_cast<std::size_t>(i)];
        sum += r.value;
        EXPECT_EQ(row->text(1), "recorded");
        EXPECT_EQ(row->text(2), "B2");
        // The uncertainty to two significant digits (at most six decimals), the value to its place.
        ASSERT_TRUE(r.standardError);
        const int decimals = std::clamp(1 - static_cast<int>(std::floor(std::log10(*r.standardError))), 0, 6);
        EXPECT_EQ(row->text(3), QLocale().toString(r.value, 'f', decimals) + " ± " +
                                    QLocale().toString(*r.standardError, 'f', decimals));
        EXPECT_TRUE(row->text(4).contains(" – ")) << "a press has a depth range";
    }
    QTreeWidget* sites = qobject_cast<ui::PressesPanel*>(window->account())->siteList();
    ASSERT_EQ(sites->topLevelItemCount(), 1);
    EXPECT_EQ(sites->topLevelItem(0)->text(0), "B2");
    EXPECT_EQ(sites->topLevelItem(0)->text(1), QString::number(readings.size()));
    const double mean = sum / static_cast<double>(readings.size());
    EXPECT_NEAR(QLocale().toDouble(sites->topLevelItem(0)->text(2)), mean, 0.05);
    auto* grid = window->findChild<QLabel*>(QStringLiteral("siteGrid"));
    ASSERT_NE(grid, nullptr);
    EXPECT_TRUE(grid->text().contains(QStringLiteral("n = %1").arg(readings.size())));

    // Read again with the profile's nominal gauge factors — the ones this
    // session used — the re-analysis lists each press beside its recorded
    // twin, with the same k_o; saved, it is an analysis of its own.
    auto* again = qobject_cast<ui::PressesPanel*>(window->account())->reanalysis();
    again->gaugeFactorBox()->setCurrentIndex(
        again->gaugeFactorBox()->findData(static_cast<int>(ui::PalpationReanalysisBox::GaugeFactors::Nominal)));
    ASSERT_TRUE(again->run().isEmpty());
    ASSERT_EQ(presses->topLevelItemCount(), static_cast<int>(2 * readings.size()));
    for (int i = 0; i + 1 < presses->topLevelItemCount(); i += 2) {
        EXPECT_EQ(presses->topLevelItem(i)->text(1), "recorded");
        EXPECT_EQ(presses->topLevelItem(i + 1)->text(1), "re-analysis");
        EXPECT_EQ(presses->topLevelItem(i + 1)->text(3), presses->topLevelItem(i)->text(3));
    }
    tactiscope::testing::saveScreenshot(*window, QStringLiteral("review-palpation"));
    EXPECT_TRUE(again->saveAs(QStringLiteral("nominal")).isEmpty());
    EXPECT_FALSE(again->saveAs(QStringLiteral("nominal")).isEmpty()) << "a result is saved once";
    EXPECT_EQ(store.readings(1, "nominal").size(), readings.size());
    EXPECT_EQ(presses->topLevelItem(1)->text(1), "saved \"nominal\"");

    auto* raw = window->findChild<QAction*>(QStringLiteral("rawChannelsAction"));
    ASSERT_NE(raw, nullptr);
    raw->trigger();
    EXPECT_EQ(window->plot()->laneNames(), (std::vector<std::string>{"high", "low", "displacement"}));
    EXPECT_NEAR(window->plot()->from_s(), readings[0].start_s, 1e-6);  // the view stays where it was
    raw->trigger();
    EXPECT_EQ(window->plot()->laneNames().front(), "force_high");
    delete window;
}

TEST(ReviewCapacitive, OpensOnTheCapacitanceChangeForceAndDeflection)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("lab.tactiscope");
    const auto recorded =
        tactiscope::testing::recordEmulated(dir.path(), db, "capacitive-weights", 4, {"--subject", "beam-1"});
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();

    QString error;
    auto* window = ui::ReviewWindow::open(db, 1, nullptr, error);
    ASSERT_NE(window, nullptr) << error.toStdString();
    window->setAttribute(Qt::WA_DeleteOnClose, false);
    window->show();
    window->plot()->reload();
    EXPECT_EQ(window->plot()->laneNames(), (std::vector<std::string>{"capacitance", "delta_c", "force", "deflection"}));
    EXPECT_NE(window->plot()->derivedBasis().find("the beam model"), std::string::npos)
        << window->plot()->derivedBasis();  // no calibration in this store
    // The calibration used, beside the records: here the beam model, with
    // the baseline the session started on.
    QLabel* basis = window->findChild<QLabel*>(QStringLiteral("capacitiveBasisText"));
    ASSERT_NE(basis, nullptr);
    EXPECT_TRUE(basis->text().contains("the beam model")) << basis->text().toStdString();
    EXPECT_TRUE(basis->text().contains("pF at the start")) << basis->text().toStdString();

    // Read through a calibration stored after the recording: the force
    // scales by the sensitivities' ratio, sample for sample; the recording
    // keeps its own basis.
    const auto beam =
        std::get<core::sensors::CapacitiveBeamProfile>(*core::sensors::builtInProfile(core::Mode::Capacitive));
    const auto model = core::capacitive::CapacitiveSensitivity::fromModel(core::sensors::CapacitiveBeam(beam.geometry));
    core::calibration::CalibrationRecord record;
    record.kind = core::calibration::kCapacitiveKind;
    record.sensorName = beam.name;
    record.operatorName = "Grace";
    record.timestampUtc = "2026-11-24T08:00:00Z";
    record.values = {{"c0_pf", model.c0_f * 1e12}, {"sensitivity_pf_per_mn", 2.5}, {"baseline_sigma_pf", 0.004}};
    window->store().addCalibration(record);
    delete window;
    window = ui::ReviewWindow::open(db, 1, nullptr, error);
    ASSERT_NE(window, nullptr) << error.toStdString();
    window->setAttribute(Qt::WA_DeleteOnClose, false);
    window->show();
    window->plot()->setRange(0.0, 4.0);
    window->plot()->reload();
    ASSERT_TRUE(window->plot()->shown(2).exact);
    const auto before = window->plot()->shown(2).low;  // the force, through the beam model
    auto* choice = window->findChild<QComboBox*>(QStringLiteral("capacitiveCalibrationChoice"));
    ASSERT_NE(choice, nullptr);
    ASSERT_EQ(choice->count(), 2);
    choice->setCurrentIndex(1);
    window->plot()->reload();
    const auto after = window->plot()->shown(2).low;
    ASSERT_EQ(after.size(), before.size());
    const double ratio = model.perNewton_f / 2.5e-9;  // 2.5 pF/mN is 2.5e-9 F/N
    int compared = 0;
    for (std::size_t i = 0; i < after.size(); ++i) {
        if (std::isnan(before[i]) || before[i] == 0.0) continue;
        EXPECT_NEAR(after[i] / before[i], ratio, 1e-9 * ratio) << i;
        ++compared;
    }
    EXPECT_GT(compared, 10);
    basis = window->findChild<QLabel*>(QStringLiteral("capacitiveBasisText"));
    EXPECT_TRUE(basis->text().contains("2026-11-24T08:00:00Z by Grace")) << basis->text().toStdString();
    tactiscope::testing::saveScreenshot(*window, QStringLiteral("review-capacitive"));
    auto* raw = window->findChild<QAction*>(QStringLiteral("rawChannelsAction"));
    ASSERT_NE(raw, nullptr);
    raw->trigger();
    EXPECT_EQ(window->plot()->laneNames(), (std::vector<std::string>{"capacitance"}));
    delete window;
}
