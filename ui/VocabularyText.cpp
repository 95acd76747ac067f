// VocabularyText: the modes' titles.
#include "ui/VocabularyText.h"

#include <QCoreApplication>

namespace tactiscope::ui {

QString modeTitle(core::Mode mode)
{
    switch (mode) {
    case core::Mode::PanelScan:
        return QCoreApplication::translate("Mode", "Panel scan");
    case core::Mode::Palpation:
        return QCoreApplication::translate("Mode", "Palpation");
    case core::Mode::Capacitive:
        return QCoreApplication::translate("Mode", "Capacitive");
    case core::Mode::General:
        return QCoreApplication::translate("Mode", "General recording");
    }
    return {};
}

QString orderText(int direction)
{
    return direction > 0 ? QObject::tr("A then B") : QObject::tr("B then A");
}

}  // namespace tactiscope::ui
