// What the main window tells when a recording ends (LiveStation::
// recordingEnded), whichever way it ended: a problem box for an end that
// was not a stop (its disk, a lost probe, a failed link; each device by
// name in a session of several), a status line for a session the trigger
// cut (the line goes on), and the verdict asked of the operator for a
// session that has one (a session of several: its parts' verdict).
#pragma once

#include "devices/session/LivePipeline.h"

#include <QString>

#include <functional>
#include <memory>
#include <string>

class QWidget;

namespace tactiscope::core::storage {
class StoreWorker;
}

namespace tactiscope::ui {

class VerdictDialog;

struct RecordingEndContext {
    QWidget* window = nullptr;
    std::shared_ptr<core::storage::StoreWorker> store;  // where the session went
    std::string operatorName;                           // who answers the verdict
    std::function<void(const QString&)> tell;           // a line in the status bar
    std::function<void()> verdictSaved;                 // the operator's verdict is stored
};

// Returns the verdict dialog when one was asked, else null.
VerdictDialog* tellRecordingEnd(const devices::session::RecordingEnd& end, const RecordingEndContext& context);
// One device's part of a session of several ended early (PipelineNews::
// partsEnded): why, while the others record on.
void tellPartEnded(QWidget* window, const std::string& device, const devices::session::RecordingSummary& summary);

}  // namespace tactiscope::ui
