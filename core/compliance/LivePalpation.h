// Palpation on a live stream (seed 001): a sink on the acquisition thread
// that turns the compliance probe's two beam channels into forces, shows
// F_H, F_L and Q = F_H/F_L in a LiveBuffer, keeps the running k_o of the
// press in progress, and hands each completed press (PressReader) to the GUI.
//
// Channels and forces: PalpationForces, the same per-sample code a stored
// session's review and export run.
//
// Tare: the probe's zero is the mean of the first kTare_s of the stream
// that is steady (the probe is lifted when a stream starts, but a stream
// may start in the middle of a press: each beam's force moved by no more
// than the contact threshold, or no more than its own noise explains),
// with the standard error of that mean as its uncertainty (each press
// reading carries what it adds to the reading's uncertainty); while it is
// being taken no force is computed (the output is NaN). tare() is a rule, not a wish: it takes the
// mean of the last kTare_s already seen as the new zero only when the probe
// is not pressing and both beams stayed within the contact threshold over
// that stretch, and otherwise says why not and changes nothing, so a zero is
// never taken under a load. A press in progress is dropped rather than read
// across two zeros. Lost samples end
// a press in progress without a reading; what follows the gap is read as a
// press of its own, so a reading never spans a gap.
#pragma once

#include "core/BlockSink.h"
#include "core/ChannelDescriptor.h"
#include "core/LiveBuffer.h"
#include "core/compliance/PalpationForces.h"
#include "core/compliance/StiffnessReadings.h"
#include "core/signal/SteadyWindow.h"

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace tactiscope::core::compliance {

// A zero taken (the first, or a tare) and the first stream sample read on it.
struct ZeroChange {
    std::uint64_t firstIndex = 0;
    RawZero zero;
    double time_s = 0.0;  // the stream time of firstIndex
    // Why, where the record must say it: a zero taken again because the
    // one before was taken under a load (empty for a first zero, a tare).
    std::string note;
};

// What the display shows between presses and while pressing.
struct PalpationState {
    bool taring = true;
    bool pressing = false;
    std::optional<double> pressStart_s;  // while pressing, in stream time
    // While pressing: the mean k_o so far and its standard error, N/m.
    std::optional<std::pair<double, double>> current;
    // While pressing: the samples so far at each beam's ADC limit (a
    // clipped press reads no number: "press less deep").
    BeamLimits atLimit;
};

class LivePalpation final : public BlockSink {
public:
    static constexpr double kTare_s = 0.5;
    // A beam whose means before and after a point of the window differ by
    // this many of their standard errors moved (a ramp, a press), whatever
    // its spread (SteadyWindow::stepScore).
    static constexpr double kSteadyScore = 6.0;

    // Throws std::invalid_argument when the channels lack a displacement or
    // two beams, or for a non-physical probe.
    LivePalpation(const std::vector<ChannelDescriptor>& channels, double sampleRate_hz,
                  const LivePalpationSettings& settings, double displaySeconds);

    // The channels of output(): F_H and F_L in N (NaN while taring), and Q
    // (NaN unless both forces are above the contact threshold), named for
    // a display that has no subscripts: "F stiff", "F soft", "Q".
    static std::vector<ChannelDescriptor> outputChannels();
    const sensors::CompliancePair& pair() const { return m_forces.pair(); }
    // The gauge factor that turns a beam's counts into strain; none when
    // the device sends strain or force itself.
    std::optional<double> gaugeFactor(bool highBeam) const { return m_forces.gaugeFactor(highBeam); }
    // One beam calibrated and the other not (mixedCalibration()): what to say.
    const std::optional<std::string>& mixedCalibrationWarning() const { return m_mixedCalibration; }
    // A beam in counts whose clipping is not judged (PalpationForces).
    std::optional<std::string> unjudgedClipping() const { return m_forces.unjudgedClipping(); }

    // Any thread: the last kTare_s become the zero (see above); nothing when
    // taken, else the reason, in words for the operator.
    std::optional<std::string> tare();
    // Before it is fed: go on from `previous`'s zero (if it had one yet)
    // instead of taking a first one. The raw zero is the beams' counts, so
    // it holds for any profile of the same device.
    void inheritZero(const LivePalpation& previous);

    // Acquisition thread.
    void consume(const SampleBlock& block) override;

    std::shared_ptr<const LiveBuffer> output() const { return m_output; }
    PalpationState state() const;
    // Presses completed since the last call, in time order.
    std::vector<PressReading> takeReadings();
    // Any thread: the zero in use (none while the first is taken), and the
    // zeros taken since the last call, in order, for a recording to store.
    std::optional<ZeroChange> currentZero() const;
    std::vector<ZeroChange> takeZeroChanges();

private:
    void setZero(std::uint64_t firstIndex, double time_s, const RawZero& zero, std::string note = {});
    // Whether the stretch in the first-zero windows may be the zero.
    bool firstZeroSteady() const;

    PalpationForces m_forces;  // acquisition thread, but for the constant parts
    PressSettings m_pressSettings;
    std::optional<std::string> m_mixedCalibration;
    std::size_t m_tareSamples;
    std::shared_ptr<LiveBuffer> m_output;

    mutable std::mutex m_mutex;  // guards the members below
    PalpationState m_state;
    std::vector<PressReading> m_readings;
    // The last kTare_s without a gap: raw values for the zero, forces (on
    // the current zero) for judging it.
    signal::SteadyWindow m_rawHigh, m_rawLow, m_forceHigh, m_forceLow;
    std::optional<RawZero> m_pendingZero;
    std::string m_pendingZeroNote;  // its ZeroChange::note
    std::optional<ZeroChange> m_zero;
    std::vector<ZeroChange> m_zeroChanges;

    // Acquisition thread only.
    PressReader m_reader;
    std::optional<std::uint64_t> m_nextIndex;
    bool m_firstZeroTaken = false;
    signal::SteadyWindow m_firstHigh, m_firstLow;  // the latest kTare_s while it is not
    std::vector<PressReading> m_completed;
};

}  // namespace tactiscope::core::compliance
