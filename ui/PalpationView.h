// The palpation mode (seed 001) under the probe's traces: F_H, F_L and Q as
// lanes; the current stiffness in large type with its
// standard error while pressing; a tare button; each completed press as a
// row (time, k_o, standard error, displacement range, displacement slope,
// site); the latest reading on the reference-tissue scale; and the optional
// grid map of phantom sites.
#pragma once

#include "core/compliance/LivePalpation.h"

#include <QString>
#include <QWidget>

#include <memory>
#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace tactiscope::ui {

class LivePlotWidget;
class SiteGridMap;
class StiffnessScale;

// A completed press and the site it was taken at (empty without a grid map).
struct SiteReading {
    core::compliance::PressReading press;
    QString site;
};

class PalpationView : public QWidget {
    Q_OBJECT

public:
    explicit PalpationView(QWidget* parent = nullptr);

    // Shows `palpation`'s output; null detaches. `probeName` says which
    // profile turns the beams' signals into forces, `calibration` which
    // gauge-factor calibrations ("" when none).
    void setPalpation(std::shared_ptr<core::compliance::LivePalpation> palpation, double sampleRate_hz,
                      const QString& probeName, const QString& calibration = {});
    // Refreshes the large readout; called by the main window's timer.
    void updateReadout();
    // Takes the presses completed since the last call into the list, the
    // scale and the grid, and returns them (the main window stores them).
    std::vector<SiteReading> takeNewReadings();
    // A new recording: empties the list (the grid map stays: same phantom).
    void startSubject();
    int readingCount() const;

    LivePlotWidget* lanes() const { return m_lanes; }
    SiteGridMap* siteGrid() const { return m_grid; }

public slots:
    void tare();

signals:
    void profilesRequested();  // the probe line's "Change…" link

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    std::shared_ptr<core::compliance::LivePalpation> m_palpation;
    LivePlotWidget* m_lanes = nullptr;
    QLabel* m_probe = nullptr;
    QLabel* m_stiffness = nullptr;
    QLabel* m_status = nullptr;
    QPushButton* m_tare = nullptr;
    StiffnessScale* m_scale = nullptr;
    QTableWidget* m_presses = nullptr;
    SiteGridMap* m_grid = nullptr;
};

}  // namespace tactiscope::ui
