// A calibration sweep as it is recorded in a wizard (issue 40): the beam's
// capacitance and the reference force, each read from its device's live
// buffer from the moment the recording starts, and on Finish paired on the
// beam's own time axis — the reference's times carried over through the
// host's clock by the two devices' mappings (the same device: as they are).
// What the pairing rests on (the two clocks' relative uncertainty) goes
// with it.
#pragma once

#include "core/LiveBuffer.h"
#include "core/calibration/ReferencePairing.h"
#include "core/timing/ClockAlignment.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace tactiscope::ui {

struct SweepChannel {
    std::shared_ptr<const core::LiveBuffer> buffer;
    std::size_t channel = 0;
    double scale = 1.0;  // SI units per stored unit
};

class SweepCapture {
public:
    // Reads from each buffer's newest sample on.
    SweepCapture(SweepChannel beam, SweepChannel reference);

    // Takes what came since the last call.
    void poll();

    std::size_t beamSamples() const { return m_beamValue.size(); }
    // The reference now and at its highest, from its first second's mean
    // (nothing on it yet); none before a second of it.
    std::optional<double> referenceNow_n() const;
    std::optional<double> referencePeak_n() const;
    // Whether the sweep went up by `rise` and came back to within `rest` of
    // its start for the last `settled_s` seconds: it is over.
    bool backAtRest(double rise_n, double rest_n, double settled_s) const;
    bool sameDevice() const { return m_beam.buffer == m_reference.buffer; }

    struct Paired {
        core::calibration::PairedSweep sweep;
        std::optional<double> clockUncertainty_s;  // 0 on one device
    };
    // Throws std::invalid_argument when the two devices' clocks are not
    // both mapped, or the samples do not overlap.
    Paired pair(const std::optional<core::timing::ClockMapping>& beamClock,
                const std::optional<core::timing::ClockMapping>& referenceClock, double referenceRate_hz) const;

private:
    std::optional<double> referenceStart_n() const;

    SweepChannel m_beam, m_reference;
    core::LiveCursor m_beamCursor, m_referenceCursor;
    core::LiveChunk m_chunk;
    std::vector<double> m_beamTime, m_beamValue, m_referenceTime, m_referenceValue;
};

}  // namespace tactiscope::ui
