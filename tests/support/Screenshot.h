// Saves what a widget shows as a PNG, so a developer can look at what a user
// sees after every test run (build/<preset>/screenshots/, or the folder in
// TACTISCOPE_SCREENSHOT_DIR: scripts/update-screenshots.sh uses it for
// docs/screenshots/).
#pragma once

#include <QString>

class QWidget;

namespace tactiscope::testing {

// Grabs `widget` (which must be shown) into <screenshot dir>/<name>.png and
// returns the file's path, or an empty string when it could not be written.
QString saveScreenshot(QWidget& widget, const QString& name);

}  // namespace tactiscope::testing
