// Saves what a widget shows as a PNG, so a developer can look at what a user
// sees after every test run (build/<preset>/screenshots/, or the folder in
// TACTISCOPE_SCREENSHOT_DIR: scripts/update-screenshots.sh uses it for
// docs/screenshots/).
#pragma once

#include <QSize>
#include <QString>

class QWidget;

namespace tactiscope::testing {

// Grabs `widget` (which must be shown) into <screenshot dir>/<name>.png and
// returns the file's path, or an empty string when it could not be written.
QString saveScreenshot(QWidget& widget, const QString& name);

// The same at another window size (a 1920×1080 screen), named
// <name>-<width>x<height>; the widget gets its size back after.
QString saveScreenshotAtSize(QWidget& widget, const QString& name, QSize size);

}  // namespace tactiscope::testing
