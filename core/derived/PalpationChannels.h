// A stored palpation session's physical quantities — F_H and F_L in N, Q,
// and k_o in N/m while in contact — computed from its raw samples, its
// stored profile and gauge-factor calibrations, and the zeros it recorded,
// by the very code the live view runs (compliance::PalpationForces). So the
// review and an export show what the operator saw, sample for sample.
//
// Reading only what is shown: the forces are increasing functions of one
// raw channel each, so a stretch's force extremes are the force of its raw
// extremes; overview() maps the store's min/max pyramid through them
// (exact, and cheap for hours) wherever a stretch lies on one zero, and
// reads exact samples for a stretch that spans a zero change. Q and k_o
// depend on two channels at once: they come from exact samples only, so
// their overview is empty for a range of more than kExactLimit samples
// (the review says to zoom in).
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/compliance/PalpationForces.h"
#include "core/storage/SessionExport.h"
#include "core/storage/SessionStore.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tactiscope::core::derived {

class PalpationChannels final : public storage::ComputedColumns {
public:
    static constexpr std::uint64_t kExactLimit = 200'000;  // samples per channel

    // Throws std::invalid_argument for a session that is not a palpation
    // one, or whose profile or channels cannot give forces (the message
    // says which); storage::StorageError when the store cannot be read.
    PalpationChannels(storage::SessionSource& store, std::int64_t session);

    // force_high [N], force_low [N], Q, stiffness [N/m].
    std::vector<ChannelDescriptor> channels() const override;
    // The stored channels the beams' forces come from.
    std::size_t highChannel() const { return m_forces->highChannel(); }
    std::size_t lowChannel() const { return m_forces->lowChannel(); }
    // What the forces were computed with, in words: the profile and each
    // beam's gauge factor (calibrated or nominal).
    std::string basis() const override { return m_basis; }

    // Exact values of samples [first, first + count) of every derived
    // channel, clipped to the session: NaN in gaps, before the first zero,
    // and for Q and k_o out of contact or out of range.
    std::vector<std::vector<double>> read(std::uint64_t first, std::uint64_t count) override;

    // About `points` min/max stretches of one derived channel over the range
    // (see above for how each is computed).
    std::vector<storage::OverviewPoint> overview(std::size_t channel, std::uint64_t first, std::uint64_t count,
                                                 std::size_t points);

private:
    struct Span {  // samples read on one zero
        std::uint64_t first = 0;
        std::uint64_t end = 0;
        double rawHigh = 0.0, rawLow = 0.0;
    };
    // The forces object set to the zero that reads sample `index`, if any.
    const compliance::PalpationForces* forcesAt(std::uint64_t index);

    storage::SessionSource& m_store;
    std::int64_t m_session;
    std::uint64_t m_sampleCount = 0;
    std::unique_ptr<compliance::PalpationForces> m_forces;
    std::vector<Span> m_spans;  // in order; samples before the first have no force
    const Span* m_current = nullptr;
    std::string m_basis;
};

}  // namespace tactiscope::core::derived
