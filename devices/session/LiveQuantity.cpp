// QuantityReader: a device channel from the block itself, a derived
// quantity from the newest samples of its processor's output.
#include "devices/session/LiveQuantity.h"

#include <algorithm>
#include <limits>

namespace tactiscope::devices::session {

QuantityReader QuantityReader::deviceChannel(std::size_t channel, std::string unit)
{
    QuantityReader reader;
    reader.m_device = true;
    reader.m_channel = channel;
    reader.m_unit = std::move(unit);
    return reader;
}

QuantityReader QuantityReader::derived(const LiveQuantity& quantity)
{
    QuantityReader reader;
    reader.m_channel = quantity.channel;
    reader.m_unit = quantity.unit;
    reader.m_output = quantity.output;
    reader.m_outputSeen = quantity.output->samplesWritten();
    return reader;
}

void QuantityReader::read(const core::SampleBlock& block, std::vector<double>& values)
{
    const std::size_t count = block.sampleCount();
    if (m_device) {
        const auto channel = block.channel(m_channel);
        values.assign(channel.begin(), channel.end());
        return;
    }
    values.assign(count, std::numeric_limits<double>::quiet_NaN());
    if (!m_output) return;
    // The processor ran on this block just before: its output grew by the
    // block's samples. Anything else (a processor replaced, a block it
    // skipped) leaves these samples without a value rather than misplaced.
    const std::uint64_t written = m_output->samplesWritten();
    const std::uint64_t grown = written - std::min(written, m_outputSeen);
    m_outputSeen = written;
    if (grown != count || written < count) return;
    core::LiveCursor cursor{written - count, 0};
    if (m_output->readNew(cursor, m_chunk, count) != count || cursor.overrun != 0) return;
    std::copy(m_chunk.values[m_channel].begin(), m_chunk.values[m_channel].end(), values.begin());
}

}  // namespace tactiscope::devices::session
