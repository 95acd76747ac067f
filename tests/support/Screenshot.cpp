// Screenshot helper for widget tests.
#include "support/Screenshot.h"

#include <QDir>
#include <QPixmap>
#include <QWidget>

namespace tactiscope::testing {

QString saveScreenshot(QWidget& widget, const QString& name)
{
    const QDir directory(QStringLiteral(TACTISCOPE_SCREENSHOT_DIR));
    if (!directory.mkpath(QStringLiteral("."))) return {};
    const QString path = directory.filePath(name + QStringLiteral(".png"));
    return widget.grab().save(path, "PNG") ? path : QString();
}

}  // namespace tactiscope::testing
