// LineRate: a text board's rate from its own clock or from the arrivals.
#include "devices/protocol/LineRate.h"

#include "core/timing/ClockAlignment.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

namespace tactiscope::devices::protocol {

namespace {

// The coarsest step every stamp is a whole number of (1, 0.1, … 1e-6
// units): what a board's time is known to.
double resolutionOf(const std::vector<double>& stamps)
{
    for (const double step : {1.0, 0.1, 0.01, 1e-3, 1e-4, 1e-5, 1e-6}) {
        const bool whole = std::ranges::all_of(stamps, [step](double v) {
            const double steps = v / step;
            return std::abs(steps - std::round(steps)) <= 1e-6 * std::max(1.0, std::abs(steps));
        });
        if (whole) return step;
    }
    return 1e-6;
}

// A rate's standard uncertainty from the fit's (relative) and the host's
// wandering delay level, independent at the window's two ends.
double withHostWander(double rate_hz, double fitU, double span_s)
{
    return rate_hz * std::hypot(fitU, std::sqrt(2.0) * LineRate::kHostWander_s / span_s);
}

}  // namespace

void LineRate::add(double arrival_s, const std::optional<BoardTime>& boardTime)
{
    m_arrivals.push_back(arrival_s);
    if (!boardTime) {
        m_everyLineTimed = false;
        m_boardTimes.clear();
    } else if (m_everyLineTimed)
        m_boardTimes.push_back(*boardTime);
}

std::optional<LineRateEstimate> LineRate::estimate() const
{
    if (auto byBoard = fromBoardClock()) return byBoard;
    return fromArrivals();
}

bool LineRate::settled()
{
    if (static_cast<double>(m_arrivals.size()) <= kPeriods || m_arrivals.back() - m_arrivals.front() < kWindow_s)
        return false;  // without fitting anything
    if (10 * m_arrivals.size() < 11 * m_linesLookedAt) return false;
    m_linesLookedAt = m_arrivals.size();
    const auto rate = estimate();
    if (!rate || static_cast<double>(rate->lines) <= kPeriods || rate->span_s < kWindow_s) return false;
    return (rate->u_hz && *rate->u_hz <= kSettledU * rate->rate_hz) || rate->span_s >= kLongestWindow_s;
}

std::optional<LineRateEstimate> LineRate::fromBoardClock() const
{
    if (!m_everyLineTimed || m_boardTimes.size() < 3) return std::nullopt;
    std::vector<double> stamps;
    for (const auto& time : m_boardTimes) stamps.push_back(time.value);
    std::vector<double> steps;
    for (std::size_t i = 1; i < stamps.size(); ++i) {
        // A clock that stands or goes back (a restart, a wrap) times nothing.
        if (!(stamps[i] > stamps[i - 1])) return std::nullopt;
        steps.push_back(stamps[i] - stamps[i - 1]);
    }
    auto sorted = steps;
    std::ranges::nth_element(sorted, sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2));
    const double typical = sorted[sorted.size() / 2];
    // A step of several periods is lines lost in between: they were sent.
    double periods = 0.0;
    for (const double step : steps) periods += std::max(1.0, std::round(step / typical));
    const double spanUnits = stamps.back() - stamps.front();
    const double hostSpan_s = m_arrivals.back() - m_arrivals.front();
    double secondsPerUnit = m_boardTimes.front().seconds_per_unit.value_or(0.0);
    if (secondsPerUnit <= 0.0) {
        if (!(hostSpan_s > 0.0)) return std::nullopt;
        // Of s, ms and µs, the unit whose span is nearest the host's.
        const double ratio = spanUnits / hostSpan_s;
        const std::array<double, 3> unitsPerSecond{1.0, 1e3, 1e6};
        const auto nearest =
            std::ranges::min_element(unitsPerSecond, {}, [ratio](double u) { return std::abs(std::log(ratio / u)); });
        secondsPerUnit = 1.0 / *nearest;
    }
    LineRateEstimate rate;
    rate.boardClock = true;
    rate.boardSecondsPerUnit = secondsPerUnit;
    rate.rate_hz = periods / (spanUnits * secondsPerUnit);
    // The span's two ends are each known to the stamps' resolution: uniform
    // errors of ± half a step, q²/12 each.
    rate.u_hz = rate.rate_hz * resolutionOf(stamps) / std::sqrt(6.0) / spanUnits;
    rate.lines = m_arrivals.size();
    rate.span_s = hostSpan_s;
    return rate;
}

std::optional<LineRateEstimate> LineRate::fromArrivals() const
{
    // What arrives in the first moments may have waited in the port (a
    // backlog read at once, however many reads it takes): not timed.
    const auto settledFrom = std::ranges::upper_bound(m_arrivals, m_arrivals.front() + kBacklog_s);
    const auto skipped = static_cast<std::size_t>(settledFrom - m_arrivals.begin());
    const std::span<const double> arrivals(m_arrivals.begin() + static_cast<std::ptrdiff_t>(skipped), m_arrivals.end());
    if (arrivals.size() < 3) return std::nullopt;
    const double span_s = arrivals.back() - arrivals.front();
    if (!(span_s > 0.0)) return std::nullopt;
    // Line i is stamped i steps; a short window is stretched so that its
    // steps fill the mapping's segments (a linear change of its device
    // axis, which its drift undoes).
    const double stretch =
        std::max(1.0, 1.2 * static_cast<double>(core::timing::kClockSegments) * core::timing::kClockBin_s / span_s);
    const double step_s = stretch * span_s / static_cast<double>(arrivals.size() - 1);
    core::timing::ClockAlignment alignment(1.0 / stretch - 1.0);
    for (std::size_t i = 0; i < arrivals.size(); ++i) alignment.add(static_cast<double>(i) * step_s, arrivals[i]);
    const auto mapping = alignment.mapping();
    if (!mapping) return std::nullopt;
    // The lines the mapping found on time, from the first of its span: a
    // board catching up on what it could not send while nobody read (its
    // lags falling a period per period) is set aside by it, and the rate
    // is timed, and settles, on the rest. (The span runs between bins'
    // fastest lines: up to two bins short of the lines' even when none
    // was set aside.)
    const double lastStep = static_cast<double>(arrivals.size() - 1);
    const double setAside_s = lastStep * step_s - mapping->span_s;
    const auto onTime = setAside_s > 2.0 * core::timing::kClockBin_s
                            ? static_cast<std::size_t>(std::clamp(std::floor(setAside_s / step_s), 0.0, lastStep))
                            : std::size_t{0};
    LineRateEstimate rate;
    rate.lines = arrivals.size() - onTime;
    rate.span_s = arrivals.back() - arrivals[onTime];
    if (mapping->basis != core::timing::ClockUncertaintyBasis::TooFewFrames) {
        // Host seconds per step is 1 + drift.
        const double period_s = step_s * (1.0 + mapping->drift);
        if (!(period_s > 0.0)) return std::nullopt;
        rate.rate_hz = 1.0 / period_s;
        rate.u_hz = withHostWander(rate.rate_hz, mapping->drift_u / (1.0 + mapping->drift), rate.span_s);
        return rate;
    }
    // Too few lines for the mapping to state its uncertainty: a straight
    // line through the arrivals, each as late as chance made it, after
    // those the hull shows were held up far beyond the rest (a backlog, a
    // stalled read) are set aside. Its slope's standard error, widened for
    // the few lines (Student's t has variance ν/(ν−2)), is the uncertainty.
    std::vector<double> above;
    for (std::size_t i = onTime; i < arrivals.size(); ++i)
        above.push_back(arrivals[i] - mapping->host_s(static_cast<double>(i) * step_s));
    auto sorted = above;
    std::ranges::nth_element(sorted, sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2));
    const double heldUp_s = 5.0 * sorted[sorted.size() / 2] + 1e-6;
    const auto heldUp = [&](std::size_t i) { return above[i - onTime] > heldUp_s; };
    double n = 0.0, meanX = 0.0, meanY = 0.0;
    for (std::size_t i = onTime; i < arrivals.size(); ++i) {
        if (heldUp(i)) continue;
        n += 1.0;
        meanX += (static_cast<double>(i) - meanX) / n;
        meanY += (arrivals[i] - meanY) / n;
    }
    if (n < 5.0) return std::nullopt;
    double sxx = 0.0, sxy = 0.0;
    for (std::size_t i = onTime; i < arrivals.size(); ++i) {
        if (heldUp(i)) continue;
        sxx += (static_cast<double>(i) - meanX) * (static_cast<double>(i) - meanX);
        sxy += (static_cast<double>(i) - meanX) * (arrivals[i] - meanY);
    }
    const double period_s = sxy / sxx;
    if (!(period_s > 0.0)) return std::nullopt;
    double squares = 0.0;
    for (std::size_t i = onTime; i < arrivals.size(); ++i) {
        if (heldUp(i)) continue;
        const double e = arrivals[i] - meanY - period_s * (static_cast<double>(i) - meanX);
        squares += e * e;
    }
    const double dof = n - 2.0;
    const double periodU_s = std::sqrt(squares / dof / sxx * dof / (dof - 2.0));
    rate.rate_hz = 1.0 / period_s;
    rate.u_hz = withHostWander(rate.rate_hz, periodU_s / period_s, rate.span_s);
    return rate;
}

}  // namespace tactiscope::devices::protocol
