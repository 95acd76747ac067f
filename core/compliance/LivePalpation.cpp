// LivePalpation: channel roles, tare, forces per sample, press readings.
#include "core/compliance/LivePalpation.h"

#include "core/SampleBlock.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace tactiscope::core::compliance {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A force in whole millinewtons, as the operator reads it.
std::string milliNewtons(double n)
{
    return std::to_string(static_cast<long long>(std::lround(n * 1e3)));
}

// A zero of the beams' stretches: their means, known to their standard errors.
RawZero zeroOf(const signal::SteadyWindow& high, const signal::SteadyWindow& low)
{
    return {high.mean(), low.mean(), std::pair{high.standardErrorOfMean(), low.standardErrorOfMean()}};
}

}  // namespace

LivePalpation::LivePalpation(const std::vector<ChannelDescriptor>& channels, double sampleRate_hz,
                             const LivePalpationSettings& settings, double displaySeconds)
    : m_forces(channels, settings),
      m_pressSettings(settings.press),
      m_mixedCalibration(mixedCalibration(settings)),
      m_tareSamples(std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(kTare_s * sampleRate_hz)))),
      m_output(std::make_shared<LiveBuffer>(outputChannels().size(),
                                            static_cast<std::size_t>(std::ceil(displaySeconds * sampleRate_hz)) + 1)),
      m_rawHigh(std::max<std::size_t>(4, m_tareSamples)),
      m_rawLow(m_rawHigh.length()),
      m_forceHigh(m_rawHigh.length()),
      m_forceLow(m_rawHigh.length()),
      m_reader(m_forces.pair(), settings.press),
      m_firstHigh(m_rawHigh.length()),
      m_firstLow(m_rawHigh.length())
{
}

void LivePalpation::setZero(std::uint64_t firstIndex, double time_s, const RawZero& zero, std::string note)
{
    m_forces.setZero(zero);
    m_reader.setZeroUncertainty(m_forces.zeroUncertainty());
    const std::lock_guard lock(m_mutex);
    m_zero = ZeroChange{firstIndex, zero, time_s, std::move(note)};
    m_zeroChanges.push_back(*m_zero);
}

void LivePalpation::inheritZero(const LivePalpation& previous)
{
    const auto zero = previous.currentZero();
    if (!zero) return;  // it was still taking its first: so does this one
    m_forces.setZero(zero->zero);
    m_reader.setZeroUncertainty(m_forces.zeroUncertainty());
    m_firstZeroTaken = true;
    const std::lock_guard lock(m_mutex);
    m_zero = zero;
    m_state.taring = false;
}

std::optional<ZeroChange> LivePalpation::currentZero() const
{
    const std::lock_guard lock(m_mutex);
    return m_zero;
}

std::vector<ZeroChange> LivePalpation::takeZeroChanges()
{
    const std::lock_guard lock(m_mutex);
    return std::exchange(m_zeroChanges, {});
}

std::vector<ChannelDescriptor> LivePalpation::outputChannels()
{
    return {{"F stiff", "N", ChannelKind::Force}, {"F soft", "N", ChannelKind::Force}, {"Q", "", ChannelKind::Other}};
}

std::optional<std::string> LivePalpation::tare()
{
    const std::lock_guard lock(m_mutex);
    if (m_state.taring) return "the first zero is still being taken: keep the probe lifted and still";
    if (!m_forceHigh.full()) return "wait half a second: the signal since the last zero or gap is too short to judge";
    if (m_state.pressing)
        return "the probe is pressing (F_H " + milliNewtons(m_forceHigh.mean()) + " mN, F_L " +
               milliNewtons(m_forceLow.mean()) + " mN): lift it, then tare";
    const double moving = std::max(m_forceHigh.spread(), m_forceLow.spread());
    if (moving > m_pressSettings.contactThreshold_n)
        return "the beams are moving (their force changed by " + milliNewtons(moving) +
               " mN in the last half second): hold the probe lifted and still, then tare";
    m_pendingZero = zeroOf(m_rawHigh, m_rawLow);
    m_pendingZeroNote.clear();
    return std::nullopt;
}

void LivePalpation::consume(const SampleBlock& block)
{
    if (block.empty()) return;
    const bool gap = m_nextIndex && block.firstSampleIndex() != *m_nextIndex;
    std::optional<RawZero> newZero;
    std::string zeroNote;
    {
        const std::lock_guard lock(m_mutex);
        newZero = std::exchange(m_pendingZero, std::nullopt);
        zeroNote = std::exchange(m_pendingZeroNote, {});
        // A zero is judged on samples without a gap, on one zero.
        if (gap || newZero) {
            m_forceHigh.clear();
            m_forceLow.clear();
        }
        if (gap) {
            m_rawHigh.clear();
            m_rawLow.clear();
        }
    }
    m_nextIndex = block.endSampleIndex();
    // Drop a press in progress: it would be read across a gap or two zeros.
    if (gap || newZero) m_reader.dropPress();
    if (newZero) setZero(block.firstSampleIndex(), block.t0_s(), *newZero, std::move(zeroNote));
    // The first zero comes from samples without a gap: one a gap interrupted starts over.
    if (gap && !m_firstZeroTaken) {
        m_firstHigh.clear();
        m_firstLow.clear();
    }

    SampleBlock display(3, block.sampleCount(), block.t0_s(), block.dt_s(), block.firstSampleIndex(), block.sequence());
    for (std::size_t s = 0; s < block.sampleCount(); ++s) {
        const double high = block.value(m_forces.highChannel(), s);
        const double low = block.value(m_forces.lowChannel(), s);
        if (!m_firstZeroTaken) {
            m_firstHigh.push(high);
            m_firstLow.push(low);
            if (m_firstHigh.full() && firstZeroSteady()) {
                m_firstZeroTaken = true;
                setZero(block.firstSampleIndex() + s + 1, block.timeAt_s(s) + block.dt_s(),
                        zeroOf(m_firstHigh, m_firstLow));
            }
            for (std::size_t c = 0; c < 3; ++c) display.channel(c)[s] = kNaN;
            continue;
        }
        const double fHigh = m_forces.forceHigh(high);
        const double fLow = m_forces.forceLow(low);
        display.channel(0)[s] = fHigh;
        display.channel(1)[s] = fLow;
        display.channel(2)[s] = m_forces.q(fHigh, fLow);
        if (auto reading = m_reader.push(block.timeAt_s(s),
                                         m_forces.displacement_m(block.value(m_forces.displacementChannel(), s)), fHigh,
                                         fLow, m_forces.limitsOf(high, low)))
            m_completed.push_back(*reading);
    }
    m_output->consume(display);

    const std::lock_guard lock(m_mutex);
    for (std::size_t s = 0; s < block.sampleCount(); ++s) {
        m_rawHigh.push(block.value(m_forces.highChannel(), s));
        m_rawLow.push(block.value(m_forces.lowChannel(), s));
        if (std::isnan(display.channel(0)[s])) continue;  // no force while the first zero is taken
        m_forceHigh.push(display.channel(0)[s]);
        m_forceLow.push(display.channel(1)[s]);
    }
    // Forces that hold below zero, steadily, beyond the contact threshold
    // (no press pulls a beam) say the zero was taken under a load held
    // still (a stream that began in a press's hold): the probe is lifted
    // now, and this stretch becomes the zero. The record says so: what
    // was read before came from the wrong zero.
    const double threshold_n = m_pressSettings.contactThreshold_n;
    const auto steady = [&](const signal::SteadyWindow& force) {
        return force.spread() <= threshold_n || force.stepScore() <= kSteadyScore;
    };
    if (m_forceHigh.full() && m_rawHigh.full() && !m_pendingZero && !m_reader.pressing() &&
        std::min(m_forceHigh.mean(), m_forceLow.mean()) < -threshold_n && steady(m_forceHigh) && steady(m_forceLow)) {
        m_pendingZero = zeroOf(m_rawHigh, m_rawLow);
        m_pendingZeroNote = "the forces held at F_H " + milliNewtons(m_forceHigh.mean()) + " mN, F_L " +
                            milliNewtons(m_forceLow.mean()) +
                            " mN with the probe still, below any press: the zero before was taken under a load (a "
                            "stream begun in a press held still), and the forces and readings before here were read "
                            "from it; zeroed again here";
    }
    m_state.taring = !m_firstZeroTaken;
    m_state.pressing = m_reader.pressing();
    m_state.pressStart_s = m_reader.pressing() ? std::optional(m_reader.pressStart_s()) : std::nullopt;
    m_state.current = m_reader.current();
    m_state.atLimit = m_reader.pressAtLimit();
    m_readings.insert(m_readings.end(), m_completed.begin(), m_completed.end());
    m_completed.clear();
}

// Each beam: its force moved by no more than the contact threshold over
// the stretch, or no step within it beyond its noise (a noisy beam).
bool LivePalpation::firstZeroSteady() const
{
    const auto steady = [&](const signal::SteadyWindow& raw, bool highBeam) {
        return m_forces.forceOfChange(highBeam, raw.spread()) <= m_pressSettings.contactThreshold_n ||
               raw.stepScore() <= kSteadyScore;
    };
    return steady(m_firstHigh, true) && steady(m_firstLow, false);
}

PalpationState LivePalpation::state() const
{
    const std::lock_guard lock(m_mutex);
    return m_state;
}

std::vector<PressReading> LivePalpation::takeReadings()
{
    const std::lock_guard lock(m_mutex);
    return std::exchange(m_readings, {});
}

}  // namespace tactiscope::core::compliance
