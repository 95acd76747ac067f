// A part's stored clock mapping in words, as the command line and the
// review show it: where the device's first sample lies on the session's
// clock, how fast its crystal ran, each with its uncertainty and what that
// rests on.
#pragma once

#include <string>

namespace tactiscope::core::timing {

// "+0.512345 s at the start ± 0.015 ms, 80.4 ± 0.3 ppm slow (± from the
// spread of the fastest frames' delays)"; "not mapped (…)" for a part
// whose mapping is missing or unreadable.
std::string clockMappingText(const std::string& clockJson);

}  // namespace tactiscope::core::timing
