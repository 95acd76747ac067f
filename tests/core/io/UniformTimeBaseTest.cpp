// The time-base check, whole and block by block: the same interval, and an
// irregular or backward step named at its row in its block, also when it
// is the step between two blocks.
#include "core/io/UniformTimeBase.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

using tactiscope::core::io::TimeBaseError;
using tactiscope::core::io::uniformSampleInterval;
using tactiscope::core::io::UniformTimeBaseCheck;

TEST(UniformTimeBase, BlocksGiveTheWholeSeriesMeanInterval)
{
    std::vector<double> t;
    for (int i = 0; i < 1000; ++i) t.push_back(10.0 + 0.002 * i + (i % 2 ? 1e-7 : 0.0));
    UniformTimeBaseCheck check;
    for (std::size_t first = 0; first < t.size(); first += 333)
        check.add(std::span(t).subspan(first, std::min<std::size_t>(333, t.size() - first)));
    // By hand: (t.back − t.front) / 999, t.back carrying +1e-7 (999 is odd).
    EXPECT_NEAR(check.interval_s(), (0.002 * 999 + 1e-7) / 999, 1e-15);
    EXPECT_EQ(check.interval_s(), uniformSampleInterval(t));
}

TEST(UniformTimeBase, ABadStepIsNamedAtItsRowEvenBetweenBlocks)
{
    UniformTimeBaseCheck check;
    check.add(std::vector<double>{0.0, 0.002, 0.004});
    try {
        check.add(std::vector<double>{0.010, 0.012});  // 6 ms after the last block's end
        FAIL() << "an irregular step was accepted";
    } catch (const TimeBaseError& e) {
        EXPECT_EQ(e.row(), 0u);
        EXPECT_NE(std::string(e.what()).find("irregular"), std::string::npos);
    }
    UniformTimeBaseCheck backwards;
    backwards.add(std::vector<double>{0.0, 0.002, 0.004});
    try {
        backwards.add(std::vector<double>{0.006, 0.005});
        FAIL() << "time going back was accepted";
    } catch (const TimeBaseError& e) {
        EXPECT_EQ(e.row(), 1u);
    }
    EXPECT_THROW(UniformTimeBaseCheck().add(std::vector<double>{1.0}), TimeBaseError);
}

TEST(UniformTimeBase, AllowedAGapOfWholeIntervalsIsCountedAndLeftOutOfTheInterval)
{
    // 0, 2, 4 ms, then 10 ms (two samples missing), 12, 14; the next block
    // begins 4 ms after (one missing).
    UniformTimeBaseCheck check(0.01, UniformTimeBaseCheck::Gaps::Allowed);
    check.add(std::vector<double>{0.0, 0.002, 0.004, 0.010, 0.012, 0.014});
    check.add(std::vector<double>{0.018, 0.020});
    EXPECT_EQ(check.samplesAfterGaps(), (std::vector<std::uint64_t>{3, 6}));
    EXPECT_EQ(check.samplesMissing(), 3u);
    // Five steps of 2 ms: the gaps' 6 and 4 ms are no interval.
    EXPECT_NEAR(check.interval_s(), 0.002, 1e-15);
    // Refused unless allowed; half an interval off is irregular either way.
    EXPECT_THROW(UniformTimeBaseCheck().add(std::vector<double>{0.0, 0.002, 0.004, 0.010}), TimeBaseError);
    EXPECT_THROW(UniformTimeBaseCheck(0.01, UniformTimeBaseCheck::Gaps::Allowed)
                     .add(std::vector<double>{0.0, 0.002, 0.004, 0.009}),
                 TimeBaseError);
}
