// Screenshot helper for widget tests.
#include "support/Screenshot.h"

#include "support/WaitFor.h"

#include <QCoreApplication>
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
    // Layouts settle on posted events: a widget grabbed right after show()
    // would still have the sizes it had before its contents were set.
    QCoreApplication::sendPostedEvents();
    return widget.grab().save(path, "PNG") ? path : QString();
}

QString saveScreenshotAtSize(QWidget& widget, const QString& name, QSize size)
{
    const QSize before = widget.size();
    widget.resize(size);
    // A frame of the plots redrawn at the new width (they redraw on a timer).
    runEventLoopFor(300);
    const QString path =
        saveScreenshot(widget, QStringLiteral("%1-%2x%3").arg(name).arg(size.width()).arg(size.height()));
    widget.resize(before);
    runEventLoopFor(100);
    return path;
}

}  // namespace tactiscope::testing
