// The optional grid map of the palpation mode: the sites of a phantom as
// rows × columns (A1, A2, … B1, …). The clinician selects a cell and
// presses; the reading lands in that cell, drawn in the stiffness colour map
// with a legend in N/m, and the selection moves on to the next cell.
#pragma once

#include <QWidget>

#include <optional>

class QCheckBox;
class QSpinBox;
class QTableWidget;

namespace tactiscope::ui {

class SiteGridMap : public QWidget {
    Q_OBJECT

public:
    explicit SiteGridMap(QWidget* parent = nullptr);

    bool isActive() const;
    void setActive(bool active);
    // The selected cell's name, e.g. "B3"; empty when the map is off.
    QString currentSite() const;
    void selectSite(int row, int column);
    // Puts a reading into the selected cell and selects the next one.
    void place(double stiffness_n_per_m, double standardError_n_per_m);
    // The reading shown in a cell, if any.
    std::optional<double> valueAt(int row, int column) const;

private:
    void resizeGrid();

    QCheckBox* m_active = nullptr;
    QSpinBox* m_rows = nullptr;
    QSpinBox* m_columns = nullptr;
    QTableWidget* m_grid = nullptr;
    QWidget* m_legend = nullptr;
};

// A site's name: row letter and column number from 1, e.g. (1, 2) → "B3".
QString siteName(int row, int column);

}  // namespace tactiscope::ui
