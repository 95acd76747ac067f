// Fuzz entry points: decoder, stream and payload parsers on arbitrary bytes.
#include "FuzzEntryPoints.h"

#include "devices/protocol/BinaryStream.h"
#include "devices/protocol/TextStream.h"

#include <span>

namespace tactiscope::fuzz {
namespace {

// Feeds `data` in chunks of 1…16 bytes, the sizes drawn from the data.
template <typename Feed>
void inChunks(const std::uint8_t* data, std::size_t size, Feed feed)
{
    std::size_t i = 0;
    std::uint8_t seed = size ? data[0] : 0;
    while (i < size) {
        seed = static_cast<std::uint8_t>(seed * 33 + 7);
        const std::size_t n = std::min<std::size_t>(1 + seed % 16, size - i);
        feed(std::span<const std::uint8_t>(data + i, n));
        i += n;
    }
}

}  // namespace

void binaryStream(const std::uint8_t* data, std::size_t size)
{
    devices::protocol::BinaryStream stream;
    devices::protocol::StreamOutput out;
    double t = 0.0;
    inChunks(data, size, [&](std::span<const std::uint8_t> chunk) {
        stream.push(chunk, t, out);
        t += 0.01;
    });
    // Whatever came out must be internally consistent.
    for (const auto& block : out.blocks) {
        if (block.values().size() != block.channelCount() * block.sampleCount()) __builtin_trap();
    }
    // The payload parsers on the raw input too.
    const std::vector<std::uint8_t> bytes(data, data + size);
    (void)devices::protocol::parseInfo(bytes);
    (void)devices::protocol::parseData(bytes);
    (void)devices::protocol::parseStatus(bytes);
    (void)devices::protocol::parseCommand(bytes);
}

void textStream(const std::uint8_t* data, std::size_t size)
{
    devices::protocol::TextStream stream(100.0);
    std::vector<core::SampleBlock> out;
    double t = 0.0;
    inChunks(data, size, [&](std::span<const std::uint8_t> chunk) {
        stream.push(chunk, t, out);
        t += 0.01;
    });
    // A board's layouts only grow: each block holds the channels known
    // when it began, never fewer than the one before, never more than all.
    std::size_t channels = 0;
    for (const auto& block : out) {
        if (block.channelCount() < channels || block.channelCount() > stream.channels().size()) __builtin_trap();
        channels = block.channelCount();
    }
}

}  // namespace tactiscope::fuzz
