// Polls a condition from a plain thread (no Qt event loop) until it holds or
// a time limit passes. The limit bounds a liveness check ("the writer gets
// there"); it is not a speed assertion.
#pragma once

#include <chrono>
#include <thread>

namespace tactiscope::testing {

template <typename Predicate>
bool eventually(Predicate condition, std::chrono::milliseconds limit = std::chrono::seconds(10))
{
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (!condition()) {
        if (std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return true;
}

}  // namespace tactiscope::testing
