// TriggerMachine: arming, trigger, post time, hold-off, count.
#include "core/trigger/TriggerMachine.h"

#include "core/text/NumberFormat.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tactiscope::core::trigger {
namespace {

std::uint64_t samplesOf(double seconds, double rate_hz, const char* what)
{
    if (!(std::isfinite(seconds) && seconds >= 0.0))
        throw std::invalid_argument(std::string("trigger: the ") + what + " time must be 0 s or more");
    return static_cast<std::uint64_t>(std::llround(seconds * rate_hz));
}

}  // namespace

std::string settingsText(const TriggerSettings& settings)
{
    const auto seconds = [](double s) { return text::formatShortest(s) + " s"; };
    return settings.condition.text() + ", pre " + seconds(settings.pre_s) + ", post " + seconds(settings.post_s) +
           ", hold-off " + seconds(settings.holdOff_s);
}

std::string numberedSubject(const std::string& first, unsigned n)
{
    if (n == 0 || first.empty()) return first;
    const auto digits = first.find_last_not_of("0123456789") + 1;  // npos + 1 == 0: all digits
    if (digits == first.size()) return first + "-" + std::to_string(n + 1);
    const std::string number = first.substr(digits);
    if (number.size() > 18) return first + "-" + std::to_string(n + 1);  // beyond a counter: a name
    std::string next = std::to_string(std::stoull(number) + n);
    if (next.size() < number.size()) next.insert(0, number.size() - next.size(), '0');
    return first.substr(0, digits) + next;
}

const char* toString(TriggerState state)
{
    switch (state) {
    case TriggerState::Waiting:
        return "waiting";
    case TriggerState::Armed:
        return "armed";
    case TriggerState::Triggered:
        return "triggered";
    case TriggerState::Finished:
        return "finished";
    }
    return "";
}

TriggerMachine::TriggerMachine(TriggerSettings settings, double sampleRate_hz)
    : m_settings(std::move(settings))
{
    if (!(std::isfinite(sampleRate_hz) && sampleRate_hz > 0.0))
        throw std::invalid_argument("trigger: the sample rate must be positive");
    if (m_settings.sessions && *m_settings.sessions == 0) throw std::invalid_argument("trigger: at least one session");
    m_pre = samplesOf(m_settings.pre_s, sampleRate_hz, "pre-trigger");
    m_post = samplesOf(m_settings.post_s, sampleRate_hz, "post-trigger");
    m_holdOff = samplesOf(m_settings.holdOff_s, sampleRate_hz, "hold-off");
}

TriggerMachine::Step TriggerMachine::push(std::uint64_t index, double value)
{
    Step step;
    if (!m_firstSeen) m_firstSeen = index;
    const auto& c = m_settings.condition;
    if (std::isnan(value)) {
        m_previous.reset();
        return step;
    }
    m_valueSeen = true;
    const bool holds = c.holds(value);
    const bool begins = c.begins(m_previous, value);
    m_previous = value;

    if (m_state == TriggerState::Triggered) {
        // A level or window runs on while it holds; its post time counts
        // from the sample it cleared at (an edge's from its trigger).
        if (!c.isEdge() && holds) m_clearedAt.reset();
        if (!c.isEdge() && !holds && !m_clearedAt) m_clearedAt = index;
        const std::uint64_t from = c.isEdge() ? m_open->trigger + 1 : m_clearedAt.value_or(index + 1);
        if (c.isEdge() || m_clearedAt) {
            if (index + 1 >= from + m_post) {
                m_open->end = from + m_post;
                step.ended = m_open;
                m_lastEnd = m_open->end;
                m_open.reset();
                m_clearedAt.reset();
                ++m_cut;
                m_rearmAt = m_lastEnd + m_holdOff;
                m_state = m_settings.sessions && m_cut >= *m_settings.sessions ? TriggerState::Finished
                                                                               : TriggerState::Waiting;
            }
        }
        return step;
    }
    if (m_state == TriggerState::Finished) return step;
    if (m_state == TriggerState::Waiting) {
        // Armed once the hold-off is over and the condition no longer holds
        // (a level still high from before is no new trigger).
        if (index < m_rearmAt || (holds && !c.isEdge())) return step;
        m_state = TriggerState::Armed;
        if (!c.isEdge()) return step;  // this sample does not hold: nothing begins here
    }
    if (!begins) return step;
    TriggeredSpan span;
    span.trigger = index;
    const std::uint64_t back = std::max(*m_firstSeen, m_lastEnd);
    span.first = index >= back + m_pre ? index - m_pre : back;
    m_open = span;
    step.started = span;
    m_state = TriggerState::Triggered;
    return step;
}

}  // namespace tactiscope::core::trigger
