// The note of a marker, asked without blocking: the marker's time is the key
// press, typing the note does not delay it, and the recording goes on.
#pragma once

#include <QString>

#include <functional>

class QWidget;

namespace tactiscope::ui {

void askMarkerNote(QWidget* parent, double time_s, std::function<void(const QString& note)> entered);

}  // namespace tactiscope::ui
