// Screenshot helper for widget tests.
#include "support/Screenshot.h"

#include <QDir>
#include <QPixmap>
#include <QWidget>

namespace tactiscope::testing {

QString saveScreenshot(QWidget& widget, const QString& name)
{
    // scripts/update-screenshots.sh points this at docs/screenshots.
    const QString override = qEnvironmentVariable("TACTISCOPE_SCREENSHOT_DIR");
    const QDir directory(override.isEmpty() ? QStringLiteral(TACTISCOPE_SCREENSHOT_DIR) : override);
    if (!directory.mkpath(QStringLiteral("."))) return {};
    const QString path = directory.filePath(name + QStringLiteral(".png"));
    return widget.grab().save(path, "PNG") ? path : QString();
}

}  // namespace tactiscope::testing
