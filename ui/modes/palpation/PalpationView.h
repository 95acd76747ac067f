// The palpation mode (seed 001) under the probe's traces: F_H, F_L and Q as
// lanes; the current stiffness in large type with its
// standard error while pressing; a tare button; each completed press as a
// row (time, k_o, standard error, displacement range, displacement slope,
// site); the latest reading on the reference-tissue scale; and the optional
// grid map of phantom sites.
#pragma once

#include "core/compliance/LivePalpation.h"
#include "core/compliance/SiteGrid.h"
#include "devices/session/LiveSession.h"
#include "ui/modes/LiveModeView.h"

#include <QString>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace tactiscope::ui {

class LivePlotWidget;
class SiteGridMap;
class StiffnessScale;

class PalpationView : public LiveModeView {
    Q_OBJECT

public:
    explicit PalpationView(QWidget* parent = nullptr);

    // Shows the session's palpation output, with the profile that turns the
    // beams' signals into forces and the gauge-factor calibrations it reads.
    void bind(const devices::session::LiveSession* session) override;
    // The clinician's grid and choice of site go to the session first (a
    // press completed in this poll was taken there); then its presses and
    // the readout.
    void update(devices::session::LiveSession& session) override;
    // Refreshes the large readout; called by the main window's timer.
    void updateReadout();
    // Shows the session's presses (devices::session::PalpationUnit::presses())
    // on the lists' clock: rows, the scale and, for those stored, the grid's
    // cells; another generation starts afresh. The grid's selection is the
    // session's next site.
    void showPresses(const std::vector<devices::session::PressRecord>& presses,
                     const devices::session::LiveLists& lists, const std::optional<core::compliance::SiteGrid>& grid);
    int readingCount() const;

    LivePlotWidget* lanes() const override { return m_lanes; }
    SiteGridMap* siteGrid() const { return m_grid; }

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void startSubject();
    void fitPressColumns();

    std::shared_ptr<core::compliance::LivePalpation> m_palpation;
    LivePlotWidget* m_lanes = nullptr;
    QLabel* m_probe = nullptr;
    QLabel* m_stiffness = nullptr;
    QLabel* m_status = nullptr;
    QPushButton* m_tare = nullptr;
    StiffnessScale* m_scale = nullptr;
    QTableWidget* m_presses = nullptr;
    SiteGridMap* m_grid = nullptr;
    std::uint64_t m_generation = 0;
    devices::session::LiveClock m_clock = devices::session::LiveClock::SinceConnect;
};

}  // namespace tactiscope::ui
