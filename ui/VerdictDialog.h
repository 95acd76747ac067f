// The panel's verdict when a panel-scan recording stops: the detector's
// count and verdict, which the operator keeps or overrides (a dent the probe
// missed, a false alarm), with an optional note saying why. Non-modal: the
// line goes on while it waits, and the automatic verdict is already stored.
#pragma once

#include "core/Vocabulary.h"

#include <QDialog>
#include <QString>

class QLineEdit;

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

// "1 defect", "5 defects".
QString defectCountText(int defects);

}  // namespace tactiscope::ui
