// Naming a re-analysis before it is stored, for every mode's re-analysis
// in the review window: the name asked for without blocking (a dated
// default), and the rule a name must meet — not empty, not "live" (the
// recording's), not one the session already has, of events or readings.
#pragma once

#include "core/storage/SessionStore.h"

#include <QString>

#include <functional>

class QWidget;

namespace tactiscope::ui {

// Why `name` cannot name a new analysis of `session`, or empty when it can.
// Throws core::storage::StorageError when the store cannot be read.
QString analysisNameProblem(core::storage::SessionSource& store, std::int64_t session, const QString& name);

// Asks for a name without blocking; `save` is called with it when given.
// `kept` says what stays as it is ("the recorded events").
void askAnalysisName(QWidget* parent, const QString& kept, std::function<void(const QString&)> save);

}  // namespace tactiscope::ui
