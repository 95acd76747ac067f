// Recording from the main window against the live simulator: the session
// bar starts and stops a session, Ctrl+M drops a marker and Ctrl+Shift+M one
// with a note (timed at the key press), and the store then holds a complete
// session with the bar's metadata, the samples streamed while recording, and
// the markers; a note finished after the recording stopped still reaches
// its session. A store that cannot be opened is shown without stopping the
// live view; sessions a crash cut short are reported once.
#include "core/SampleBlock.h"
#include "core/Version.h"
#include "core/storage/SessionStore.h"
#include "support/DamagedStore.h"
#include "support/MainWindowHelpers.h"
#include "support/ReadyToRecord.h"
#include "support/Screenshot.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/live/LiveMarkers.h"
#include "ui/live/LiveStation.h"
#include "ui/live/RecordingPolicy.h"
#include "ui/plot/LivePlotWidget.h"

#include <QComboBox>
#include <QFile>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::testing::child;
using tactiscope::testing::liveSimulator;
using tactiscope::testing::runEventLoopFor;
using tactiscope::testing::waitFor;

TEST(Recording, TheSessionBarRecordsASessionWithItsMetadataAndAMarker)
{
    QTemporaryDir dir;
    const QString store = dir.filePath("line3.tactiscope");
    ui::MainWindow window;
    window.setStorePath(store);
    window.show();
    auto* record = child<QPushButton>(window, "recordButton");
    EXPECT_FALSE(record->isEnabled());  // nothing to record yet
    window.station().connectSource(liveSimulator());
    ASSERT_TRUE(record->isEnabled());

    child<QComboBox>(window, "modeBox")->setCurrentIndex(0);
    QTest::keyClicks(child<QLineEdit>(window, "subjectEdit"), QStringLiteral("door-17"));
    QTest::keyClicks(child<QLineEdit>(window, "operatorEdit"), QStringLiteral("Ada"));
    QTest::mouseClick(record, Qt::LeftButton);
    ASSERT_TRUE(window.isRecording());
    EXPECT_TRUE(child<QLineEdit>(window, "subjectEdit")->isReadOnly());  // metadata is fixed while recording
    ASSERT_TRUE(waitFor([&] { return child<QLabel>(window, "recordingLabel")->text().contains("REC"); }, 3000));
    runEventLoopFor(1200);
    QTest::keyClick(&window, Qt::Key_M, Qt::ControlModifier);
    runEventLoopFor(300);
    QTest::keyClick(&window, Qt::Key_M, Qt::ControlModifier | Qt::ShiftModifier);
    auto* note = window.findChild<QInputDialog*>(QStringLiteral("markerNoteDialog"));
    ASSERT_NE(note, nullptr);
    EXPECT_FALSE(window.isHidden());
    runEventLoopFor(500);  // the operator types; the marker keeps the key press's time
    note->setTextValue(QStringLiteral("scratch near the edge"));
    note->accept();
    window.activateWindow();  // the keyboard goes back to the main window
    ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
    runEventLoopFor(300);
    EXPECT_TRUE(child<QLabel>(window, "elapsedLabel")->text().startsWith(QStringLiteral("00:00:0")));
    tactiscope::testing::saveScreenshot(window, QStringLiteral("recording"));
    QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier);  // stop
    ASSERT_FALSE(window.isRecording());
    EXPECT_TRUE(window.station().isConnected());  // the live view goes on
    EXPECT_TRUE(child<QLabel>(window, "recordingLabel")->text().startsWith(QStringLiteral("Session 1 saved")));

    core::storage::SessionStore sessions(store.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto list = sessions.sessions();
    ASSERT_EQ(list.size(), 1u);
    const auto& s = list.front();
    EXPECT_EQ(s.status, tactiscope::core::SessionStatus::Complete);
    EXPECT_EQ(s.metadata.mode, tactiscope::core::Mode::PanelScan);
    EXPECT_EQ(s.metadata.subject, "door-17");
    EXPECT_EQ(s.metadata.operatorName, "Ada");
    // The simulator's identity, as a device's INFO would give it.
    EXPECT_EQ(s.metadata.deviceModel, "Tactiscope simulator");
    EXPECT_EQ(s.metadata.deviceSerial, "panel scan");
    EXPECT_EQ(s.metadata.deviceFirmware, tactiscope::core::versionString());
    EXPECT_EQ(s.sampleRate_hz, 500.0);
    // About two seconds of the 500 Hz simulator, with nothing lost.
    EXPECT_GT(s.sampleCount, 700u);
    EXPECT_LT(s.sampleCount, 3000u);
    EXPECT_TRUE(sessions.gaps(s.id).empty());
    std::vector<core::storage::SessionEvent> markers;  // the detector's defects are there too
    for (const auto& e : sessions.events(s.id))
        if (e.kind == tactiscope::core::EventKind::Marker) markers.push_back(e);
    ASSERT_EQ(markers.size(), 2u);
    EXPECT_GT(markers[0].start_s, 0.9);
    EXPECT_TRUE(markers[0].note.empty());
    EXPECT_EQ(markers[1].note, "scratch near the edge");
    // 0.3 s after the first, not 0.8 s (when the note was accepted).
    EXPECT_NEAR(markers[1].start_s - markers[0].start_s, 0.3, 0.15);
    EXPECT_LT(markers[1].start_s, static_cast<double>(s.sampleCount) / 500.0);
}

TEST(Recording, AStoreThatCannotBeOpenedIsShownAndTheLiveViewGoesOn)
{
    QTemporaryDir dir;
    const QString notAStore = dir.filePath("notes.txt");
    QFile file(notAStore);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("my notes, not a store\n");
    file.close();
    ui::MainWindow window;
    window.setStorePath(notAStore);
    window.station().connectSource(liveSimulator());
    window.show();
    EXPECT_FALSE(window.startRecording());
    EXPECT_FALSE(window.isRecording());
    QMessageBox* box = nullptr;
    ASSERT_TRUE(waitFor([&] { return (box = window.findChild<QMessageBox*>(QStringLiteral("problemBox"))); }, 2000));
    EXPECT_FALSE(box->isModal());
    EXPECT_TRUE(box->informativeText().contains(QStringLiteral("not a Tactiscope session store")))
        << box->informativeText().toStdString();
    const auto drawn = window.livePlot()->drawnPointCount(0);
    EXPECT_TRUE(waitFor([&] { return window.livePlot()->drawnPointCount(0) != drawn; }, 2000));
}

TEST(Recording, ANoteFinishedAfterTheRecordingStoppedIsKeptInItsSession)
{
    QTemporaryDir dir;
    const QString store = dir.filePath("s.tactiscope");
    ui::MainWindow window;
    window.setStorePath(store);
    window.show();
    window.station().connectSource(liveSimulator("palpation"));
    ASSERT_TRUE(window.startRecording());
    runEventLoopFor(800);
    window.markers().markWithNote();
    auto* note = window.findChild<QInputDialog*>(QStringLiteral("markerNoteDialog"));
    ASSERT_NE(note, nullptr);
    runEventLoopFor(300);
    window.stopRecording();  // while the operator is still typing
    note->setTextValue(QStringLiteral("bruise at the edge"));
    note->accept();

    core::storage::SessionStore sessions(store.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto id = sessions.sessions().front().id;
    ASSERT_TRUE(waitFor([&] { return !sessions.annotations(id).empty(); }, 5000));
    const auto annotations = sessions.annotations(id);
    ASSERT_EQ(annotations.size(), 1u);
    EXPECT_EQ(annotations[0].text, "bruise at the edge");
    EXPECT_GT(annotations[0].time_s, 0.6);  // the key press, not the accept
    EXPECT_LT(annotations[0].time_s, 1.0);
}

namespace {

// The window started on `store`: the box named `name` its check of the
// store shows, or nullptr when none comes within 10 s.
QMessageBox* boxOnStart(ui::MainWindow& window, const QString& store, const QString& name)
{
    window.setStorePath(store);
    window.show();
    window.checkStore();
    QMessageBox* box = nullptr;
    waitFor([&] { return (box = window.findChild<QMessageBox*>(name)); }, 10000);
    return box;
}

}  // namespace

TEST(Recording, SessionsACrashCutShortAreReportedOnce)
{
    QTemporaryDir dir;
    const QString store = dir.filePath("crashed.tactiscope");
    {
        // A recording that never ended: what a crash leaves behind.
        core::storage::SessionStore sessions(store.toStdString());
        core::storage::SessionMetadata metadata;
        metadata.mode = tactiscope::core::Mode::Palpation;
        metadata.subject = "phantom-4";
        const std::vector<core::ChannelDescriptor> channels{{"a", "", core::ChannelKind::Strain}};
        const auto id = sessions.beginSession(metadata, channels, 100.0);
        core::SampleBlock block(1, 250, 0.0, 0.01, 0);
        sessions.appendBlocks(id, std::span(&block, 1));
    }
    ui::MainWindow window;
    QMessageBox* box = boxOnStart(window, store, QStringLiteral("interruptedBox"));
    ASSERT_NE(box, nullptr);
    EXPECT_FALSE(box->isModal());
    EXPECT_TRUE(box->informativeText().contains(QStringLiteral("Session 1 (palpation, phantom-4)")))
        << box->informativeText().toStdString();
    EXPECT_TRUE(box->informativeText().contains(QStringLiteral("2.5 s kept")));
    tactiscope::testing::saveScreenshot(*box, QStringLiteral("interrupted-sessions"));
    box->close();
    runEventLoopFor(50);

    core::storage::SessionStore sessions(store.toStdString(), core::storage::Database::Access::ReadOnly);
    EXPECT_EQ(sessions.sessions().front().status, tactiscope::core::SessionStatus::Interrupted);
    window.checkStore();   // already reported
    runEventLoopFor(500);  // the worker's answer
    EXPECT_EQ(window.findChild<QMessageBox*>(QStringLiteral("interruptedBox")), nullptr);
}

TEST(Recording, ADamagedStoreIsShownAtStartNotAtRecord)
{
    // Before, the window started on it with no notice, and recording into
    // it went ahead silently.
    QTemporaryDir dir;
    const QString store = dir.filePath("damaged.tactiscope");
    {
        core::storage::SessionStore sessions(store.toStdString());
        const std::vector<core::ChannelDescriptor> channels{{"a", "", core::ChannelKind::Strain}};
        const auto id = sessions.beginSession({}, channels, 1000.0);
        core::SampleBlock block(1, 200'000, 0.0, 0.001, 0);
        for (std::size_t i = 0; i < 200'000; ++i) block.channel(0)[i] = static_cast<double>(i % 977);
        sessions.appendBlocks(id, std::span(&block, 1));
        sessions.endSession(id, tactiscope::core::SessionStatus::Complete);
    }
    ASSERT_TRUE(tactiscope::testing::scribbleOverTheMiddle(store.toStdString()));
    ui::MainWindow window;
    QMessageBox* box = boxOnStart(window, store, QStringLiteral("storeProblemBox"));
    ASSERT_NE(box, nullptr);
    EXPECT_FALSE(box->isModal());
    EXPECT_TRUE(box->informativeText().contains(QStringLiteral("is damaged"))) << box->informativeText().toStdString();
    tactiscope::testing::saveScreenshot(*box, QStringLiteral("damaged-store"));
}

TEST(Recording, QuittingWhileRecordingAsksFirstAndStoppingGoesThroughTheVerdict)
{
    // Before, Ctrl+Q stopped the recording and quit, storing a verdict
    // nobody confirmed.
    QTemporaryDir dir;
    ui::MainWindow window;
    tactiscope::testing::readyToRecord(window, dir.filePath("s.tactiscope"));
    ASSERT_TRUE(window.startRecording());
    // Longer than the 0.6 s the panel scan's verdict needs: a shorter
    // recording is "too short to judge" and asks no verdict.
    runEventLoopFor(1500);

    EXPECT_FALSE(window.close());  // refused: it asks
    EXPECT_TRUE(window.isRecording());
    auto* box = window.findChild<QMessageBox*>(QStringLiteral("quitWhileRecordingBox"));
    ASSERT_NE(box, nullptr);
    EXPECT_TRUE(box->informativeText().contains(QStringLiteral("asks for its verdict")));
    QTest::mouseClick(child<QPushButton>(*box, "keepRecordingButton"), Qt::LeftButton);
    runEventLoopFor(100);
    EXPECT_TRUE(window.isRecording());
    EXPECT_TRUE(window.isVisible());

    EXPECT_FALSE(window.close());
    box = window.findChild<QMessageBox*>(QStringLiteral("quitWhileRecordingBox"));
    ASSERT_NE(box, nullptr);
    QTest::mouseClick(child<QPushButton>(*box, "stopForQuitButton"), Qt::LeftButton);
    runEventLoopFor(100);
    EXPECT_FALSE(window.isRecording());
    EXPECT_TRUE(window.isVisible()) << "the verdict step is the operator's, in the open window";
    auto* verdict = window.findChild<QDialog*>(QStringLiteral("verdictBox"));
    ASSERT_NE(verdict, nullptr);
    // Issue 52: once the verdict is answered, the window quits as asked.
    QTest::mouseClick(child<QPushButton>(*verdict, "keepButton"), Qt::LeftButton);
    EXPECT_TRUE(waitFor([&] { return !window.isVisible(); }, 2000));
}

// A palpation has no verdict: the question does not promise one (issue 37).
TEST(Recording, QuittingWhileRecordingAPalpationPromisesNoVerdict)
{
    QTemporaryDir dir;
    ui::MainWindow window;
    window.setStorePath(dir.filePath("s.tactiscope"));
    window.setMode(core::Mode::Palpation);
    window.station().connectSource(liveSimulator("palpation"));
    window.show();
    QTest::keyClicks(child<QLineEdit>(window, "operatorEdit"), QStringLiteral("Ada"));
    ASSERT_TRUE(window.startRecording());
    runEventLoopFor(300);
    EXPECT_FALSE(window.close());
    auto* box = window.findChild<QMessageBox*>(QStringLiteral("quitWhileRecordingBox"));
    ASSERT_NE(box, nullptr);
    EXPECT_FALSE(box->informativeText().contains(QStringLiteral("verdict"))) << box->informativeText().toStdString();
    QTest::mouseClick(child<QPushButton>(*box, "stopForQuitButton"), Qt::LeftButton);
    runEventLoopFor(100);
    EXPECT_FALSE(window.isRecording());
    EXPECT_EQ(window.findChild<QDialog*>(QStringLiteral("verdictBox")), nullptr);
    EXPECT_FALSE(window.isVisible()) << "Stop recording in the quit question quits";
}

TEST(Recording, AFileThatIsNotAStoreIsRefusedWhenChosen)
{
    QTemporaryDir dir;
    const QString good = dir.filePath("good.tactiscope");
    const QString csv = dir.filePath("scan.csv");
    QFile file(csv);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("t,a,b\n0,1e-6,2e-6\n");
    file.close();
    ui::MainWindow window;
    window.setStorePath(good);
    window.show();
    EXPECT_FALSE(window.useStore(csv));
    auto* refused = window.findChild<QMessageBox*>(QStringLiteral("storeRefusedBox"));
    ASSERT_NE(refused, nullptr);
    EXPECT_TRUE(refused->text().contains("scan.csv")) << refused->text().toStdString();
    const auto* store = child<QLabel>(window, "storeLabel");
    EXPECT_TRUE(store->text().contains("good.tactiscope") || store->toolTip().contains("good.tactiscope"))
        << "the store stays what it was";
    EXPECT_TRUE(window.useStore(dir.filePath("new.tactiscope")));  // not there yet: the first recording makes it
}

TEST(Recording, AStationThatRequiresASubjectAndAnOperatorRecordsOnlyWithBoth)
{
    ui::setRequireSubjectAndOperator(true);
    QTemporaryDir dir;
    ui::MainWindow window;
    window.setStorePath(dir.filePath("s.tactiscope"));
    window.station().connectSource(liveSimulator());
    window.show();
    child<QLineEdit>(window, "subjectEdit")->clear();
    child<QLineEdit>(window, "operatorEdit")->clear();
    QTest::keyClicks(child<QLineEdit>(window, "operatorEdit"), QStringLiteral("Ada"));
    EXPECT_FALSE(window.startRecording());
    auto* refused = window.findChild<QMessageBox*>(QStringLiteral("recordRefusedBox"));
    ASSERT_NE(refused, nullptr);
    EXPECT_TRUE(refused->informativeText().contains("type the subject (panel or phantom id)"))
        << refused->informativeText().toStdString();
    EXPECT_FALSE(refused->informativeText().contains("operator's name")) << "the operator was given";
    QTest::keyClicks(child<QLineEdit>(window, "subjectEdit"), QStringLiteral("door-17"));
    EXPECT_TRUE(window.startRecording());
    window.stopRecording();
    ui::setRequireSubjectAndOperator(false);  // the process's other tests record without
}

TEST(Recording, AStoreChosenWhileConnectedIsWhereTheNextRecordingGoes)
{
    QTemporaryDir dir;
    const QString first = dir.filePath("first.tactiscope");
    const QString second = dir.filePath("second.tactiscope");
    ui::MainWindow window;
    window.setStorePath(first);
    window.station().connectSource(liveSimulator());
    window.show();
    QTest::keyClicks(child<QLineEdit>(window, "operatorEdit"), QStringLiteral("Ada"));
    ASSERT_TRUE(window.useStore(second));
    ASSERT_TRUE(window.startRecording());
    runEventLoopFor(300);
    window.stopRecording();
    EXPECT_FALSE(QFile::exists(first)) << "the recording went to the store chosen before";
    ASSERT_TRUE(QFile::exists(second));
    core::storage::SessionStore sessions(second.toStdString(), core::storage::Database::Access::ReadOnly);
    EXPECT_EQ(sessions.sessions().size(), 1u);
}
