// The host's steady clock in seconds: the time every link check, arrival
// and silence is measured on (never the wall clock, which can jump).
#pragma once

#include <chrono>

namespace tactiscope::devices {

inline double steadySeconds()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The instant of a steadySeconds() value (a clock mapping's host time).
inline std::chrono::steady_clock::time_point steadyInstant(double seconds)
{
    return std::chrono::steady_clock::time_point(
        std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds)));
}

// And back: the steadySeconds() value of an instant.
inline double steadySecondsOf(std::chrono::steady_clock::time_point instant)
{
    return std::chrono::duration<double>(instant.time_since_epoch()).count();
}

}  // namespace tactiscope::devices
