// Chunk encoding: binary32, little-endian, channel-major.
#include "core/storage/ChunkCodec.h"

#include "core/SampleBlock.h"
#include "core/storage/Database.h"

#include <bit>
#include <string>

namespace tactiscope::core::storage {

void putBinary32(float value, std::uint8_t* out)
{
    const auto bits = std::bit_cast<std::uint32_t>(value);
    for (int b = 0; b < 4; ++b) out[b] = static_cast<std::uint8_t>(bits >> (8 * b));
}

float getBinary32(const std::uint8_t* in)
{
    std::uint32_t bits = 0;
    for (int b = 0; b < 4; ++b) bits |= static_cast<std::uint32_t>(in[b]) << (8 * b);
    return std::bit_cast<float>(bits);
}

std::vector<std::uint8_t> encodeChunk(std::span<const SampleBlock> blocks)
{
    if (blocks.empty()) return {};
    std::size_t samples = 0;
    for (const SampleBlock& block : blocks) samples += block.sampleCount();
    const std::size_t channels = blocks.front().channelCount();
    std::vector<std::uint8_t> bytes(channels * samples * 4);
    std::uint8_t* out = bytes.data();
    for (std::size_t c = 0; c < channels; ++c) {
        for (const SampleBlock& block : blocks) {
            for (const double value : block.channel(c)) {
                putBinary32(static_cast<float>(value), out);
                out += 4;
            }
        }
    }
    return bytes;
}

std::vector<std::uint8_t> encodeChunk(const SampleBlock& block)
{
    return encodeChunk(std::span(&block, 1));
}

void decodeChunkChannel(std::span<const std::uint8_t> blob, std::size_t channels, std::size_t samples,
                        std::size_t channel, std::size_t first, std::span<double> out)
{
    const std::size_t count = out.size();
    if (blob.size() != channels * samples * 4 || channel >= channels || first + count > samples)
        throw StoreInputError("a sample chunk has " + std::to_string(blob.size()) + " bytes, not the " +
                              std::to_string(channels * samples * 4) + " its header promises; the store is damaged");
    const std::uint8_t* in = blob.data() + (channel * samples + first) * 4;
    for (std::size_t s = 0; s < count; ++s, in += 4) out[s] = static_cast<double>(getBinary32(in));
}

}  // namespace tactiscope::core::storage
