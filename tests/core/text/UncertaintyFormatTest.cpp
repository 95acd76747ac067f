// Values and their uncertainties as the CLI and the GUI write them: two
// significant digits of the uncertainty, counted after rounding.
#include "core/text/UncertaintyFormat.h"

#include <gtest/gtest.h>

using namespace tactiscope::core::text;

TEST(UncertaintyFormat, TwoSignificantDigitsOfTheUncertaintySetTheDecimals)
{
    EXPECT_EQ(uncertaintyDecimals(0.034), 3);
    EXPECT_EQ(uncertaintyDecimals(1.2), 1);
    EXPECT_EQ(uncertaintyDecimals(56.0), 0);
    EXPECT_EQ(uncertaintyDecimals(0.0995), 2);  // rounds to 0.10, not 0.100
    EXPECT_EQ(uncertaintyDecimals(0.0049), 4);
    EXPECT_EQ(uncertaintyDecimals(0.0), 0);
    EXPECT_EQ(uncertaintyDecimals(1e-12, 6), 6);
}

TEST(UncertaintyFormat, AValueIsWrittenToItsUncertaintysPlaceAndExactDataInWords)
{
    EXPECT_EQ(valueWithUncertainty(116.98, 0.034, "N/m"), "116.980 ± 0.034 N/m");
    EXPECT_EQ(valueWithUncertainty(116.9934, 0.0198, "N/m"), "116.993 ± 0.020 N/m");
    EXPECT_EQ(valueWithUncertainty(1234.5, 56.0), "1234 ± 56");
    EXPECT_EQ(valueWithUncertainty(99861.0, 195.0, "N/m"), "99861 ± 195 N/m");
    // Near the compliance probe's stiff end: not seven digits of a ± of 15 %.
    EXPECT_EQ(valueWithUncertainty(8708294.0, 1529677.0, "N/m"), "(8.7 ± 1.5)·10⁶ N/m");
    EXPECT_EQ(valueWithUncertainty(174.0, 0.0, "N/m"), "174 N/m (no scatter)");
    EXPECT_EQ(valueWithUncertainty(174.0, 1e-12, "N/m"), "174 N/m (no scatter)");
}
