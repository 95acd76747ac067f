// SweepCapture: two buffers read as they fill, paired through the host's clock.
#include "ui/modes/capacitive/SweepCapture.h"

#include <algorithm>
#include <stdexcept>

namespace tactiscope::ui {

SweepCapture::SweepCapture(SweepChannel beam, SweepChannel reference)
    : m_beam(std::move(beam)),
      m_reference(std::move(reference))
{
    m_beamCursor.next = m_beam.buffer->samplesWritten();
    m_referenceCursor.next = m_reference.buffer->samplesWritten();
}

void SweepCapture::poll()
{
    const auto take = [this](const SweepChannel& from, core::LiveCursor& cursor, std::vector<double>& time,
                             std::vector<double>& value) {
        while (from.buffer->readNew(cursor, m_chunk, 65536) > 0) {
            time.insert(time.end(), m_chunk.time_s.begin(), m_chunk.time_s.end());
            for (const double v : m_chunk.values[from.channel]) value.push_back(v * from.scale);
        }
    };
    take(m_beam, m_beamCursor, m_beamTime, m_beamValue);
    take(m_reference, m_referenceCursor, m_referenceTime, m_referenceValue);
}

std::optional<double> SweepCapture::referenceStart_n() const
{
    if (m_referenceTime.empty() || m_referenceTime.back() - m_referenceTime.front() < 1.0) return std::nullopt;
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < m_referenceTime.size() && m_referenceTime[i] - m_referenceTime.front() < 1.0; ++i, ++n)
        sum += m_referenceValue[i];
    return sum / static_cast<double>(n);
}

std::optional<double> SweepCapture::referenceNow_n() const
{
    const auto start = referenceStart_n();
    if (!start) return std::nullopt;
    return m_referenceValue.back() - *start;
}

std::optional<double> SweepCapture::referencePeak_n() const
{
    const auto start = referenceStart_n();
    if (!start) return std::nullopt;
    return *std::ranges::max_element(m_referenceValue) - *start;
}

bool SweepCapture::backAtRest(double rise_n, double rest_n, double settled_s) const
{
    const auto peak = referencePeak_n();
    if (!peak || *peak < rise_n) return false;
    const auto start = *referenceStart_n();
    const double since = m_referenceTime.back() - settled_s;
    for (std::size_t i = m_referenceTime.size(); i-- > 0 && m_referenceTime[i] >= since;)
        if (std::abs(m_referenceValue[i] - start) > rest_n) return false;
    // The peak must lie before that quiet stretch.
    const auto peakAt = std::ranges::max_element(m_referenceValue) - m_referenceValue.begin();
    return m_referenceTime[static_cast<std::size_t>(peakAt)] < since;
}

SweepCapture::Paired SweepCapture::pair(const std::optional<core::timing::ClockMapping>& beamClock,
                                        const std::optional<core::timing::ClockMapping>& referenceClock,
                                        double referenceRate_hz) const
{
    Paired result;
    if (sameDevice()) {
        result.sweep = core::calibration::pairWithReference(m_beamTime, m_beamValue, m_referenceTime, m_referenceValue,
                                                            referenceRate_hz);
        result.clockUncertainty_s = 0.0;
        return result;
    }
    if (!beamClock || !referenceClock)
        throw std::invalid_argument(
            "the two devices' clocks are not both known on the host's yet (a device that stamps no time, or too few "
            "frames so far), so their samples cannot be paired");
    // The reference's times on the beam's axis: its clock to the host's,
    // the host's to the beam's.
    std::vector<double> onBeam(m_referenceTime.size());
    for (std::size_t i = 0; i < onBeam.size(); ++i)
        onBeam[i] = beamClock->device_s(referenceClock->host_s(m_referenceTime[i]));
    result.sweep =
        core::calibration::pairWithReference(m_beamTime, m_beamValue, onBeam, m_referenceValue, referenceRate_hz);
    if (!m_beamTime.empty())
        result.clockUncertainty_s = core::timing::relativeUncertainty_s(
            *beamClock, *referenceClock, beamClock->host_s(m_beamTime.front()), beamClock->host_s(m_beamTime.back()));
    return result;
}

}  // namespace tactiscope::ui
