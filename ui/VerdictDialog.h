// The panel's verdict when a panel-scan recording stops: the detector's
// count and verdict, which the operator keeps or overrides (a dent the probe
// missed, a false alarm), with an optional note saying why. Non-modal: the
// line goes on while it waits, and the automatic verdict is already stored.
#pragma once

#include "core/Vocabulary.h"

#include <QDialog>
#include <QString>

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
    VerdictDialog(int defects, core::Verdict verdict, QWidget* parent = nullptr);

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
    double end_s = 0.0;  // the note's annotation goes here
    int defects = 0;
    core::Verdict automatic = core::Verdict::Pass;  // already stored with the session
    std::string author;
};

// Asks without blocking and writes the answer through the store worker of
// the store the session was recorded into (kept alive until answered): a
// changed verdict, and the note as an annotation at the session's end. `saved(message)` tells a status line; a failure
// is reported.
void askVerdict(QWidget* parent, std::shared_ptr<core::storage::StoreWorker> store, const VerdictQuestion& question,
                std::function<void(const QString& message)> saved);

// "1 defect", "5 defects".
QString defectCountText(int defects);

}  // namespace tactiscope::ui
