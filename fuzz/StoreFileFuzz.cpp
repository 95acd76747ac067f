// libFuzzer target: session store files handed over by someone else.
#include "FuzzEntryPoints.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    tactiscope::fuzz::storeFile(data, size);
    return 0;
}
