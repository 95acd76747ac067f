// The panel-scan mode (seed 000) under the strain traces: the detector's
// output as its own lanes (decision +1 / −1 / 0, best R_ab and R_ba), its
// parameters editable while scanning (each change acts from the next block),
// a clear alarm on every defect with an optional sound, the list of defects
// (time, order, peak R, lag, implied scan speed) and the running count and
// verdict of the panel.
#pragma once

#include "core/detector/LiveDetection.h"
#include "devices/session/LiveSession.h"
#include "ui/modes/LiveModeView.h"

#include <QTimer>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QTableWidget;

namespace tactiscope::devices::session {
class PanelScanUnit;
}

namespace tactiscope::ui {

class LivePlotWidget;

class PanelScanView : public LiveModeView {
    Q_OBJECT

public:
    explicit PanelScanView(QWidget* parent = nullptr);

    // Shows the session's detector's output and edits its settings.
    void bind(const devices::session::LiveSession* session) override;
    // The session's defects.
    void update(devices::session::LiveSession& session) override;
    int defectCount() const;
    LivePlotWidget* lanes() const override { return m_lanes; }
    void setTraces(LivePlotWidget* traces) override { m_traces = traces; }

private:
    // Shows the panel's defects (the live session's list, on its clock) at
    // their sites: rows for those not listed yet, with the alarm; another
    // generation is a new list. The count says whether they are the
    // recording's, the stopped recording's as stored, or since connect and
    // not recorded.
    void showDefects(const devices::session::PanelScanUnit& unit, const devices::session::LiveLists& lists);
    void startPanel();
    void markOnTraces(const std::vector<core::detector::DefectEvent>& defects,
                      const devices::session::LiveLists& lists);
    QString countText() const;  // "5 defects at 1 site"
    QString verdictText() const;
    void showCount();
    void applySettings();
    void showSettings(const core::detector::LiveDetectionSettings& settings);
    void raiseAlarm(const core::detector::DefectEvent& event, double shownTime_s);
    void calmAlarm();

    std::shared_ptr<core::detector::LiveDetection> m_detection;
    LivePlotWidget* m_lanes = nullptr;
    LivePlotWidget* m_traces = nullptr;  // the device's, above
    std::uint64_t m_generation = 0;
    std::uint64_t m_tracesGeneration = 0;  // of the lists whose defects are on m_traces
    std::size_t m_onTraces = 0;
    devices::session::LiveClock m_clock = devices::session::LiveClock::SinceConnect;
    std::string m_notJudged;  // the last recording's, as its unit says
    QDoubleSpinBox* m_threshold = nullptr;
    QDoubleSpinBox* m_lagFrom = nullptr;
    QDoubleSpinBox* m_lagTo = nullptr;
    QDoubleSpinBox* m_lagStep = nullptr;
    QDoubleSpinBox* m_epsilon = nullptr;
    QComboBox* m_lambdaRule = nullptr;
    QDoubleSpinBox* m_lambda = nullptr;
    QCheckBox* m_faceToFace = nullptr;
    QDoubleSpinBox* m_spacing = nullptr;
    QCheckBox* m_sound = nullptr;
    QLabel* m_settingsError = nullptr;
    QLabel* m_alarm = nullptr;
    QLabel* m_countLabel = nullptr;
    QTableWidget* m_events = nullptr;
    // The rows listed are crossings; the verdict counts the sites they make
    // (the unit's, placed as the stored session's are).
    std::size_t m_siteCount = 0;
    QTimer m_alarmTimer;
    bool m_showing = false;  // showSettings() is filling the fields
};

}  // namespace tactiscope::ui
