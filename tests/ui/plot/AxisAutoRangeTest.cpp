// The calm autoscaling rule.
#include "ui/plot/AxisAutoRange.h"

#include <gtest/gtest.h>

using tactiscope::ui::AxisRange;
using tactiscope::ui::nextAxisRange;

TEST(AxisAutoRange, FitsTheDataWithAMarginWhenNothingIsShownYet)
{
    const AxisRange r = nextAxisRange({0.0, 0.0}, -2.0, 8.0);
    EXPECT_DOUBLE_EQ(r.lower, -3.0);  // 10 % of the 10-unit span each side
    EXPECT_DOUBLE_EQ(r.upper, 9.0);
}

TEST(AxisAutoRange, HoldsStillWhileTheDataStaysInside)
{
    const AxisRange current{-3.0, 9.0};
    const AxisRange r = nextAxisRange(current, -1.0, 7.5);
    EXPECT_DOUBLE_EQ(r.lower, -3.0);
    EXPECT_DOUBLE_EQ(r.upper, 9.0);
}

TEST(AxisAutoRange, GrowsAtOnceWhenTheDataLeaves)
{
    const AxisRange r = nextAxisRange({-3.0, 9.0}, -1.0, 19.0);
    EXPECT_DOUBLE_EQ(r.lower, -3.0);
    EXPECT_DOUBLE_EQ(r.upper, 21.0);
}

TEST(AxisAutoRange, ShrinksOnlyWhenTheDataFillsLessThanAThird)
{
    const AxisRange current{0.0, 12.0};
    EXPECT_DOUBLE_EQ(nextAxisRange(current, 4.0, 8.5).upper, 12.0);  // 4.5 of 12 fills more than a third
    const AxisRange r = nextAxisRange(current, 5.0, 8.0);            // 3 of 12 does not
    EXPECT_DOUBLE_EQ(r.lower, 4.7);
    EXPECT_DOUBLE_EQ(r.upper, 8.3);
}

TEST(AxisAutoRange, GivesAFlatSignalAVisibleSpan)
{
    const AxisRange r = nextAxisRange({0.0, 0.0}, 5.0, 5.0);
    EXPECT_GT(r.size(), 0.0);
    EXPECT_LT(r.lower, 5.0);
    EXPECT_GT(r.upper, 5.0);
}
