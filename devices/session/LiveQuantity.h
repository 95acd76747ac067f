// A quantity a trigger or a limit watches, one value per sample of the
// stream: a device channel as it comes, or a mode's derived quantity
// (force, displacement, the detector's output), which the mode's processor
// writes, sample for sample, into its output buffer. Units name theirs
// (LiveModeUnit::quantities()); the session resolves a name to one of
// these. Read on the acquisition thread by the sinks after the processors
// (StreamWatch), so a derived value is there for the block just consumed.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/LiveBuffer.h"
#include "core/SampleBlock.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tactiscope::devices::session {

// A mode's derived quantity, as its unit offers it: the name the operator
// writes ("force"), its SI unit, and the processor's output channel.
struct LiveQuantity {
    std::string name;
    std::string unit;
    core::ChannelKind kind = core::ChannelKind::Other;  // how a view shows it (a force in mN)
    std::shared_ptr<const core::LiveBuffer> output;
    std::size_t channel = 0;
};

// Reads a quantity's values block by block; default-made, it reads none
// (NaN: a quantity that is gone).
class QuantityReader {
public:
    // A device channel, by its position in the block.
    static QuantityReader deviceChannel(std::size_t channel, std::string unit);
    // A processor's output, sample for sample with the device's blocks.
    static QuantityReader derived(const LiveQuantity& quantity);

    // The values of `block`'s samples, into `values` (one per sample):
    // NaN where a derived quantity has none (its processor was replaced
    // and the new one has not yet read this block).
    void read(const core::SampleBlock& block, std::vector<double>& values);
    const std::string& unit() const { return m_unit; }

private:
    bool m_device = false;
    std::size_t m_channel = 0;
    std::string m_unit;
    std::shared_ptr<const core::LiveBuffer> m_output;
    std::uint64_t m_outputSeen = 0;  // its samples written when last read
    core::LiveChunk m_chunk;
};

}  // namespace tactiscope::devices::session
