// The capacitive beam on a live stream (seed 002): a sink on the acquisition
// thread that runs a CapacitiveReadout over the first capacitance channel,
// puts the force and the tip displacement into a LiveBuffer for the lanes
// (C itself is among the device's traces), and keeps the newest reading (C, C0, ΔC, ΔC/C0, F, w) for the large
// readouts.
//
// Zero: the beam is unloaded when a stream starts, so the baseline C0 is
// re-taken from the first kTare_s of the stream that is steady, by the
// tare rule below (the calibration's C0 is from another day; the baseline
// drifts; a stream may start while a weight is being placed). tare() is a rule: the mean of the last
// kTare_s becomes C0 only when that stretch is steady (no step within it
// beyond its noise, or its halves within 3σ of the calibrated baseline
// noise), so a
// weight being placed or lifted is never zeroed; otherwise it says why. A
// readout rebuilt for another profile or calibration re-takes nothing: it
// goes on from its predecessor's C0 (inheritBaseline).
#pragma once

#include "core/BlockSink.h"
#include "core/ChannelDescriptor.h"
#include "core/LiveBuffer.h"
#include "core/calibration/CalibrationRecord.h"
#include "core/capacitive/CapacitanceInput.h"
#include "core/capacitive/CapacitiveReadout.h"
#include "core/sensors/SensorProfile.h"
#include "core/signal/SteadyWindow.h"

#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tactiscope::core::capacitive {

// What a stored "capacitive" calibration record holds for the readout.
struct StoredCapacitiveCalibration {
    CapacitiveSensitivity sensitivity;
    double noiseSigma_f = 0.0;  // the baseline noise, for drift tracking
};

// From the record's values (c0_pf, baseline_sigma_pf, sensitivity_pf_per_mn
// and/or displacement_sensitivity_pf_per_mm); the one of the two
// sensitivities not calibrated comes from the other through the beam's k_s.
// Throws std::invalid_argument when the record lacks them.
StoredCapacitiveCalibration capacitiveCalibrationOf(const calibration::CalibrationRecord& record,
                                                    const sensors::CapacitiveBeam& beam);

// The readout's C0 as it changed (start tare, tare, a drift step) and the
// first stream sample read on it.
struct BaselineChange {
    std::uint64_t firstIndex = 0;
    double c0_f = 0.0;
};

// A baseline as a session stores it (storage::SessionZero): {"c0_f": …};
// and back (none when unreadable).
std::string baselineJson(double c0_f);
std::optional<double> baselineFromJson(const std::string& json);

// The readout of a capacitive beam: its calibration's sensitivity and
// baseline noise from the newest usable "capacitive" record for the beam
// among `calibrations` (its index in `used`, if given), else the beam model
// without drift tracking. Throws std::invalid_argument for a beam the model
// rejects; `problem` says why a record could not be used.
struct ReadoutSettings {
    CapacitiveSensitivity sensitivity;
    DriftSettings drift;
};
ReadoutSettings readoutSettings(const sensors::CapacitiveBeamProfile& probe,
                                std::span<const calibration::CalibrationRecord> calibrations,
                                std::optional<std::size_t>* used = nullptr, std::string* problem = nullptr);

class LiveCapacitive final : public BlockSink {
public:
    static constexpr double kTare_s = 0.5;
    // How far the means before and after any point of the tare window may
    // differ, in standard errors of their difference (SteadyWindow::
    // stepScore): a steady noisy signal's largest stays below 4.
    static constexpr double kSteadyScore = 6.0;

    // Throws std::invalid_argument without a capacitance channel, for one
    // in counts that `scales` (the profile's) give no capacitance scale, or
    // for non-positive sensitivities.
    LiveCapacitive(const std::vector<ChannelDescriptor>& channels, double sampleRate_hz,
                   const CapacitiveSensitivity& sensitivity, const DriftSettings& drift, double displaySeconds,
                   const sensors::ChannelScales& scales = {});

    // The channels of output(): force in N, tip displacement in m.
    static std::vector<ChannelDescriptor> outputChannels();

    // Any thread: the last kTare_s's mean becomes C0 (see above); nothing
    // when taken, else the reason, in words for the operator.
    std::optional<std::string> tare();
    // Before it is fed: go on from `previous`'s C0 once that one has taken
    // its start baseline, instead of taking one of its own.
    void inheritBaseline(const LiveCapacitive& previous);

    // Acquisition thread.
    void consume(const SampleBlock& block) override;

    std::shared_ptr<const LiveBuffer> output() const { return m_output; }
    // The newest reading; none before the first sample.
    std::optional<CapacitiveReading> latest() const;
    // Any thread: the C0 in use and the first stream sample read on it, and
    // the changes since the last call, for a recording to store.
    BaselineChange currentBaseline() const;
    std::vector<BaselineChange> takeBaselineChanges();

private:
    bool windowSteady() const;  // m_mutex held
    std::size_t m_channel = 0;
    CapacitanceInput m_input;  // its values to farads
    std::shared_ptr<LiveBuffer> m_output;
    double m_noiseSigma_f;

    mutable std::mutex m_mutex;  // guards the members below
    std::optional<CapacitiveReading> m_latest;
    signal::SteadyWindow m_window;  // the last kTare_s of capacitance
    std::optional<double> m_pendingC0_f;
    BaselineChange m_baseline;
    std::vector<BaselineChange> m_baselineChanges;
    bool m_startTaredSeen = false;  // m_startTared, for another thread

    // Acquisition thread only.
    CapacitiveReadout m_readout;
    bool m_startTared = false;
    std::uint64_t m_changesSeen = 0;  // the readout's baselineChanges() already recorded
};

}  // namespace tactiscope::core::capacitive
