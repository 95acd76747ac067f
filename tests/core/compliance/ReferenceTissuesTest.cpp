// The reference tissue table shipped in resources/, and placing readings.
#include "core/compliance/ReferenceTissues.h"

#include <gtest/gtest.h>

using namespace tactiscope::core::compliance;

TEST(ReferenceTissues, TheShippedTableHasThePapersValues)
{
    const auto tissues = loadReferenceTissues(TACTISCOPE_SOURCE_DIR "/resources/reference-tissues.json");
    ASSERT_EQ(tissues.size(), 8u);
    const auto find = [&](const std::string& start) {
        for (const auto& t : tissues) {
            if (t.name.rfind(start, 0) == 0) return t;
        }
        return ReferenceTissue{};
    };
    EXPECT_EQ(find("Normal liver").max_n_per_m, 40.0);
    EXPECT_EQ(find("Diseased liver").max_n_per_m, 80.0);
    EXPECT_EQ(find("Swine brain").min_n_per_m, 80.0);
    EXPECT_EQ(find("Swine brain").max_n_per_m, 100.0);
    EXPECT_EQ(find("Liver (pig").min_n_per_m, 127.0);
    EXPECT_EQ(find("Lower esophagus").min_n_per_m, 195.0);
    EXPECT_EQ(find("Fat").min_n_per_m, 83.0);
    EXPECT_EQ(find("Skin").min_n_per_m, 331.0);
    EXPECT_EQ(find("Muscle").min_n_per_m, 497.0);
}

TEST(ReferenceTissues, PlacesAReadingAmongTheClosestTissues)
{
    const auto tissues = parseReferenceTissues(R"({"tissues": [
        {"name": "a", "stiffness_n_per_m": 40}, {"name": "b", "stiffness_min_n_per_m": 80, "stiffness_max_n_per_m": 100},
        {"name": "c", "stiffness_n_per_m": 127}]})",
                                               "test");
    const auto placed = placeReading(tissues, 90.0);
    EXPECT_EQ(placed[0].tissue->name, "b");
    EXPECT_EQ(placed[0].distance_n_per_m, 0.0);
    EXPECT_EQ(placed[1].tissue->name, "c");
    EXPECT_EQ(placed[1].distance_n_per_m, 37.0);
    EXPECT_EQ(placed[2].distance_n_per_m, 50.0);
}

TEST(ReferenceTissues, ErrorsNameTheEntry)
{
    try {
        parseReferenceTissues(R"({"tissues": [{"name": "x", "stiffness_n_per_m": -1}]})", "t.json");
        FAIL();
    } catch (const ReferenceTissueError& e) {
        EXPECT_STREQ(e.what(), "t.json: tissues[0].stiffness_n_per_m: must be a positive number");
    }
    EXPECT_THROW(parseReferenceTissues("{}", "t.json"), ReferenceTissueError);
}
