// A stored capacitive session's physical quantities — ΔC in F, ΔC/C0, the
// tip force in N and deflection in m — computed from its capacitance
// samples (a board's counts through its profile's scale,
// capacitive/CapacitanceInput.h), the calibration it carries (else the
// beam model of its profile) and the baselines C0 it recorded, by the live readout's own
// formulas (capacitive::CapacitiveReadout::readingAt). Each is C − C0
// scaled by a positive constant on one baseline, so the overview maps the
// store's min/max pyramid through it, and reads exact samples only for a
// stretch across a baseline change.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/calibration/CalibrationRecord.h"
#include "core/capacitive/CapacitanceInput.h"
#include "core/capacitive/CapacitiveReadout.h"
#include "core/storage/SessionExport.h"
#include "core/storage/SessionStore.h"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tactiscope::core::derived {

class CapacitiveChannels final : public storage::ComputedColumns {
public:
    // Through the calibration recorded with the session, else the beam
    // model; or through `calibration` (a re-analysis with another record).
    // Throws std::invalid_argument for a session that is not a capacitive
    // one, lacks a usable profile, or a `calibration` that is not this
    // beam's or cannot be used (the message says which);
    // storage::StorageError when the store cannot be read.
    CapacitiveChannels(storage::SessionSource& store, std::int64_t session,
                       const std::optional<calibration::CalibrationRecord>& calibration = std::nullopt);

    // delta_c [F], relative_change, force [N], deflection [m].
    std::vector<ChannelDescriptor> channels() const override;
    std::string basis() const override { return m_basis; }
    std::size_t capacitanceChannel() const { return m_channel; }
    // The calibration record the readings went through; none: the beam model.
    const std::optional<calibration::CalibrationRecord>& calibration() const { return m_calibration; }
    const capacitive::CapacitiveSensitivity& sensitivity() const { return m_sensitivity; }
    // Each baseline C0 (F) and the first sample read on it, in order.
    std::vector<std::pair<std::uint64_t, double>> baselines() const;

    std::vector<std::vector<double>> read(std::uint64_t first, std::uint64_t count) override;
    std::vector<storage::OverviewPoint> overview(std::size_t channel, std::uint64_t first, std::uint64_t count,
                                                 std::size_t points);

private:
    struct Span {  // samples read on one C0
        std::uint64_t first = 0;
        std::uint64_t end = 0;
        double c0_f = 0.0;
    };
    const Span* spanAt(std::uint64_t index) const;
    double value(std::size_t channel, double capacitance_f, double c0_f) const;

    storage::SessionSource& m_store;
    std::int64_t m_session;
    std::uint64_t m_sampleCount = 0;
    std::size_t m_channel = 0;
    capacitive::CapacitanceInput m_input;  // its stored values to farads
    capacitive::CapacitiveSensitivity m_sensitivity;
    std::optional<calibration::CalibrationRecord> m_calibration;
    std::vector<Span> m_spans;
    std::string m_basis;
};

}  // namespace tactiscope::core::derived
