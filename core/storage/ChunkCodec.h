// How a chunk of samples is stored in a BLOB: channel-major (all samples of
// channel 0, then channel 1, …), each sample an IEEE-754 binary32 in
// little-endian byte order, whatever the host. Binary32 keeps 24 bits of
// mantissa, more than any bridge ADC or capacitance-to-digital converter of
// these probes resolves, at half the size of binary64.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace tactiscope::core {
class SampleBlock;
}

namespace tactiscope::core::storage {

// One chunk from consecutive blocks of the same channels, as if they were
// one block: channel 0 of every block, then channel 1, …
std::vector<std::uint8_t> encodeChunk(std::span<const SampleBlock> blocks);
std::vector<std::uint8_t> encodeChunk(const SampleBlock& block);

// One sample in the chunk and pyramid encoding.
void putBinary32(float value, std::uint8_t* out);
float getBinary32(const std::uint8_t* in);

// Writes samples [first, first + out.size()) of channel `channel` of a
// chunk with `channels` channels and `samples` samples per channel to
// `out`. Throws StorageError when the BLOB's size does not match.
void decodeChunkChannel(std::span<const std::uint8_t> blob, std::size_t channels, std::size_t samples,
                        std::size_t channel, std::size_t first, std::span<double> out);

}  // namespace tactiscope::core::storage
