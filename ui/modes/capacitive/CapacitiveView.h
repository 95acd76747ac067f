// The capacitive mode (seed 002) under the capacitance trace: force and tip
// displacement as lanes; C, ΔC, ΔC/C0, force and displacement in large
// readouts; the baseline C0 with a tare button; and what turns ΔC into µN
// and mm — the active calibration, or the beam model before there is one.
#pragma once

#include "core/capacitive/LiveCapacitive.h"
#include "ui/modes/LiveModeView.h"

#include <QString>

#include <memory>

class QLabel;
class QPushButton;

namespace tactiscope::ui {

class LivePlotWidget;

class CapacitiveView : public LiveModeView {
    Q_OBJECT

public:
    explicit CapacitiveView(QWidget* parent = nullptr);

    // Shows the session's capacitive output, with the profile and what
    // the sensitivities come from (a calibration, or the beam model).
    void bind(const devices::session::LiveSession* session) override;
    void update(devices::session::LiveSession& session) override;
    // Refreshes the readouts; called by the main window's timer.
    void updateReadouts();
    LivePlotWidget* lanes() const override { return m_lanes; }

private:
    QLabel* addReadout(const QString& caption, const char* objectName);

    std::shared_ptr<core::capacitive::LiveCapacitive> m_capacitive;
    LivePlotWidget* m_lanes = nullptr;
    QWidget* m_readoutPanel = nullptr;
    QLabel* m_capacitance = nullptr;
    QLabel* m_deltaC = nullptr;
    QLabel* m_relative = nullptr;
    QLabel* m_force = nullptr;
    QLabel* m_displacement = nullptr;
    QLabel* m_baseline = nullptr;
    QLabel* m_calibration = nullptr;
    QPushButton* m_tare = nullptr;
};

}  // namespace tactiscope::ui
