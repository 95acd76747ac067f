// The host's steady clock in seconds: the time every link check, arrival
// and silence is measured on (never the wall clock, which can jump).
#pragma once

#include <chrono>

namespace tactiscope::devices {

inline double steadySeconds()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace tactiscope::devices
