// Counting clipped samples: by the known range, or by flat runs at the extremes.
#include "core/dsp/ClipCount.h"

#include <cmath>

namespace tactiscope::core::dsp {
namespace {

constexpr std::uint64_t kClippedRun = 3;

}  // namespace

void ClipCounter::push(double value)
{
    if (!std::isfinite(value)) {
        endRun();
        return;
    }
    if (m_range) {
        if (value <= m_range->low || value >= m_range->high) ++m_beyondRange;
        return;
    }
    ++m_samples;
    if (value == m_runValue) {
        ++m_runLength;
        ++m_repeats;
    } else {
        endRun();
        m_runValue = value;
        m_runLength = 1;
    }
    // A new extreme forgets the runs at the old one: only the recording's
    // own extremes count.
    if (value > m_top) {
        m_top = value;
        m_atTop = 0;
    }
    if (value < m_bottom) {
        m_bottom = value;
        m_atBottom = 0;
    }
}

void ClipCounter::endRun()
{
    if (m_runLength >= kClippedRun) {
        if (m_runValue == m_top) m_atTop += m_runLength;
        if (m_runValue == m_bottom) m_atBottom += m_runLength;
    }
    m_runLength = 0;
    m_runValue = std::numeric_limits<double>::quiet_NaN();
}

std::uint64_t ClipCounter::clipped() const
{
    if (m_range) return m_beyondRange;
    ClipCounter ended = *this;
    ended.endRun();
    if (!(ended.m_top > ended.m_bottom)) return 0;  // flat
    const std::uint64_t atExtremes = ended.m_atTop + ended.m_atBottom;
    const std::uint64_t repeatsElsewhere = ended.m_repeats > atExtremes ? ended.m_repeats - atExtremes : 0;
    if (100 * repeatsElsewhere > ended.m_samples) return 0;  // repeats anyway: runs tell nothing
    return atExtremes;
}

}  // namespace tactiscope::core::dsp
