// The streaming offline detector against the live ProbeDetector (a separate
// merge of the pairs) for any way of cutting the stream into pushes, across
// its chunk size, with one thread and split in two (in time, or by lags);
// a lost stretch restarts it as a separate recording would.
#include "core/detector/StreamingDetection.h"

#include "DetectorSignals.h"
#include "core/SampleBlock.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace tactiscope::core::detector;
using tactiscope::core::SampleBlock;
using tactiscope::testing::delayedBy;
using tactiscope::testing::plus;
using tactiscope::testing::whiteNoise;

namespace {

// Three cantilevers: b follows a by 26 samples (52 ms at 500 Hz), c by 40.
struct ThreeCantilevers {
    std::vector<double> a, b, c;
    explicit ThreeCantilevers(std::size_t n)
        : a(whiteNoise(n, 2e-5, 21)),
          b(plus(delayedBy(a, 26), whiteNoise(n, 4e-6, 22))),
          c(plus(delayedBy(a, 40), whiteNoise(n, 4e-6, 23)))
    {
    }
};

// The live detector's outputs, one block of 1000 samples at a time.
std::vector<ProbeOutput> liveOutputs(const ThreeCantilevers& s, std::size_t first, std::size_t count)
{
    ProbeDetector probe(DetectorParameters{}, {0, 1, 2});
    std::vector<ProbeOutput> outputs;
    for (std::size_t from = first; from < first + count; from += 1000) {
        const std::size_t n = std::min<std::size_t>(1000, first + count - from);
        SampleBlock block(3, n, static_cast<double>(from - first) * 0.002, 0.002, from);
        for (std::size_t i = 0; i < n; ++i) {
            block.channel(0)[i] = s.a[from + i];
            block.channel(1)[i] = s.b[from + i];
            block.channel(2)[i] = s.c[from + i];
        }
        const auto out = probe.push(block);
        outputs.insert(outputs.end(), out.begin(), out.end());
    }
    return outputs;
}

}  // namespace

TEST(StreamingDetection, AnyCuttingOfTheStreamGivesTheLiveDetectorsOutputs)
{
    // Longer than one chunk, so pushes cross the chunk boundary too.
    const std::size_t n = StreamingDetection::kChunk + 5000;
    const ThreeCantilevers s(n);
    const auto live = liveOutputs(s, 0, n);
    for (const std::size_t push : {std::size_t{1} << 20, std::size_t{70001}, std::size_t{4999}, std::size_t{777}}) {
        for (const unsigned threads : {1u, 2u}) {
            std::vector<ProbeOutput> streamed;
            std::uint64_t expectedFirst = 0;
            StreamingDetection detection(3, {DetectorParameters{}, 0.02, std::nullopt, threads}, 0.0,
                                         [&](std::uint64_t first, std::span<const ProbeOutput> run) {
                                             EXPECT_EQ(first, expectedFirst);
                                             expectedFirst += run.size();
                                             streamed.insert(streamed.end(), run.begin(), run.end());
                                         });
            for (std::size_t from = 0; from < n; from += push) {
                const std::size_t count = std::min(push, n - from);
                const std::vector<std::span<const double>> part{std::span(s.a).subspan(from, count),
                                                                std::span(s.b).subspan(from, count),
                                                                std::span(s.c).subspan(from, count)};
                detection.push(part);
            }
            // Two threads split long runs in time (the warm-up of λ = 75
            // samples is 6 075 samples; a run needs four of them).
            if (threads == 2 && push > 70000) {
                EXPECT_GT(detection.timeSplits().junctions, 0u) << push;
            }
            const auto result = detection.finish();
            EXPECT_EQ(result.analysedSamples, n);
            ASSERT_EQ(streamed.size(), n);
            for (std::size_t i = 0; i < n; ++i) {
                ASSERT_EQ(streamed[i].combined.rab, live[i].combined.rab) << push << " per push, sample " << i;
                ASSERT_EQ(streamed[i].combined.rba, live[i].combined.rba) << i;
                ASSERT_EQ(streamed[i].combined.lagAb, live[i].combined.lagAb) << i;
                ASSERT_EQ(streamed[i].pairAb, live[i].pairAb) << i;
                ASSERT_EQ(streamed[i].combined.decision, live[i].combined.decision) << i;
                ASSERT_DOUBLE_EQ(streamed[i].t_s, 0.002 * static_cast<double>(i)) << i;
            }
        }
    }
}

TEST(StreamingDetection, ALostStretchRestartsTheDetectorAsASeparateRecordingWould)
{
    const std::size_t n = 20000, lostFrom = 8000, lostTo = 8013;
    ThreeCantilevers s(n);
    for (std::size_t i = lostFrom; i < lostTo; ++i) s.b[i] = std::numeric_limits<double>::quiet_NaN();
    std::vector<std::pair<std::uint64_t, ProbeOutput>> streamed;
    StreamingDetection detection(3, {DetectorParameters{}, 0.02, std::nullopt, 1}, 0.0,
                                 [&](std::uint64_t first, std::span<const ProbeOutput> run) {
                                     for (std::size_t i = 0; i < run.size(); ++i)
                                         streamed.emplace_back(first + i, run[i]);
                                 });
    const std::vector<std::span<const double>> all{s.a, s.b, s.c};
    detection.push(all);
    EXPECT_EQ(detection.finish().analysedSamples, n - (lostTo - lostFrom));

    // Before the loss: a recording of its own; after it: another, from silence.
    const auto before = liveOutputs(s, 0, lostFrom);
    const auto after = liveOutputs(s, lostTo, n - lostTo);
    ASSERT_EQ(streamed.size(), before.size() + after.size());
    for (std::size_t k = 0; k < streamed.size(); ++k) {
        const auto& [index, output] = streamed[k];
        const ProbeOutput& expected = k < before.size() ? before[k] : after[k - before.size()];
        ASSERT_EQ(index, k < before.size() ? k : lostTo + (k - before.size()));
        ASSERT_EQ(output.combined.rab, expected.combined.rab) << index;
        ASSERT_EQ(output.combined.decision, expected.combined.decision) << index;
        ASSERT_DOUBLE_EQ(output.t_s, 0.002 * static_cast<double>(index)) << index;
    }
}

TEST(StreamingDetection, AWarmUpThatMissesTheTrueStateIsRecomputed)
{
    // Loud (10⁶⁰) until sample 40 000, then quiet (10⁻⁶⁰): the second
    // half's warm-up (from 43 925 on) sees only quiet samples, while the
    // loud ones' trace in the true state (e⁻¹³³ · 10¹²⁰ in the longest
    // lag's moments) still dwarfs the quiet moments at the junction
    // (50 000). The second half must be recomputed, and every output still
    // equal the live detector's.
    const std::size_t n = 100000;
    ThreeCantilevers s(n);
    for (auto* series : {&s.a, &s.b, &s.c})
        for (std::size_t i = 0; i < n; ++i) (*series)[i] *= i < 40000 ? 1e60 : 1e-60;
    const auto live = liveOutputs(s, 0, n);
    std::vector<ProbeOutput> streamed;
    StreamingDetection detection(3, {DetectorParameters{}, 0.02, std::nullopt, 2}, 0.0,
                                 [&](std::uint64_t, std::span<const ProbeOutput> run) {
                                     streamed.insert(streamed.end(), run.begin(), run.end());
                                 });
    const std::vector<std::span<const double>> all{s.a, s.b, s.c};
    detection.push(all);
    EXPECT_EQ(detection.timeSplits().junctions, 1u);
    EXPECT_EQ(detection.timeSplits().recomputed, 1u);
    ASSERT_EQ(streamed.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
        ASSERT_EQ(streamed[i].combined.rab, live[i].combined.rab) << i;
        ASSERT_EQ(streamed[i].combined.rba, live[i].combined.rba) << i;
        ASSERT_EQ(streamed[i].combined.decision, live[i].combined.decision) << i;
    }
}
