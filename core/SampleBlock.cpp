// SampleBlock construction checks and channel access.
#include "core/SampleBlock.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace tactiscope::core {

SampleBlock::SampleBlock(std::size_t channelCount, std::size_t sampleCount, double t0_s, double dt_s,
                         std::uint64_t firstSampleIndex, std::uint32_t sequence)
    : m_channelCount(channelCount),
      m_sampleCount(sampleCount),
      m_t0_s(t0_s),
      m_dt_s(dt_s),
      m_firstSampleIndex(firstSampleIndex),
      m_sequence(sequence)
{
    if (channelCount == 0) throw std::invalid_argument("SampleBlock needs at least one channel");
    if (!(std::isfinite(dt_s) && dt_s > 0.0))
        throw std::invalid_argument("SampleBlock sample interval must be positive, got " + std::to_string(dt_s));
    if (!std::isfinite(t0_s)) throw std::invalid_argument("SampleBlock start time must be finite");
    m_values.assign(channelCount * sampleCount, 0.0);
}

std::span<double> SampleBlock::channel(std::size_t c)
{
    if (c >= m_channelCount) throw std::out_of_range("SampleBlock channel index out of range");
    return std::span<double>(m_values).subspan(c * m_sampleCount, m_sampleCount);
}

std::span<const double> SampleBlock::channel(std::size_t c) const
{
    if (c >= m_channelCount) throw std::out_of_range("SampleBlock channel index out of range");
    return std::span<const double>(m_values).subspan(c * m_sampleCount, m_sampleCount);
}

}  // namespace tactiscope::core
