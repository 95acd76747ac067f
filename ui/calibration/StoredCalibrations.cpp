// StoredCalibrations: reading and adding records through SessionStore.
#include "ui/calibration/StoredCalibrations.h"

#include "core/storage/SessionStore.h"

#include <QDir>
#include <QFileInfo>
#include <QMessageBox>

namespace tactiscope::ui {

std::optional<core::storage::StoredCalibration> newestCalibration(const QString& storePath, std::string_view kind,
                                                                  const std::string& sensor)
{
    if (!QFileInfo::exists(storePath)) return std::nullopt;
    try {
        core::storage::SessionStore store(storePath.toStdString(), core::storage::Database::Access::ReadOnly);
        return store.newestCalibration(kind, sensor);
    } catch (const core::storage::StorageError& e) {
        qWarning("calibrations not read: %s", e.what());
    }
    return std::nullopt;
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
        QMessageBox::warning(parent, QObject::tr("Calibration not stored"),
                             QObject::tr("The calibration could not be stored in %1:\n%2")
                                 .arg(storePath, QString::fromStdString(e.what())));
        return std::nullopt;
    }
}

}  // namespace tactiscope::ui
