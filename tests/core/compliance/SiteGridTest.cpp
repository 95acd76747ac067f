// A phantom's grid of sites: names both ways, the selection moving row by
// row and wrapping, cells outside the grid ignored, sizes bounded.
#include "core/compliance/SiteGrid.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace tactiscope::core::compliance;

TEST(SiteGrid, NamesAreRowLettersAndColumnNumbersBothWays)
{
    EXPECT_EQ(SiteGrid::name({0, 0}), "A1");
    EXPECT_EQ(SiteGrid::name({1, 2}), "B3");
    EXPECT_EQ(SiteGrid::name({25, 39}), "Z40");
    EXPECT_EQ(SiteGrid::cellOf("B3"), (SiteCell{1, 2}));
    EXPECT_EQ(SiteGrid::cellOf("Z40"), (SiteCell{25, 39}));
    for (const char* notACell : {"", "B", "b3", "B0", "B41", "B3x", "3B", "B-1"})
        EXPECT_FALSE(SiteGrid::cellOf(notACell)) << notACell;
}

TEST(SiteGrid, TheSelectionMovesRowByRowAndWraps)
{
    SiteGrid grid(2, 3);
    EXPECT_EQ(grid.currentName(), "A1");
    grid.select({0, 2});
    grid.advance();
    EXPECT_EQ(grid.currentName(), "B1");
    grid.select({1, 2});
    grid.advance();
    EXPECT_EQ(grid.currentName(), "A1");
    grid.select({2, 0});  // outside: ignored
    EXPECT_EQ(grid.currentName(), "A1");
    EXPECT_THROW(SiteGrid(0, 3), std::invalid_argument);
    EXPECT_THROW(SiteGrid(27, 3), std::invalid_argument);
    EXPECT_THROW(SiteGrid(3, 41), std::invalid_argument);
}
