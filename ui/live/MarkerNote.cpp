// MarkerNote: a non-modal input dialog that deletes itself.
#include "ui/live/MarkerNote.h"

#include "ui/common/NumberText.h"

#include <QInputDialog>
#include <QLocale>

namespace tactiscope::ui {

void askMarkerNote(QWidget* parent, double time_s, std::function<void(const QString& note)> entered)
{
    auto* dialog = new QInputDialog(parent);
    dialog->setObjectName(QStringLiteral("markerNoteDialog"));
    dialog->setWindowTitle(QObject::tr("Note for a marker"));
    dialog->setLabelText(QObject::tr("Note for the marker at %1 s (recording time):").arg(fixedText(time_s, 2)));
    dialog->setMinimumWidth(420);  // room for a sentence and the title
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    QObject::connect(dialog, &QInputDialog::textValueSelected, parent, std::move(entered));
    dialog->open();
}

}  // namespace tactiscope::ui
