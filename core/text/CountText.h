// A count with its noun for the program's one-line summaries: "1 defect",
// "20 defects". English only: these lines are read by people and tools
// alike (the CLI's output), never translated.
#pragma once

#include <cstddef>
#include <string>

namespace tactiscope::core::text {

inline std::string countText(std::size_t n, const char* one, const char* many)
{
    return std::to_string(n) + ' ' + (n == 1 ? one : many);
}

}  // namespace tactiscope::core::text
