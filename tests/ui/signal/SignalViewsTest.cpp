// The signal work in the GUI (issue 57), on the real main window with the
// simulator's panel scan under 20 µε of common and 5 µε of differential
// 50 Hz hum: Session ▸ Filters and math channels… finds the mains, sets a
// notch on both gauges and a math channel, refuses a unit mismatch in
// words, and the window plots what they give with each filter's delay; the
// live spectrum shows the hum's line where the simulator put it, and the
// signal health panel its amplitude in µε (and none through the notch); the
// recording keeps the setup, and the review's spectrum of its math channel
// reads it again from the store. A capacitive beam's creep reads live too.
#include "core/storage/SessionStore.h"
#include "devices/session/LiveSession.h"
#include "devices/simulator/CapacitiveWeightsScenario.h"
#include "devices/simulator/MainsHumOverlay.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"
#include "support/MainWindowHelpers.h"
#include "support/Screenshot.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/live/LiveStation.h"
#include "ui/plot/LivePlotWidget.h"
#include "ui/review/ReviewPlot.h"
#include "ui/review/ReviewWindow.h"
#include "ui/signal/ReviewFilterDialog.h"
#include "ui/signal/ReviewSpectrum.h"
#include "ui/signal/SignalDialog.h"
#include "ui/signal/SpectrumView.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <gtest/gtest.h>

#include <algorithm>

using namespace tactiscope;
using tactiscope::testing::child;
using tactiscope::testing::waitFor;

namespace {

std::unique_ptr<devices::BlockSource> hummedPanelScan()
{
    devices::simulator::MainsHumSettings hum;
    hum.common = 20e-6;
    hum.differential = 5e-6;
    return std::make_unique<devices::simulator::SimulatorSource>(
        std::make_unique<devices::simulator::HummedScenario>(devices::simulator::makeScenario("panel-scan"), hum));
}

QAction* action(const QWidget& window, const char* name)
{
    auto* found = window.findChild<QAction*>(QString::fromLatin1(name));
    EXPECT_NE(found, nullptr) << name;
    return found;
}

}  // namespace

TEST(SignalViews, FiltersAndAMathChannelAreSetFoundShownRecordedAndReviewed)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("line.tactiscope");
    ui::MainWindow window;
    window.setStorePath(db);
    window.resize(1366, 768);
    window.show();
    window.station().connectSource(hummedPanelScan());
    ASSERT_TRUE(waitFor([&] { return window.station().device() != nullptr; }, 5000));
    QTest::qWait(1500);  // a second and a half of hum to find

    action(window, "signalAction")->trigger();
    auto* dialog = window.findChild<ui::SignalDialog*>(QStringLiteral("signalDialog"));
    ASSERT_NE(dialog, nullptr);
    QTest::mouseClick(child<QPushButton>(*dialog, "signalFindMains"), Qt::LeftButton);
    EXPECT_TRUE(child<QLabel>(*dialog, "signalMainsFound")->text().startsWith(QStringLiteral("50 Hz hum")))
        << child<QLabel>(*dialog, "signalMainsFound")->text().toStdString();
    EXPECT_EQ(child<QComboBox>(*dialog, "signalMains")->currentData().toDouble(), 50.0);
    auto* filters = child<QTableWidget>(*dialog, "signalFilters");
    ASSERT_EQ(filters->rowCount(), 2);
    for (int row = 0; row < 2; ++row) qobject_cast<QCheckBox*>(filters->cellWidget(row, 1))->setChecked(true);
    EXPECT_TRUE(filters->item(0, 6)->text().endsWith(QStringLiteral(" ms")))
        << filters->item(0, 6)->text().toStdString();

    // A sum of a strain and a force is refused, in the dialog, and nothing changes.
    auto* math = child<QPlainTextEdit>(*dialog, "signalMath");
    math->setPlainText(QStringLiteral("x[mN]=a + 1"));
    QTest::mouseClick(child<QPushButton>(*dialog, "signalApply"), Qt::LeftButton);
    EXPECT_FALSE(child<QLabel>(*dialog, "signalProblem")->text().isEmpty());
    EXPECT_TRUE(window.station().device()->signalSetup().empty());

    // A notch at 60 Hz on 50 Hz hum is applied, and said to leave the hum whole.
    math->clear();
    child<QComboBox>(*dialog, "signalMains")->setCurrentIndex(1);
    QTest::mouseClick(child<QPushButton>(*dialog, "signalApply"), Qt::LeftButton);
    EXPECT_TRUE(
        child<QLabel>(*dialog, "signalProblem")->text().contains(QStringLiteral("the signal's hum is at 50 Hz")))
        << child<QLabel>(*dialog, "signalProblem")->text().toStdString();
    EXPECT_EQ(window.station().device()->signalSetup().filters.front().settings.notch_hz, 60.0);
    child<QComboBox>(*dialog, "signalMains")->setCurrentIndex(0);

    math->setPlainText(QStringLiteral("diff[µε]=a - b"));
    child<QCheckBox>(*dialog, "signalAnalyseFiltered")->setChecked(true);
    tactiscope::testing::saveScreenshot(*dialog, QStringLiteral("signal-dialog"));
    QTest::mouseClick(child<QPushButton>(*dialog, "signalApply"), Qt::LeftButton);
    EXPECT_TRUE(child<QLabel>(*dialog, "signalProblem")->text().isEmpty())
        << child<QLabel>(*dialog, "signalProblem")->text().toStdString();
    const auto& setup = window.station().device()->signalSetup();
    ASSERT_EQ(setup.filters.size(), 2u);
    EXPECT_EQ(setup.filters[0].settings.notch_hz, 50.0);
    ASSERT_EQ(setup.math.size(), 1u);
    EXPECT_TRUE(setup.analysisFiltered);
    dialog->close();

    // The traces show the filtered channels, a line says what they are and
    // how late, and the plot under it the math channel; unticked, the
    // traces are as they came and the plot holds the filtered ones too.
    auto* line = child<QLabel>(window, "signalLine");
    EXPECT_TRUE(window.findChild<QWidget*>(QStringLiteral("signalPanel"))->isVisible());
    EXPECT_TRUE(line->text().startsWith(QStringLiteral("The traces show the filtered channels · a.filtered: mains "
                                                       "notch 50 Hz and harmonics, delay ")))
        << line->text().toStdString();
    EXPECT_TRUE(line->text().contains(QStringLiteral("diff[µε]=a - b")));
    auto* plot = child<ui::LivePlotWidget>(window, "signalPlot");
    ASSERT_TRUE(waitFor([&] { return plot->samplesReceived() > 500; }, 5000));
    EXPECT_EQ(plot->laneCount(), 1u);  // diff, in its µε
    action(window, "filteredTracesAction")->trigger();
    EXPECT_FALSE(line->text().startsWith(QStringLiteral("The traces show"))) << line->text().toStdString();
    ASSERT_TRUE(waitFor([&] { return plot->laneCount() == 2u; }, 5000));  // a.filtered, b.filtered; diff
    action(window, "filteredTracesAction")->trigger();
    auto* traces = child<ui::LivePlotWidget>(window, "tracesPlot");
    ASSERT_TRUE(waitFor([&] { return traces->samplesReceived() > 100 && plot->samplesReceived() > 100; }, 5000));

    // The live spectrum of a (as it came) shows the hum's line at 50 Hz,
    // at its amplitude: 20 + 5 µε on a.
    auto* spectrumDock = window.findChild<QDockWidget*>(QStringLiteral("spectrumDock"));
    ASSERT_NE(spectrumDock, nullptr);
    spectrumDock->toggleViewAction()->trigger();  // View ▸ Spectrum
    ASSERT_TRUE(waitFor([&] { return spectrumDock->isVisible(); }, 2000));
    auto* spectrum = spectrumDock->findChild<ui::SpectrumView*>();
    ASSERT_NE(spectrum, nullptr);
    ASSERT_TRUE(waitFor([&] { return spectrum->spectrum().averages >= 2; }, 8000));
    ASSERT_FALSE(spectrum->spectrum().peaks.empty());
    const auto& strongest = spectrum->spectrum().peaks.front();
    EXPECT_NEAR(strongest.frequency_hz, 50.0, 1.0);
    EXPECT_NEAR(strongest.amplitude, 25e-6, 2.5e-6);
    EXPECT_TRUE(spectrum->peaksText().contains(QStringLiteral("µε"))) << spectrum->peaksText().toStdString();
    QTest::qWait(1500);  // a second and a half of traces to look at
    tactiscope::testing::saveScreenshot(window, QStringLiteral("signal-live"));

    // View ▸ Signal health reads the same hum on a, in µε.
    auto* healthDock = window.findChild<QDockWidget*>(QStringLiteral("healthDock"));
    ASSERT_NE(healthDock, nullptr);
    healthDock->toggleViewAction()->trigger();
    ASSERT_TRUE(waitFor([&] { return healthDock->isVisible(); }, 2000));
    auto* health = healthDock->findChild<QTableWidget*>(QStringLiteral("healthTable"));
    ASSERT_NE(health, nullptr);
    ASSERT_TRUE(waitFor(
        [&] { return health->rowCount() > 0 && health->item(0, 1)->text().contains(QStringLiteral("at 50 Hz")); },
        8000));
    // A drift read over seconds would be the noise's: it waits for half a minute.
    EXPECT_EQ(health->item(0, 4)->text(), QStringLiteral("from 30 s on"));
    EXPECT_EQ(health->item(0, 0)->text(), QStringLiteral("a"));
    const QString hum = health->item(0, 1)->text();
    EXPECT_TRUE(hum.contains(QStringLiteral("µε at 50 Hz"))) << hum.toStdString();
    EXPECT_NEAR(QLocale().toDouble(hum.section(QLatin1Char(' '), 0, 0)), 25.0, 1.25) << hum.toStdString();
    for (const char* name : {"a.filtered", "diff"})
        EXPECT_FALSE(health->findItems(QString::fromLatin1(name), Qt::MatchExactly).isEmpty()) << name;
    // The notch leaves no hum on a.filtered.
    const int filteredRow = health->findItems(QStringLiteral("a.filtered"), Qt::MatchExactly).front()->row();
    EXPECT_EQ(health->item(filteredRow, 1)->text(), QStringLiteral("none"));
    tactiscope::testing::saveScreenshot(window, QStringLiteral("signal-health-live"));
    auto* since = healthDock->findChild<QLabel*>(QStringLiteral("healthSince"));
    ASSERT_NE(since, nullptr);
    EXPECT_TRUE(since->text().contains(QStringLiteral("since the panel opened"))) << since->text().toStdString();

    // Recorded, the session keeps the setup; its review's spectrum of the
    // math channel, computed again from the store, has no 50 Hz line left.
    ASSERT_FALSE(window.station().startRecording({}));
    EXPECT_TRUE(since->text().contains(QStringLiteral("since the recording began"))) << since->text().toStdString();
    QTest::qWait(2500);
    window.station().stopRecording();
    ASSERT_TRUE(waitFor([&] { return !window.station().isRecording(); }, 5000));
    {
        core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
        const auto id = store.lastSession();
        ASSERT_TRUE(id);
        EXPECT_FALSE(store.session(*id)->metadata.signalSetup.empty());
    }
    QString error;
    std::unique_ptr<ui::ReviewWindow> review(ui::ReviewWindow::open(db, 1, nullptr, error));
    ASSERT_TRUE(review) << error.toStdString();
    review->show();
    // Its plot shows them as lanes after the mode's, computed again from the store.
    const auto lanes = review->findChild<ui::ReviewPlot*>()->laneNames();
    for (const char* name : {"a.filtered", "b.filtered", "diff"})
        EXPECT_NE(std::ranges::find(lanes, std::string(name)), lanes.end()) << name;
    review->resize(1366, 768);
    QTest::qWait(500);  // drawn
    if (auto* scroll = review->findChild<QScrollArea*>(QStringLiteral("laneScroll")))
        scroll->verticalScrollBar()->setValue(scroll->verticalScrollBar()->maximum());  // the signal lanes, last
    QTest::qWait(300);
    tactiscope::testing::saveScreenshot(*review, QStringLiteral("review-signal-lanes"));
    action(*review, "reviewSpectrumAction")->trigger();
    auto* reviewed = review->findChild<ui::ReviewSpectrum*>(QStringLiteral("reviewSpectrum"));
    ASSERT_NE(reviewed, nullptr);
    auto* channel = reviewed->findChild<QComboBox*>(QStringLiteral("spectrumChannel"));
    channel->setCurrentIndex(channel->findText(QStringLiteral("diff")));
    const auto& diff = reviewed->view()->spectrum();
    ASSERT_GT(diff.averages, 0u);
    for (const auto& peak : diff.peaks)
        EXPECT_FALSE(std::abs(peak.frequency_hz - 50.0) < 1.0 && peak.amplitude > 1.0)  // µε, the unit diff is in
            << peak.frequency_hz << " Hz, " << peak.amplitude;
    tactiscope::testing::saveScreenshot(*reviewed, QStringLiteral("spectrum-review"));
    reviewed->close();

    // Signal ▸ Filter a channel in review…: a zero-phase 5 Hz low-pass on a
    // is a lane of its own, named after it, said in the header; removed again.
    bool filled = false;
    QTimer::singleShot(0, review.get(), [&] {
        auto* filterDialog = review->findChild<ui::ReviewFilterDialog*>(QStringLiteral("reviewFilterDialog"));
        ASSERT_NE(filterDialog, nullptr);
        auto* add = filterDialog->findChild<QPushButton*>(QStringLiteral("reviewFilterAdd"));
        EXPECT_FALSE(add->isEnabled());  // nothing chosen yet
        auto* filterChannel = filterDialog->findChild<QComboBox*>(QStringLiteral("reviewFilterChannel"));
        filterChannel->setCurrentIndex(filterChannel->findText(QStringLiteral("a")));
        filterDialog->findChild<QDoubleSpinBox*>(QStringLiteral("reviewFilterLowpass"))->setValue(300.0);
        EXPECT_FALSE(add->isEnabled());  // above 500 Hz's Nyquist: refused in words
        EXPECT_TRUE(filterDialog->findChild<QLabel*>(QStringLiteral("reviewFilterSaid"))->text().contains("Hz"));
        filterDialog->findChild<QDoubleSpinBox*>(QStringLiteral("reviewFilterLowpass"))->setValue(5.0);
        EXPECT_TRUE(add->isEnabled());
        tactiscope::testing::saveScreenshot(*filterDialog, QStringLiteral("review-filter-dialog"));
        filled = true;
        add->click();
    });
    action(*review, "reviewFilterAction")->trigger();
    ASSERT_TRUE(filled);
    const auto filtered = review->findChild<ui::ReviewPlot*>()->laneNames();
    EXPECT_NE(std::ranges::find(filtered, std::string("a.review")), filtered.end());
    auto* header = review->findChild<QLabel*>(QStringLiteral("sessionHeader"));
    ASSERT_NE(header, nullptr);
    EXPECT_TRUE(header->text().contains(QStringLiteral("in review a.review: low-pass 5 Hz")))
        << header->text().toStdString();
    QTest::qWait(300);
    if (auto* scroll = review->findChild<QScrollArea*>(QStringLiteral("laneScroll")))
        scroll->verticalScrollBar()->setValue(scroll->verticalScrollBar()->maximum());
    QTest::qWait(300);
    tactiscope::testing::saveScreenshot(*review, QStringLiteral("review-filter-lane"));
    action(*review, "reviewFiltersClearAction")->trigger();
    const auto cleared = review->findChild<ui::ReviewPlot*>()->laneNames();
    EXPECT_EQ(std::ranges::find(cleared, std::string("a.review")), cleared.end());
}

TEST(SignalViews, TheLiveHealthReadsABeamsCreepAfterItsLoadSteps)
{
    // A quick beam (100 Hz, settling in 80 ms, creeping 5 % further with a
    // 0.8 s time constant), two weights placed and taken off, run four
    // times faster than life (its live buffer's two seconds still half a
    // second of the test's): the panel's creep line reads the simulator's
    // time constant within its ±.
    devices::simulator::CapacitiveWeightsParameters p;
    p.sampleRate_hz = 100.0;
    p.protocol = devices::simulator::WeightProtocol::Individual;
    p.weights_mgf = {100, 150};
    p.baseline_s = 2.0;
    p.dwell_s = 4.0;
    p.settleTime_s = 0.08;
    p.creepTime_s = 0.8;
    p.creepFraction = 0.05;
    ui::MainWindow window;
    QTemporaryDir dir;
    window.setStorePath(dir.filePath("beam.tactiscope"));
    window.resize(1366, 768);
    window.show();
    auto* healthDock = window.findChild<QDockWidget*>(QStringLiteral("healthDock"));
    ASSERT_NE(healthDock, nullptr);
    healthDock->toggleViewAction()->trigger();
    devices::simulator::SimulatorOptions fast;
    fast.speed = 4.0;
    window.station().connectSource(std::make_unique<devices::simulator::SimulatorSource>(
        std::make_unique<devices::simulator::CapacitiveWeightsScenario>(p), fast));
    ASSERT_TRUE(waitFor([&] { return window.station().device() != nullptr; }, 5000));
    auto* creep = healthDock->findChild<QLabel*>(QStringLiteral("healthCreep"));
    ASSERT_NE(creep, nullptr);
    const QRegularExpression read(QStringLiteral("time constant ([0-9.]+) ± ([0-9.]+) s \\((\\d+) steps"));
    QRegularExpressionMatch found;
    ASSERT_TRUE(waitFor(
        [&] {
            found = read.match(creep->text());
            return found.hasMatch() && found.captured(3).toInt() == 4;  // each weight on, and off
        },
        20000))
        << creep->text().toStdString() << " | "
        << healthDock->findChild<QLabel*>(QStringLiteral("healthSince"))->text().toStdString();
    EXPECT_TRUE(creep->text().startsWith(QStringLiteral("Creep after a load step (capacitance): ")))
        << creep->text().toStdString();
    EXPECT_NEAR(QLocale().toDouble(found.captured(1)), p.creepTime_s, 3.0 * QLocale().toDouble(found.captured(2)));
    tactiscope::testing::saveScreenshot(window, QStringLiteral("signal-health-beam"));
}
