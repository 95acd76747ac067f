// The decoders' fuzzing entry points, shared by the libFuzzer targets (fuzz
// preset, clang) and the ordinary test that replays the kept corpus with any
// compiler. Each runs one input through a decoder the way a port would
// deliver it: in chunks whose sizes come from the input itself.
#pragma once

#include <cstddef>
#include <cstdint>

namespace tactiscope::fuzz {

void binaryStream(const std::uint8_t* data, std::size_t size);
void textStream(const std::uint8_t* data, std::size_t size);

}  // namespace tactiscope::fuzz
