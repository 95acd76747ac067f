// The review window of one stored session, the day after: what was
// inspected (subject, operator, date, device, status, verdict), the
// session's plot (ReviewPlot: the overview, zoom to single samples, cursor
// readout, markers), the list of its events, readings and notes (a click
// jumps there), the reviewer's notes (add, edit, delete with undo), replay
// at 1–10× real time, the mode's own account (a panel scan's re-analysis
// beside the recorded events, ReanalysisPanel; a palpation's presses,
// sites and presses read again, PressesPanel; a capacitive beam's
// calibration, and another to read it through), a reviewer's verdict (panel
// scans) joining the verdict's trail, and the exports: the PDF report,
// printing, the plot as PNG or SVG, CSV of the session or of the range shown.
// Notes and verdicts carry the reviewer's name, typed once in the toolbar
// and remembered.
#pragma once

#include "core/derived/SessionLanes.h"
#include "core/storage/SessionStore.h"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QTimer>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QLabel;
class QLineEdit;
class QSpinBox;
class QTreeWidget;
class QTreeWidgetItem;

namespace tactiscope::ui {

class ReviewAccount;
class ReviewPlot;

class ReviewWindow : public QMainWindow {
    Q_OBJECT

public:
    // Opens the session; on failure returns null and says why in `error`.
    static ReviewWindow* open(const QString& storePath, std::int64_t session, QWidget* parent, QString& error);
    ~ReviewWindow() override;

    std::int64_t sessionId() const { return m_session.id; }
    const QString& storePath() const { return m_storePath; }  // a file or a central store's connection string
    ReviewPlot* plot() const { return m_plot; }
    // The mode's account beside the list (ui/modes/ModeUi.h); null for a mode without one.
    ReviewAccount* account() const { return m_account; }
    QTreeWidget* recordList() const { return m_list; }
    core::storage::SessionSource& store() { return *m_store; }

    // Notes: at the pinned cursor (else the middle of the view), asked
    // for without blocking; edited and deleted from the list.
    void addNote();
    QString addNoteAt(double time_s, const QString& text);  // returns an error, or empty
    QString editNote(std::int64_t annotation, const QString& text);
    QString deleteNote(std::int64_t annotation);
    QString undoDelete();
    // A reviewer's verdict on a panel scan, added to its trail; returns an
    // error, or empty. askVerdict() shows the trail and asks, without blocking.
    QString decideVerdict(core::Verdict verdict, const QString& note);
    void askVerdict();
    // Jumps to a row of the list (a click does this).
    void jumpTo(QTreeWidgetItem* item);

    // The stored channels as they are (raw), or the mode's physical quantities.
    void setRawChannels(bool raw);
    // Changes the lane options (raw channels, the calibration read through)
    // and redraws the plot; returns an error, or empty.
    QString changeLanes(const std::function<void(core::derived::LaneOptions&)>& change);

    // Replay from the left of the view at `speed`× real time.
    void setReplaySpeed(int speed);
    void play();
    void pause();
    bool isPlaying() const { return m_replay.isActive(); }

    // Exports; each returns an error, or empty.
    QString exportReport(const QString& pdfPath);
    QString exportCsv(const QString& csvPath, bool visibleRangeOnly);
    QString savePlot(const QString& imagePath);

signals:
    // Its verdict or notes were changed here: a browser listing it reads again.
    void sessionChanged();

private:
    // Signal ▸ Filter a channel in review…: a lane of the filtered channel.
    void addReviewFilter();
    ReviewWindow(const QString& storePath, std::unique_ptr<core::storage::SessionSource> store,
                 core::storage::SessionSummary session, QWidget* parent);
    void createActions();
    void refreshRecords();
    void recordsChanged();  // this window changed them: shown, and said (sessionChanged)
    void advanceReplay();
    void askNoteText(const QString& title, const QString& text, std::function<QString(const QString&)> apply);
    void editSelectedNote();
    void deleteSelectedNote();
    void printReport();
    void exportWithDialog(const QString& title, const QString& filter, const QString& suffix,
                          const std::function<QString(const QString&)>& write);
    void showProblem(const QString& text);
    // The plot's read problems are shown, and hidden again once it reads.
    void watchPlot();
    void refreshHeader();
    bool rebuildPlot();  // with m_laneOptions, keeping the view; false (and said) when it cannot
    // The reviewer's name; empty (and the name box focused, with the
    // reason shown) when none was typed.
    QString author();

    QString m_storePath;
    std::unique_ptr<core::storage::SessionSource> m_store;
    core::storage::SessionSummary m_session;
    // A session of several devices: its parts, each device's own record.
    std::vector<core::storage::SessionPart> m_parts;
    ReviewPlot* m_plot = nullptr;
    QTreeWidget* m_list = nullptr;
    QLabel* m_header = nullptr;
    QLineEdit* m_reviewer = nullptr;
    ReviewAccount* m_account = nullptr;
    core::derived::LaneOptions m_laneOptions;
    QLabel* m_problem = nullptr;
    QString m_readProblem;  // the plot's, while shown
    QSpinBox* m_speed = nullptr;
    QAction* m_playAction = nullptr;
    QAction* m_clearFilters = nullptr;  // Signal ▸ Remove the review filters
    QTimer m_replay;
    QElapsedTimer m_replayClock;
    double m_playhead_s = 0.0;
    std::optional<core::storage::Annotation> m_deleted;  // the last deleted note, for undo
};

}  // namespace tactiscope::ui
