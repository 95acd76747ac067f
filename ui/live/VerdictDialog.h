// A panel's verdict, kept or overridden (a dent the probe missed, a false
// alarm) with an optional note saying why: asked of the operator when a
// panel-scan recording stops (the automatic verdict is already stored) and
// of a reviewer in the review window. Non-modal: the line goes on while it
// waits. Either answer goes into the session's verdict trail with the
// decider's name, so a report tells who decided what.
#pragma once

#include "core/Vocabulary.h"

#include <QDialog>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

class QLineEdit;

namespace tactiscope::core::storage {
class StoreWorker;
}

namespace tactiscope::ui {

class VerdictDialog : public QDialog {
    Q_OBJECT

public:
    // `summary` says what was found and the verdict; `findings` lists what
    // it was decided on (a panel's sites), `trail` the decisions so far
    // (core/report/VerdictTrail.h), shown small.
    VerdictDialog(const QString& summary, const QStringList& findings, const QStringList& trail, core::Verdict verdict,
                  QWidget* parent = nullptr);

signals:
    // The verdict chosen (the same one when kept) and the note, maybe empty.
    void decided(core::Verdict verdict, const QString& note);

private:
    void decide(core::Verdict verdict);

    QLineEdit* m_note;
};

// What the operator is asked about a recorded panel.
struct VerdictQuestion {
    std::int64_t session = 0;
    int crossings = 0;                              // the detector's events
    int sites = 0;                                  // the places they group into
    QStringList findings;                           // a line per site (RecordingSummary::findings)
    core::Verdict automatic = core::Verdict::Pass;  // already stored with the session
    std::string operatorName;
};

// Asks without blocking and writes the answer through the store worker of
// the store the session was recorded into (kept alive until answered): the
// operator's decision, kept or changed, with the note. `saved(message)`
// tells a status line; a failure is reported. Returns the dialog (it
// deletes itself once closed).
VerdictDialog* askVerdict(QWidget* parent, std::shared_ptr<core::storage::StoreWorker> store,
                          const VerdictQuestion& question, std::function<void(const QString& message)> saved);

// "1 defect", "5 defects".
QString defectCountText(int defects);
// "1 site", "3 sites".
QString siteCountText(int sites);

}  // namespace tactiscope::ui
