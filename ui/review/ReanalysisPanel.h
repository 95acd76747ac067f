// Re-analysis of a stored panel-scan session: the surface-deflection
// detector's parameters (seed 000: lags, λ, ε, threshold, gauge mounting,
// hold and spacing), run on the stored samples on a worker thread with its
// own store connection (core::derived::detectStoredSession, the same routine
// as `tactiscope-cli analyze`), streamed a window at a time with a progress
// bar and Cancel, so the window stays responsive. The new events
// are shown beside the recorded ones and never replace them; "Save as
// analysis" stores them under a name of their own.
#pragma once

#include <QKeySequence>

#include "core/detector/DefectEvent.h"
#include "core/detector/StreamingDetection.h"
#include "core/signal/SignalSetup.h"
#include "core/storage/SessionStore.h"
#include "ui/review/ReviewAccount.h"

#include <cstdint>
#include <optional>
#include <thread>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace tactiscope::ui {

class ReanalysisPanel : public ReviewAccount {
    Q_OBJECT

public:
    // The store is the review window's (for saving); the worker opens its own.
    explicit ReanalysisPanel(const ReviewAccountContext& context, QWidget* parent);
    static QKeySequence runKeys();  // Ctrl+Return
    ~ReanalysisPanel() override;

    // The parameters as set in the panel; nullopt (and the reason shown) when
    // they are not valid.
    std::optional<core::detector::StretchSettings> settings();
    // Starts a run; false when one is running or the parameters are bad.
    bool run();
    // Stops a run; the events shown before it stay.
    void cancel();
    bool isRunning() const { return m_running; }
    const std::vector<core::detector::DefectEvent>& events() const { return m_events; }
    // The last result until it is saved (then it shows as its analysis).
    std::vector<core::detector::DefectEvent> unsavedEvents() const
    {
        return m_saved ? std::vector<core::detector::DefectEvent>{} : m_events;
    }
    // Its row of markers is always there: empty until a run finds defects.
    std::optional<Unsaved> unsaved() const override;
    bool hasResult() const { return m_hasResult; }
    // Stores the last result as an analysis; returns an error, or empty.
    QString saveAs(const QString& name);
    // Asks for a name without blocking, then saves.
    void askNameAndSave();

signals:
    void analysed();
    void saved(const QString& name);

private:
    struct Outcome {
        std::optional<core::detector::StretchDetection> detection;  // none when cancelled or failed
        double elapsed_s = 0.0;
        QString error;
    };
    void finish(Outcome outcome);
    void showProgress(std::uint64_t done, std::uint64_t total);
    void parametersChanged();

    QString m_storePath;
    core::storage::SessionSource& m_store;
    bool m_saveAllowed = true;  // the store's rights
    core::storage::SessionSummary m_session;
    std::vector<std::size_t> m_cantilevers;  // the strain channels, in probe order
    // The session's filters on them, when its mode read them so live.
    std::optional<core::signal::AnalysisFilters> m_filters;
    QDoubleSpinBox* m_lagStart;
    QDoubleSpinBox* m_lagStop;
    QDoubleSpinBox* m_lagStep;
    QComboBox* m_lambdaRule;
    QDoubleSpinBox* m_lambda;
    QDoubleSpinBox* m_epsilon;
    QDoubleSpinBox* m_threshold;
    QCheckBox* m_faceToFace;
    QDoubleSpinBox* m_hold;
    QDoubleSpinBox* m_spacing;
    QPushButton* m_run;
    QPushButton* m_save;
    QPushButton* m_cancel;
    QProgressBar* m_progress;
    QLabel* m_status;
    std::vector<core::detector::DefectEvent> m_events;
    bool m_hasResult = false;
    bool m_saved = false;
    bool m_running = false;
    std::jthread m_worker;  // last: joined before the members it reports to go
};

}  // namespace tactiscope::ui
