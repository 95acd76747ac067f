// VocabularyText: the modes' titles.
#include "ui/common/VocabularyText.h"

#include "core/modes/ModeDefinition.h"

#include <QCoreApplication>

#include <string>

namespace tactiscope::ui {

QString modeTitle(core::Mode mode)
{
    // The titles are the definitions' (core/modes), translated in context "Mode".
    const std::string title(core::definitionOf(mode).title);
    return QCoreApplication::translate("Mode", title.c_str());
}

QString orderText(int direction)
{
    return direction > 0 ? QObject::tr("A then B") : QObject::tr("B then A");
}

}  // namespace tactiscope::ui
