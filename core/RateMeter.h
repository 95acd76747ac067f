// Measures a stream's actual sample rate from (host time, cumulative sample
// count) observations, averaged over a fixed window so the number shown to
// the user is steady. The nominal rate a device announces is not proof that
// the samples arrive at that rate; this is.
#pragma once

#include <cstdint>
#include <optional>

namespace tactiscope::core {

class RateMeter {
public:
    explicit RateMeter(double window_s = 1.0);

    // Records that `totalSamples` samples had arrived by host time `now_s`.
    // Times must not decrease; counts must not decrease.
    void observe(double now_s, std::uint64_t totalSamples);

    // Samples per second over the last completed window; empty until one
    // window has passed.
    std::optional<double> rate_hz() const { return m_rate_hz; }

    void reset();

private:
    double m_window_s;
    bool m_started = false;
    double m_windowStart_s = 0.0;
    std::uint64_t m_windowStartCount = 0;
    std::optional<double> m_rate_hz;
};

}  // namespace tactiscope::core
