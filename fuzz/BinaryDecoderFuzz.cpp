// libFuzzer target: the TSP/1 binary decoder and stream.
#include "FuzzEntryPoints.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    tactiscope::fuzz::binaryStream(data, size);
    return 0;
}
