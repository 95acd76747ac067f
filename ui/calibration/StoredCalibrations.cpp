// StoredCalibrations: naming the records in use.
#include "ui/calibration/StoredCalibrations.h"

#include <QObject>
#include <QStringList>

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

}  // namespace tactiscope::ui
