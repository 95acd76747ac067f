// StoredCalibrations: naming the records in use, adding a wizard's record.
#include "ui/calibration/StoredCalibrations.h"

#include "core/storage/SessionStore.h"
#include "ui/ProblemReport.h"

#include <QDir>
#include <QFileInfo>

namespace tactiscope::ui {

QString calibrationsText(const std::vector<core::storage::StoredCalibration>& calibrations)
{
    QStringList texts;
    for (const auto& stored : calibrations)
        texts << QObject::tr("%1 on %2 by %3")
                     .arg(QString::fromStdString(stored.record.sensorName),
                          QString::fromStdString(stored.record.timestampUtc),
                          QString::fromStdString(stored.record.operatorName));
    return texts.join(QStringLiteral(", "));
}

std::int64_t storeCalibration(const QString& storePath, const core::calibration::CalibrationRecord& record)
{
    QDir().mkpath(QFileInfo(storePath).absolutePath());  // a first calibration may come before any session
    return core::storage::SessionStore(storePath.toStdString()).addCalibration(record);
}

std::optional<std::int64_t> storeCalibrationOrSay(QWidget* parent, const QString& storePath,
                                                  const core::calibration::CalibrationRecord& record)
{
    try {
        return storeCalibration(storePath, record);
    } catch (const core::storage::StorageError& e) {
        reportProblem(parent, {QObject::tr("Calibration not stored"),
                               QObject::tr("The calibration could not be stored in %1.").arg(storePath),
                               QString::fromStdString(e.what()),
                               QObject::tr("The wizard stays open with every point: free space or fix the store's "
                                           "permissions, then accept again.")});
        return std::nullopt;
    }
}

}  // namespace tactiscope::ui
