// The optional grid map of the palpation mode: the sites of a phantom as
// rows × columns (A1, A2, … B1, …), drawn in the stiffness colour map with a
// legend in N/m. It shows the live session's grid (core/compliance/SiteGrid):
// the clinician's choices (the grid's size, the cell to press next) go to
// the session on its next poll, and the selection and the readings come
// back from it, so a reading lands where the recording says it was taken.
#pragma once

#include "core/compliance/SiteGrid.h"

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
    // The grid the clinician set up; none when the map is off.
    std::optional<core::compliance::SiteGrid> grid() const;
    // The selected cell's name, e.g. "B3"; empty when the map is off.
    QString currentSite() const;
    // The clinician's choice of the next site (as a click on the cell).
    void selectSite(int row, int column);
    // The cell chosen since the last call, for the session.
    std::optional<core::compliance::SiteCell> takeChosenSite() { return std::exchange(m_chosen, std::nullopt); }

    // From the session: the cell the next press is taken at, and readings.
    void showCurrent(core::compliance::SiteCell cell);
    void clearReadings();
    void showReading(core::compliance::SiteCell cell, double stiffness_n_per_m, double standardError_n_per_m);
    // The reading shown in a cell, if any.
    std::optional<double> valueAt(int row, int column) const;

private:
    void resizeGrid();

    std::optional<core::compliance::SiteCell> m_chosen;
    bool m_showing = false;  // showCurrent() moves the selection, not the clinician
    QCheckBox* m_active = nullptr;
    QSpinBox* m_rows = nullptr;
    QSpinBox* m_columns = nullptr;
    QTableWidget* m_grid = nullptr;
    QWidget* m_legend = nullptr;
};

// A site's name: row letter and column number from 1, e.g. (1, 2) → "B3".
QString siteName(int row, int column);

}  // namespace tactiscope::ui
