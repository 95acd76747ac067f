// A path in the temporary folder that no other test process uses: for
// emulator links, pseudo-terminal tests and store files.
#pragma once

#include <filesystem>
#include <string>
#include <unistd.h>

namespace tactiscope::testing {

inline std::string uniqueTempPath(const std::string& name)
{
    return (std::filesystem::temp_directory_path() / ("tactiscope-" + std::to_string(::getpid()) + "-" + name))
        .string();
}

}  // namespace tactiscope::testing
