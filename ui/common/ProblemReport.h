// How the workstation tells a problem: every one is logged (category
// "tactiscope.problem") and shown in a box that does not block, so
// acquisition and recording go on and the operator closes it when
// convenient. A problem says what did not happen, why (the system's own
// message), and what the user can do about it.
#pragma once

#include <QLoggingCategory>
#include <QString>

#include <string>
#include <vector>

class QMessageBox;
class QWidget;

namespace tactiscope::ui {

Q_DECLARE_LOGGING_CATEGORY(problemLog)

struct Problem {
    QString title;   // the action that failed: "Cannot record"
    QString what;    // one sentence: what did not happen
    QString detail;  // why, as the system said it
    QString remedy;  // what to do about it
    QString objectName = QStringLiteral("problemBox");
};

// Logs `problem` and shows it over `parent`; returns the box (deleted when closed).
QMessageBox* reportProblem(QWidget* parent, const Problem& problem);
// Only logs it: for a window that shows its problems in a line of its own.
void logProblem(const Problem& problem);
// What a live device could not do (a processor, a calibration it could not
// read; LiveSession::takeProblems), each shown, never only logged: a
// calibration is never dropped without the operator knowing.
void reportAnalysisProblems(QWidget* parent, const std::vector<std::string>& problems);

}  // namespace tactiscope::ui
