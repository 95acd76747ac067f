// A mode's account of a stored session in the review window, beside the
// list of records: a panel's re-analysis, a palpation's presses and sites,
// a capacitive beam's calibration. The window asks it, whatever the mode,
// for what it found and nobody saved yet, tells it each time the records
// are read, and follows its requests (refresh, show a span, read the
// session through other lane options). ui/modes/ModeUi.h says which
// account a mode has.
#pragma once

#include "core/derived/SessionLanes.h"
#include "core/storage/SessionRecords.h"
#include "core/storage/SessionSource.h"

#include <QGroupBox>
#include <QString>

#include <functional>
#include <optional>
#include <vector>

namespace tactiscope::ui {

// What the window lends an account.
struct ReviewAccountContext {
    QString storePath;  // for a worker's own connection
    core::storage::SessionSource& store;
    const core::storage::SessionSummary& session;
    // Changes the plot's lane options and redraws it, keeping the view;
    // returns an error, or empty.
    std::function<QString(const std::function<void(core::derived::LaneOptions&)>& change)> changeLanes;
    std::string derivedProblem;  // why the plot shows the stored channels only, if it does
};

class ReviewAccount : public QGroupBox {
    Q_OBJECT

public:
    using QGroupBox::QGroupBox;

    // What a re-analysis found and nobody saved yet: its own row of markers
    // and its entries in the list. None: the account does not re-analyse,
    // or has nothing to show in that row.
    struct Unsaved {
        std::vector<core::storage::SessionEvent> events;
        std::vector<core::storage::SessionReading> readings;
    };
    virtual std::optional<Unsaved> unsaved() const { return std::nullopt; }
    // Readings from somewhere other than the recording, by their source.
    struct Readings {
        QString source;  // "re-analysis", "saved \"…\""
        std::vector<core::storage::SessionReading> readings;
    };
    // The session's records were read (again): the recorded readings and
    // those of the unsaved re-analysis and each saved analysis that has any.
    virtual void showReadings(const std::vector<core::storage::SessionReading>& /*recorded*/,
                              const std::vector<Readings>& /*others*/)
    {
    }
    // Whether it needs more of the row than the list (a palpation's presses,
    // sites and scale do).
    virtual bool wantsRoom() const { return false; }

signals:
    void recordsChanged();                          // re-analysed or saved: read the records again
    void spanChosen(double start_s, double end_s);  // show it on the plot
    void problem(const QString& text);
    void status(const QString& text);
};

}  // namespace tactiscope::ui
