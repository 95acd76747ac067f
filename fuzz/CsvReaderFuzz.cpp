// libFuzzer target: the CSV reader, on files other programs write.
#include "FuzzEntryPoints.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    tactiscope::fuzz::csvReader(data, size);
    return 0;
}
