// AnalysisName: the rule, and the dialog with a dated default.
#include "ui/review/AnalysisName.h"

#include <QDateTime>
#include <QInputDialog>

#include <algorithm>
#include <utility>

namespace tactiscope::ui {

QString analysisNameProblem(core::storage::SessionSource& store, std::int64_t session, const QString& name)
{
    const QString trimmed = name.trimmed();
    if (trimmed.isEmpty() || trimmed == QLatin1String(core::storage::kLiveAnalysis))
        return QObject::tr("The analysis needs a name other than \"live\".");
    const auto existing = store.analyses(session);
    if (std::ranges::find(existing, trimmed.toStdString()) != existing.end())
        return QObject::tr("The session already has an analysis named \"%1\".").arg(trimmed);
    return {};
}

void askAnalysisName(QWidget* parent, const QString& kept, std::function<void(const QString&)> save)
{
    auto* dialog = new QInputDialog(parent);
    dialog->setObjectName(QStringLiteral("analysisNameDialog"));
    dialog->setWindowTitle(QObject::tr("Save the re-analysis"));
    dialog->setLabelText(QObject::tr("Name of the analysis (%1 stay as they are):").arg(kept));
    dialog->setTextValue(
        QObject::tr("review %1").arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm"))));
    dialog->setMinimumWidth(420);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    QObject::connect(dialog, &QInputDialog::textValueSelected, parent, std::move(save));
    dialog->open();
}

}  // namespace tactiscope::ui
