// The measuring page of a calibration wizard: the load entry (value, unit,
// Capture), the stability light and what the last capture gave on the left
// above the table of captured points (Retake and Remove under it), and the
// linearity plot with the fit summary on the right. The wizard owns the
// points and fills the table; this panel only lays them out and reports the
// user's requests.
#pragma once

#include "ui/common/DisplayUnits.h"

#include <QStringList>
#include <QWidget>

#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QHBoxLayout;
class QLabel;
class QPushButton;
class QTableWidget;

namespace tactiscope::ui {

class CalibrationPlot;
class StabilityWatch;

class CapturePanel : public QWidget {
    Q_OBJECT

public:
    // loadUnits: the unit box's items, with their ids as item data.
    CapturePanel(const StabilityWatch* watch, const DisplayUnit& signalUnit,
                 const std::vector<std::pair<QString, int>>& loadUnits, const QStringList& columns,
                 QWidget* parent = nullptr);

    double loadValue() const;
    int loadUnit() const;
    void setLoad(double value, int unit);
    // Capture and the buttons are off while a capture waits for its window.
    void setWaiting(bool waiting);
    void setStatus(const QString& text);
    // One row per point; the first `leftColumns` columns are text, the
    // others numbers (right-aligned).
    void setRows(const std::vector<QStringList>& rows, int leftColumns);
    int selectedRow() const;
    void setFitSummary(const QString& text);
    CalibrationPlot* plot() const { return m_plot; }
    // Whether the loads are entered and captured one by one (the entry,
    // Retake and Remove shown) or come all at once from elsewhere (a sweep).
    void setLoadsByHand(bool byHand);
    // Puts a button at the right end of the Retake / Remove row.
    void addButton(QPushButton* button);
    // Back to the load entry, its text selected, for the next value.
    void focusEntry();

signals:
    void captureRequested();
    void retakeRequested(int row);
    void removeRequested(int row);

private:
    QWidget* m_entry;  // the load, its unit and Capture
    QDoubleSpinBox* m_value;
    QComboBox* m_unit;
    QPushButton* m_capture;
    QLabel* m_status;
    QTableWidget* m_table;
    QPushButton* m_retake;
    QPushButton* m_remove;
    QList<QPushButton*> m_extraButtons;
    QHBoxLayout* m_buttonRow;
    CalibrationPlot* m_plot;
    QLabel* m_fitSummary;
};

}  // namespace tactiscope::ui
