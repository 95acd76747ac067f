// Uniform time-base check.
#include "core/io/UniformTimeBase.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace tactiscope::core::io {

double uniformSampleInterval(std::span<const double> t, double tolerance)
{
    UniformTimeBaseCheck check(tolerance);
    check.add(t);
    return check.interval_s();
}

void UniformTimeBaseCheck::add(std::span<const double> t)
{
    if (t.empty()) return;
    std::size_t row = 0;  // index in t of the sample checked against the one before
    if (m_count == 0) {
        if (t.size() < 2) throw TimeBaseError("at least two samples are needed to know the sampling interval", 0);
        std::vector<double> steps(t.size() - 1);
        for (std::size_t i = 1; i < t.size(); ++i) {
            steps[i - 1] = t[i] - t[i - 1];
            if (!(steps[i - 1] > 0.0)) throw TimeBaseError("time is not increasing", i);
        }
        // The median step is the reference: one odd step cannot move it, so
        // the error names the line that is actually wrong.
        std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
        m_typical = steps[steps.size() / 2];
        m_first = m_last = t.front();
        m_count = 1;
        row = 1;
    }
    for (; row < t.size(); ++row) {
        const double step = t[row] - m_last;
        if (!(step > 0.0)) throw TimeBaseError("time is not increasing", row);
        const double intervals = std::round(step / m_typical);
        if (m_gapsAllowed && intervals >= 2.0 && std::abs(step - intervals * m_typical) <= m_tolerance * m_typical) {
            m_afterGaps.push_back(m_count);
            m_missing += static_cast<std::uint64_t>(intervals) - 1;
            m_gapSpan_s += step;
        } else if (std::abs(step - m_typical) > m_tolerance * m_typical) {
            throw TimeBaseError("time is irregular: step of " + std::to_string(step) + " s where " +
                                    std::to_string(m_typical) + " s is expected" +
                                    (m_gapsAllowed ? " (nor a whole number of them, a gap)" : ""),
                                row);
        }
        m_last = t[row];
        ++m_count;
    }
}

double UniformTimeBaseCheck::interval_s() const
{
    if (m_count < 2 + m_afterGaps.size()) return 0.0;
    const auto steps = static_cast<double>(m_count - 1 - m_afterGaps.size());
    return (m_last - m_first - m_gapSpan_s) / steps;
}

}  // namespace tactiscope::core::io
