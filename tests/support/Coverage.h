// Coverage of a stated standard uncertainty, tested as a statistic: over
// many independent runs, |value − truth| ≤ 1u must hold in 68.3 % of them
// and ≤ 2u in 95.4 % (a Gaussian's), each within the binomial limits of
// the number of runs (3σ, so a fixed set of seeds that passes is not luck
// at the edge).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>

namespace tactiscope::testing {

class Coverage {
public:
    void add(double error, double uncertainty)
    {
        ++m_runs;
        if (std::abs(error) <= uncertainty) ++m_within1;
        if (std::abs(error) <= 2.0 * uncertainty) ++m_within2;
    }

    std::size_t runs() const { return m_runs; }
    // "41 of 60 within 1u, 57 within 2u": the figures, for the test's log.
    std::string summary() const
    {
        std::ostringstream seen;
        seen << m_within1 << " of " << m_runs << " within 1u, " << m_within2 << " within 2u";
        return seen.str();
    }

    ::testing::AssertionResult isGaussian() const
    {
        if (m_runs < 50) return ::testing::AssertionFailure() << "too few runs to judge: " << summary();
        if (!within(m_within1, 0.6827) || !within(m_within2, 0.9545))
            return ::testing::AssertionFailure()
                   << summary() << " (expected 68.3 % and 95.4 % within 3σ binomial limits)";
        return ::testing::AssertionSuccess() << summary();
    }

private:
    bool within(std::size_t hits, double p) const
    {
        const double n = static_cast<double>(m_runs);
        return std::abs(static_cast<double>(hits) - n * p) <= 3.0 * std::sqrt(n * p * (1.0 - p));
    }

    std::size_t m_runs = 0, m_within1 = 0, m_within2 = 0;
};

}  // namespace tactiscope::testing
