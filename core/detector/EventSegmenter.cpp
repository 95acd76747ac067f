// EventSegmenter: runs, hold-time bridging and peak tracking.
#include "core/detector/EventSegmenter.h"

#include <cmath>
#include <stdexcept>

namespace tactiscope::core::detector {

EventSegmenter::EventSegmenter(double hold_s, std::optional<double> spacing_m)
    : m_hold_s(hold_s),
      m_spacing_m(spacing_m)
{
    if (!(std::isfinite(hold_s) && hold_s >= 0.0)) throw std::invalid_argument("hold time must not be negative");
    if (spacing_m && !(std::isfinite(*spacing_m) && *spacing_m > 0.0))
        throw std::invalid_argument("cantilever spacing must be positive");
}

void EventSegmenter::reset()
{
    m_open.reset();
}

void EventSegmenter::close(std::vector<DefectEvent>& completed)
{
    if (!m_open) return;
    if (m_spacing_m && m_open->peakLag_s > 0.0) m_open->speed_m_per_s = *m_spacing_m / m_open->peakLag_s;
    completed.push_back(*m_open);
    m_open.reset();
}

void EventSegmenter::push(double t_s, const DetectorOutput& o, double sampleInterval_s,
                          std::vector<DefectEvent>& completed)
{
    // A gap longer than the hold time (measured between matching samples,
    // with half a sample of slack for rounding) ends the event.
    if (m_open && t_s - m_lastActive_s > m_hold_s + sampleInterval_s * 1.5) close(completed);
    if (o.decision == 0) return;
    if (m_open && m_open->direction != o.decision) close(completed);

    const double r = o.decision > 0 ? o.rab : o.rba;
    const double lag_s = static_cast<double>(o.decision > 0 ? o.lagAb : o.lagBa) * sampleInterval_s;
    if (!m_open) {
        m_open = DefectEvent{t_s, t_s, o.decision, r, lag_s, std::nullopt, std::nullopt};
    } else if (r > m_open->peakR) {
        m_open->peakR = r;
        m_open->peakLag_s = lag_s;
    }
    m_open->end_s = t_s;
    m_lastActive_s = t_s;
}

void EventSegmenter::finish(std::vector<DefectEvent>& completed)
{
    close(completed);
}

}  // namespace tactiscope::core::detector
