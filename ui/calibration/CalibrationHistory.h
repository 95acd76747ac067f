// The calibration history of a session store: every sensor that has been
// calibrated; for the chosen one, each record with its statistics (value
// and standard error, R², points, operator), a small plot of the calibrated
// value against date with the drift summary (core::calibration::
// summarizeDrift), and for the chosen record the sessions that used it.
// The newest record of a sensor is the active one and is marked so.
#pragma once

#include "core/storage/SessionRecords.h"

#include <QDialog>
#include <QPointF>

#include <vector>

class QCustomPlot;
class QLabel;
class QListWidget;
class QTableWidget;

namespace tactiscope::ui {

class CalibrationHistory : public QDialog {
    Q_OBJECT

public:
    explicit CalibrationHistory(const QString& storePath, QWidget* parent = nullptr);

    // Re-reads the store (after a new calibration).
    void reload();
    // Shows one sensor's records; false for a sensor without any.
    bool selectSensor(const QString& sensor);
    void selectRecord(int row);

    // For tests: the plotted (seconds since the epoch, value) points.
    std::vector<QPointF> plottedPoints() const;

private:
    void showSensor();
    void showSessions();

    QString m_storePath;
    std::vector<core::storage::StoredCalibration> m_all;
    std::vector<const core::storage::StoredCalibration*> m_shown;  // of the chosen sensor, oldest first
    QListWidget* m_sensors;
    QTableWidget* m_records;
    QLabel* m_drift;
    QCustomPlot* m_plot;
    QListWidget* m_sessions;
    QLabel* m_problem;
};

}  // namespace tactiscope::ui
