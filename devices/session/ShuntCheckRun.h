// A shunt check on a live strain channel (issue 39), step by step from the
// owner's poll loop: the channel's mean with the shunt off (one window),
// the shunt switched on (TSP/1 command 6) and its answer awaited, a settling
// time, the mean with it on (another window), the shunt off again. The step
// is compared with what the shunt resistance, the gauge resistance, the
// bridge type and the gauge factor say it must be
// (core/straingauge/ShuntCalibration.h). A probe that answers nothing
// within the timeout is an older one that cannot switch a shunt; one that
// answers "shunt: …" says why not. The shunt is switched off again whatever
// happens, when the run ends or is dropped.
//
// Threading: the owner's thread only (the live session's).
#pragma once

#include "core/calibration/CalibrationRecord.h"
#include "core/straingauge/ShuntCalibration.h"
#include "devices/session/LiveSession.h"

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace tactiscope::devices::session {

struct ShuntCheckSettings {
    std::size_t channel = 0;
    core::straingauge::BridgeType bridge = core::straingauge::BridgeType::Quarter;
    double gauge_ohm = 350.0;
    double shunt_ohm = 100e3;
    double gaugeFactor = 2.0;  // the gauge's, from its data sheet
    double tolerance = 0.01;   // 1 %
    double window_s = 1.0;     // averaged with the shunt off, and on
    double settle_s = 0.3;     // after the device said it switched
    double answerTimeout_s = 2.0;
};

struct ShuntCheckResult {
    // Why it could not run (a probe that cannot switch a shunt, a channel
    // without a bridge, the device gone); empty when it ran.
    std::string refusal;
    core::straingauge::ShuntStep measured;
    core::straingauge::ShuntCheck check;
};

class ShuntCheckRun {
public:
    enum class Phase { Baseline, AwaitOn, Settle, Shunted, AwaitOff, Done };

    // Throws std::invalid_argument for a channel the session lacks or
    // settings shuntStrain() refuses.
    ShuntCheckRun(LiveSession& session, ShuntCheckSettings settings);
    ~ShuntCheckRun();  // a shunt left on is switched off

    ShuntCheckRun(const ShuntCheckRun&) = delete;
    ShuntCheckRun& operator=(const ShuntCheckRun&) = delete;

    // Reads what arrived and moves on; true once done (result() then holds).
    bool advance();
    Phase phase() const { return m_phase; }
    double progress() const;  // 0 to 1
    double expected() const { return m_expected; }
    const std::optional<ShuntCheckResult>& result() const { return m_result; }

    // The run as a calibration record for the history (kShuntCheckKind),
    // once it ran; `sensor` names the device and channel.
    core::calibration::CalibrationRecord record(const std::string& sensor, const std::string& operatorName) const;

private:
    void refuse(std::string why);
    std::optional<bool> answer(bool on);  // the device's answer: switched, refused, or none yet

    LiveSession& m_session;
    ShuntCheckSettings m_settings;
    double m_expected;
    std::size_t m_windowSamples;
    std::size_t m_settleSamples;
    core::LiveCursor m_cursor;
    core::LiveChunk m_chunk;
    std::vector<double> m_off, m_on;
    std::size_t m_settled = 0;
    static constexpr int kMostOverruns = 5;
    int m_overruns = 0;
    Phase m_phase = Phase::Baseline;
    bool m_shuntOn = false;
    std::chrono::steady_clock::time_point m_asked;
    std::string m_deviceRefusal;
    std::optional<ShuntCheckResult> m_result;
};

}  // namespace tactiscope::devices::session
