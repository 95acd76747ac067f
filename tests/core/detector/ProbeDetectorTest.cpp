// The probe detector: pair combination, SampleBlock streaming, threads.
#include "core/detector/ProbeDetector.h"

#include "core/SampleBlock.h"
#include "core/detector/DetectorSignals.h"
#include "core/detector/OfflineDetection.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace tactiscope::core;
using namespace tactiscope::core::detector;
using namespace tactiscope::testing;

TEST(ProbeDetector, CombinesPairsByTheirLargestCorrelations)
{
    DetectorOutput first{0, 0.70, 0.20, 5, 9};
    DetectorOutput second{1, 0.90, 0.30, 7, 3};
    const DetectorOutput* both[] = {&first, &second};
    const ProbeOutput o = combinePairs(both, 0.85);
    EXPECT_EQ(o.combined.decision, 1);
    EXPECT_DOUBLE_EQ(o.combined.rab, 0.90);
    EXPECT_EQ(o.combined.lagAb, 7u);
    EXPECT_EQ(o.pairAb, 1u);
    EXPECT_DOUBLE_EQ(o.combined.rba, 0.30);
    EXPECT_EQ(o.pairBa, 1u);

    // Both directions above the threshold in different pairs: the larger wins.
    DetectorOutput third{-1, 0.10, 0.95, 1, 4};
    const DetectorOutput* conflict[] = {&second, &third};
    EXPECT_EQ(combinePairs(conflict, 0.85).combined.decision, -1);
}

TEST(ProbeDetector, ThreeCantileversSeeTheDefectPassDownTheRow)
{
    // A dent passes A, then B 20 samples later, then C 20 samples after B.
    const auto a = whiteNoise(4000, 3e-4, 5);
    const auto b = delayedBy(a, 20);
    const auto c = delayedBy(a, 40);
    SampleBlock block(3, a.size(), 0.0, 0.002);
    std::copy(a.begin(), a.end(), block.channel(0).begin());
    std::copy(b.begin(), b.end(), block.channel(1).begin());
    std::copy(c.begin(), c.end(), block.channel(2).begin());

    ProbeDetector probe(DetectorParameters{}, {0, 1, 2});
    ASSERT_EQ(probe.pairCount(), 2u);
    const auto out = probe.push(block);
    ASSERT_EQ(out.size(), a.size());
    for (std::size_t i = 300; i < out.size(); ++i) {
        ASSERT_EQ(out[i].combined.decision, 1) << "sample " << i;
        ASSERT_EQ(out[i].combined.lagAb, 20u);
        ASSERT_EQ(probe.pairOutputs(0)[i].decision, 1);
        ASSERT_EQ(probe.pairOutputs(1)[i].decision, 1);
    }
    EXPECT_DOUBLE_EQ(out[10].t_s, 0.020);
}

TEST(ProbeDetector, BlocksInAnySizeGiveTheSameOutputsAsTheWholeSeries)
{
    const auto a = whiteNoise(3000, 2e-5, 6);
    const auto b = plus(delayedBy(a, 17), whiteNoise(3000, 5e-6, 7));
    std::vector<ProbeOutput> streamed;
    ProbeDetector probe(DetectorParameters{}, {1, 0});  // b is channel 0, a channel 1
    for (std::size_t first = 0; first < a.size(); first += 10) {
        SampleBlock block(2, 10, static_cast<double>(first) * 0.002, 0.002, first);
        std::copy_n(b.begin() + static_cast<std::ptrdiff_t>(first), 10, block.channel(0).begin());
        std::copy_n(a.begin() + static_cast<std::ptrdiff_t>(first), 10, block.channel(1).begin());
        const auto out = probe.push(block);
        streamed.insert(streamed.end(), out.begin(), out.end());
    }
    const auto whole = detectSeries({0.0, {a, b}, {}}, DetectorParameters{});
    ASSERT_EQ(whole.size(), streamed.size());
    for (std::size_t i = 0; i < whole.size(); ++i) {
        ASSERT_EQ(whole[i].combined.rab, streamed[i].combined.rab) << i;
        ASSERT_EQ(whole[i].combined.decision, streamed[i].combined.decision) << i;
    }
}

TEST(OfflineDetection, AnyThreadCountGivesIdenticalOutputs)
{
    const auto a = whiteNoise(5000, 2e-5, 8);
    const auto b = plus(delayedBy(a, 33), whiteNoise(5000, 5e-6, 9));
    const auto c = plus(delayedBy(a, 60), whiteNoise(5000, 5e-6, 10));
    const SeriesInput input{1.5, {a, b, c}, {}};
    const auto one = detectSeries(input, DetectorParameters{}, 1);
    for (unsigned threads : {2u, 3u, 16u}) {
        const auto many = detectSeries(input, DetectorParameters{}, threads);
        for (std::size_t i = 0; i < one.size(); ++i) {
            ASSERT_EQ(many[i].combined.rab, one[i].combined.rab) << threads << " threads, sample " << i;
            ASSERT_EQ(many[i].combined.lagBa, one[i].combined.lagBa);
            ASSERT_EQ(many[i].pairAb, one[i].pairAb);
            ASSERT_EQ(many[i].combined.decision, one[i].combined.decision);
        }
    }
    EXPECT_DOUBLE_EQ(one[2].t_s, 1.504);
}

TEST(ProbeDetector, RejectsProbesAndBlocksThatDoNotFit)
{
    EXPECT_THROW(ProbeDetector(DetectorParameters{}, {0}), std::invalid_argument);
    EXPECT_THROW(ProbeDetector(DetectorParameters{}, {1, 1}), std::invalid_argument);
    ProbeDetector probe(DetectorParameters{}, {0, 2});
    EXPECT_THROW(probe.push(SampleBlock(2, 4, 0.0, 0.002)), std::invalid_argument);  // no channel 2
    EXPECT_THROW(probe.push(SampleBlock(3, 4, 0.0, 0.001)), std::invalid_argument);  // other rate
    EXPECT_THROW(detectSeries({0.0, {}, {}}, DetectorParameters{}), std::invalid_argument);
}
