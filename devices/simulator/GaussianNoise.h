// Seeded Gaussian noise with the same sequence on every platform: the
// standard library's normal_distribution is implementation-defined, which
// would make "the same seed gives the same data" depend on the toolchain.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace tactiscope::devices::simulator {

class GaussianNoise {
public:
    GaussianNoise(std::uint64_t seed, double sigma)
        : m_engine(seed),
          m_sigma(sigma)
    {
    }

    double next()
    {
        // Box–Muller: two uniforms give two independent normals; keep the spare.
        if (m_hasSpare) {
            m_hasSpare = false;
            return m_sigma * m_spare;
        }
        const double u1 = uniformOpen();
        const double u2 = uniformOpen();
        const double radius = std::sqrt(-2.0 * std::log(u1));
        const double angle = 2.0 * std::numbers::pi * u2;
        m_spare = radius * std::sin(angle);
        m_hasSpare = true;
        return m_sigma * radius * std::cos(angle);
    }

private:
    // Uniform on (0, 1]: the top 53 bits of the engine, never 0 (log(0)).
    double uniformOpen() { return (static_cast<double>(m_engine() >> 11) + 1.0) * 0x1.0p-53; }

    std::mt19937_64 m_engine;
    double m_sigma;
    double m_spare = 0.0;
    bool m_hasSpare = false;
};

}  // namespace tactiscope::devices::simulator
