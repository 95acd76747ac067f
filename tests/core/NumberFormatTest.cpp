// Shortest round-trip number formatting.
#include "core/text/NumberFormat.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

using tactiscope::core::text::formatShortest;

TEST(NumberFormat, WritesTheShortestDecimal)
{
    EXPECT_EQ(formatShortest(0.1), "0.1");
    EXPECT_EQ(formatShortest(2.5), "2.5");
    EXPECT_EQ(formatShortest(-3.0), "-3");
    EXPECT_EQ(formatShortest(7e-6), "7e-06");
}

TEST(NumberFormat, ReadsBackToTheSameDouble)
{
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-300, 300);
    for (int i = 0; i < 10000; ++i) {
        const double value = std::ldexp(mantissa(random), exponent(random));
        const std::string text = formatShortest(value);
        EXPECT_EQ(std::strtod(text.c_str(), nullptr), value) << text;
    }
}
