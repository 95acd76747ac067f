// CalibrationText: calibration records in words, through the one formatter.
#include "ui/calibration/CalibrationText.h"

#include "core/calibration/CalibrationFields.h"
#include "core/calibration/CapacitiveCalibration.h"
#include "ui/common/DateText.h"
#include "ui/common/NumberText.h"

#include <QObject>

namespace tactiscope::ui {

QString calibrationsText(const std::vector<core::storage::StoredCalibration>& calibrations)
{
    QStringList texts;
    for (const auto& stored : calibrations)
        texts << QObject::tr("%1, calibrated %2 by %3")
                     .arg(QString::fromStdString(stored.record.sensorName), screenDateTime(stored.record.timestampUtc),
                          QString::fromStdString(stored.record.operatorName));
    return texts.join(QStringLiteral("; "));
}

QStringList calibrationValueTexts(const core::calibration::CalibrationRecord& record)
{
    QStringList texts;
    for (const auto& row : core::calibration::calibrationRows(record.values)) {
        const QString label = QString::fromStdString(row.label) + u' ';
        // A force or a length without an uncertainty (the detection limit)
        // as the wizard and the report's summary write it: SI prefix, and
        // a force as a mass too.
        if (!row.uncertainty && row.unit == "mN") {
            texts << label + detectionLimitText(row.value * 1e-3);
        } else if (!row.uncertainty && row.unit == "mm") {
            texts << label + siText(row.value * 1e-3, QStringLiteral("m"), 3);
        } else {
            const QString value =
                row.uncertainty ? valueWithErrorText(row.value, *row.uncertainty) : compactText(row.value, 4);
            texts << label + value + (row.unit.empty() ? QString() : u' ' + QString::fromStdString(row.unit));
        }
    }
    return texts;
}

QString detectionLimitText(double limit_n)
{
    return QObject::tr("%1 (%2 mgf)")
        .arg(siText(limit_n, QStringLiteral("N"), 3),
             significantText(limit_n / core::calibration::kMilligramForce_n, 3));
}

}  // namespace tactiscope::ui
