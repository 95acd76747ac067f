// libFuzzer target: the Serial-Plotter text decoder and stream.
#include "FuzzEntryPoints.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    tactiscope::fuzz::textStream(data, size);
    return 0;
}
