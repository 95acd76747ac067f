// The fuzzing entry points, shared by the libFuzzer targets (fuzz preset,
// clang) and the ordinary test that replays the kept corpus with any
// compiler. Each decoder's runs one input the way a port would deliver it:
// in chunks whose sizes come from the input itself. The CSV reader's reads
// one input as a file another program wrote.
#pragma once

#include <cstddef>
#include <cstdint>

namespace tactiscope::fuzz {

void binaryStream(const std::uint8_t* data, std::size_t size);
void textStream(const std::uint8_t* data, std::size_t size);
void csvReader(const std::uint8_t* data, std::size_t size);  // CsvFuzzEntryPoint.cpp
void storeFile(const std::uint8_t* data, std::size_t size);  // StoreFuzzEntryPoint.cpp

}  // namespace tactiscope::fuzz
