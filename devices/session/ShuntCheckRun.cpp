// ShuntCheckRun: the windows, the commands and their answers, the result.
#include "devices/session/ShuntCheckRun.h"

#include "core/signal/SteadyWindow.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tactiscope::devices::session {
namespace {

// Its second half against its first, in their own noise (SteadyWindow's
// score: about 1 when steady); the tare rules' bound.
bool steady(const std::vector<double>& window)
{
    constexpr double kSteadyScore = 6.0;
    core::signal::SteadyWindow judged(window.size());
    for (const double value : window) judged.push(value);
    return judged.halfShiftScore() <= kSteadyScore;
}

}  // namespace

ShuntCheckRun::ShuntCheckRun(LiveSession& session, ShuntCheckSettings settings)
    : m_session(session),
      m_settings(settings),
      m_expected(
          core::straingauge::shuntStrain(settings.bridge, settings.gauge_ohm, settings.shunt_ohm, settings.gaugeFactor))
{
    if (settings.channel >= session.channels().size())
        throw std::invalid_argument("shunt check: the device has no channel " + std::to_string(settings.channel + 1));
    const double rate_hz = session.source().nominalSampleRate_hz();
    m_windowSamples = std::max<std::size_t>(2, static_cast<std::size_t>(std::llround(settings.window_s * rate_hz)));
    m_settleSamples = static_cast<std::size_t>(std::llround(settings.settle_s * rate_hz));
    // From the newest sample on: the baseline is what comes now.
    m_cursor.next = session.buffer()->samplesWritten();
    m_session.takeStatuses();  // answers to anything before are not this run's
}

ShuntCheckRun::~ShuntCheckRun()
{
    if (m_shuntOn) m_session.requestShunt(m_settings.channel, false);
}

double ShuntCheckRun::progress() const
{
    const double total = 2.0 * static_cast<double>(m_windowSamples) + static_cast<double>(m_settleSamples);
    const double done = static_cast<double>(m_off.size() + m_on.size() + m_settled);
    return m_phase == Phase::Done ? 1.0 : std::min(1.0, done / total);
}

void ShuntCheckRun::refuse(std::string why)
{
    if (m_shuntOn) m_session.requestShunt(m_settings.channel, false);
    m_shuntOn = false;
    m_result = ShuntCheckResult{std::move(why), {}, {}};
    m_phase = Phase::Done;
}

// The device's answer to the last command: it switched (true), it said why
// not (false, the reason kept), or nothing yet.
std::optional<bool> ShuntCheckRun::answer(bool on)
{
    for (const auto& status : m_session.takeStatuses()) {
        if (status.message.rfind("shunt: ", 0) == 0) {
            m_deviceRefusal = status.message.substr(7);
            return false;
        }
        // The reference sketch before command 6 said so (docs/firmware.md).
        if (status.message == "unknown command") {
            m_deviceRefusal = "it does not know the shunt command (firmware older than TSP/1 command 6)";
            return false;
        }
        if (status.message.rfind(on ? "shunt on" : "shunt off", 0) == 0) return true;
    }
    return std::nullopt;
}

bool ShuntCheckRun::advance()
{
    if (m_phase == Phase::Done) return true;
    const auto channel = m_settings.channel;
    std::vector<double> fresh;
    while (m_session.buffer()->readNew(m_cursor, m_chunk, 4096) > 0)
        fresh.insert(fresh.end(), m_chunk.values[channel].begin(), m_chunk.values[channel].end());
    // Samples missed (the owner stalled behind the live buffer's two
    // seconds): a window must be contiguous, so the one being filled starts
    // again from the samples after the gap; a workstation that keeps
    // missing them cannot check.
    if (m_cursor.overrun > 0) {
        m_cursor.overrun = 0;
        if (++m_overruns > kMostOverruns)
            return refuse("the check kept missing samples: the workstation is too busy to follow the stream"), true;
        if (m_phase == Phase::Baseline) m_off.clear();
        if (m_phase == Phase::Settle || m_phase == Phase::Shunted) {
            m_on.clear();
            m_settled = 0;
            m_phase = Phase::Settle;
        }
    }
    const auto elapsed_s = [this] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_asked).count();
    };
    const auto ask = [this](bool on) {
        if (auto refusal = m_session.requestShunt(m_settings.channel, on)) return refuse(*refusal), false;
        m_asked = std::chrono::steady_clock::now();
        return true;
    };
    std::size_t used = 0;
    switch (m_phase) {
    case Phase::Baseline: {
        const std::size_t take = std::min(fresh.size(), m_windowSamples - m_off.size());
        m_off.insert(m_off.end(), fresh.begin(), fresh.begin() + static_cast<std::ptrdiff_t>(take));
        if (m_off.size() == m_windowSamples && ask(true)) m_phase = Phase::AwaitOn;
        break;
    }
    case Phase::AwaitOn: {
        const auto answered = answer(true);
        if (answered && !*answered) return refuse("the probe cannot switch the shunt: " + m_deviceRefusal), true;
        if (!answered && elapsed_s() > m_settings.answerTimeout_s)
            return refuse("the probe did not answer the shunt command: it cannot switch a shunt (a probe older than "
                          "TSP/1 command 6)"),
                   true;
        if (answered) {
            m_shuntOn = true;
            m_phase = Phase::Settle;  // the samples read so far may be from before the switch
        }
        break;
    }
    case Phase::Settle:
        used = std::min(fresh.size(), m_settleSamples - m_settled);
        m_settled += used;
        if (m_settled < m_settleSamples) break;
        m_phase = Phase::Shunted;
        [[fallthrough]];
    case Phase::Shunted: {
        const std::size_t take = std::min(fresh.size() - used, m_windowSamples - m_on.size());
        m_on.insert(m_on.end(), fresh.begin() + static_cast<std::ptrdiff_t>(used),
                    fresh.begin() + static_cast<std::ptrdiff_t>(used + take));
        if (m_on.size() == m_windowSamples && ask(false)) m_phase = Phase::AwaitOff;
        break;
    }
    case Phase::AwaitOff: {
        const auto answered = answer(false);
        if (!answered && elapsed_s() <= m_settings.answerTimeout_s) break;
        m_shuntOn = false;
        if (answered && !*answered) return refuse("the probe could not switch the shunt off: " + m_deviceRefusal), true;
        if (!answered) return refuse("the probe did not confirm the shunt off: check it before measuring"), true;
        // A step is only the shunt's when nothing else moved the channel.
        for (const auto* window : {&m_off, &m_on})
            if (!steady(*window))
                return refuse("the channel moved during the check (more than its noise): hold the probe still, "
                              "unloaded, and check again"),
                       true;
        const auto step = core::straingauge::measureShuntStep(m_off, m_on);
        m_result =
            ShuntCheckResult{{}, step, core::straingauge::checkShunt(m_expected, step.step, m_settings.tolerance)};
        m_phase = Phase::Done;
        break;
    }
    case Phase::Done:
        break;
    }
    return m_phase == Phase::Done;
}

core::calibration::CalibrationRecord ShuntCheckRun::record(const std::string& sensor,
                                                           const std::string& operatorName) const
{
    core::calibration::CalibrationRecord r;
    r.kind = std::string(core::calibration::kShuntCheckKind);
    r.sensorName = sensor;
    r.operatorName = operatorName;
    r.timestampUtc = core::calibration::utcTimestampNow();
    const auto& s = m_settings;
    r.values = {{"bridge_active_gauges", core::straingauge::activeGauges(s.bridge)},
                {"gauge_resistance_ohm", s.gauge_ohm},
                {"shunt_resistance_ohm", s.shunt_ohm},
                {"shunt_gauge_factor", s.gaugeFactor},
                {"shunt_expected_ue", m_expected * 1e6}};
    if (m_result && m_result->refusal.empty()) {
        r.values.push_back({"shunt_measured_ue", m_result->measured.step * 1e6});
        r.values.push_back({"shunt_measured_standard_error_ue", m_result->measured.uncertainty * 1e6});
        r.values.push_back({"shunt_deviation_percent", m_result->check.deviation * 100.0});
        r.values.push_back({"shunt_tolerance_percent", s.tolerance * 100.0});
        r.values.push_back({"shunt_passed", m_result->check.passed ? 1.0 : 0.0});
    }
    return r;
}

}  // namespace tactiscope::devices::session
