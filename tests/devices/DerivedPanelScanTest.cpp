// The review's detector lanes of a stored panel scan are the detector's
// output for the same samples: the simulator's reciprocating scan with a
// dent, recorded with a gap, then read window by window through
// core/derived/PanelScanChannels (each window warmed up on the samples
// before it), against the detector run once over each whole stretch of the
// stored samples — the slower direct way, with the full history. The
// threshold is the one the automatic verdict names.
#include "core/SampleBlock.h"
#include "core/derived/PanelScanChannels.h"
#include "core/detector/OfflineDetection.h"
#include "core/storage/Recorder.h"
#include "core/storage/SessionStore.h"
#include "devices/simulator/PanelScanScenario.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>

using namespace tactiscope;

namespace {

constexpr double kRate_hz = 500.0;
constexpr std::uint64_t kSamples = 12'000;  // 24 s
constexpr std::uint64_t kGapFirst = 6'000, kGapEnd = 6'400;

struct Recorded {
    std::int64_t session = 0;
    std::vector<std::vector<double>> stored;  // per cantilever, NaN in the gap
};

Recorded recordScan(const std::string& path)
{
    devices::simulator::PanelScanParameters p;
    p.seed = 11;
    devices::simulator::PanelScanScenario scenario(p);
    core::SampleBlock all(2, kSamples, 0.0, 1.0 / kRate_hz);
    scenario.generate(all);
    core::storage::SessionMetadata metadata;
    metadata.mode = core::Mode::PanelScan;
    core::storage::Recorder recorder(path, metadata, scenario.channels(), kRate_hz, 1'000'000);
    Recorded recorded{recorder.sessionId(), {}};
    // The device's samples [kGapFirst, kGapEnd) never arrive.
    for (std::uint64_t first = 0; first < kSamples; first += 100) {
        if (first >= kGapFirst && first < kGapEnd) continue;
        core::SampleBlock block(2, 100, static_cast<double>(first) / kRate_hz, 1.0 / kRate_hz, first);
        for (std::size_t c = 0; c < 2; ++c)
            for (std::size_t s = 0; s < 100; ++s) block.channel(c)[s] = all.channel(c)[first + s];
        recorder.consume(block);
    }
    core::storage::VerdictDecision automatic;
    automatic.role = core::VerdictRole::Automatic;
    automatic.verdict = core::Verdict::DefectsFound;
    automatic.basisJson = R"({"analysis":"live","threshold":0.8,"epsilon":7e-06,"lambda":"lag","face_to_face":false})";
    recorder.finish(core::SessionStatus::Complete, automatic);
    core::storage::SessionStore store(path);
    for (std::size_t c = 0; c < 2; ++c) recorded.stored.push_back(store.readChannel(recorded.session, c, 0, kSamples));
    return recorded;
}

// The direct way: the detector over each stretch without a lost sample, from its start.
std::vector<core::detector::ProbeOutput> directOutputs(const std::vector<std::vector<double>>& stored,
                                                       const core::detector::DetectorParameters& parameters)
{
    std::vector<core::detector::ProbeOutput> outputs(kSamples);
    for (const auto& [from, to] : {std::pair<std::size_t, std::size_t>{0, kGapFirst}, {kGapEnd, kSamples}}) {
        core::detector::SeriesInput input;
        for (const auto& s : stored) input.cantilevers.emplace_back(std::span(s).subspan(from, to - from));
        const auto stretch = core::detector::detectSeries(input, parameters);
        std::copy(stretch.begin(), stretch.end(), outputs.begin() + static_cast<std::ptrdiff_t>(from));
    }
    return outputs;
}

}  // namespace

TEST(DerivedPanelScan, TheDetectorLanesAreTheDetectorsOutputForTheSameSamples)
{
    const auto path = (std::filesystem::temp_directory_path() /
                       ("tactiscope-derived-p-" + std::to_string(::getpid()) + ".tactiscope"))
                          .string();
    std::filesystem::remove(path);
    const auto recorded = recordScan(path);
    ASSERT_TRUE(std::isnan(recorded.stored[0][kGapFirst]));
    ASSERT_FALSE(std::isnan(recorded.stored[0][kGapEnd]));

    core::storage::SessionStore store(path);
    core::derived::PanelScanChannels channels(store, recorded.session);
    EXPECT_EQ(channels.parameters().threshold, 0.8);  // the automatic verdict's, not the default 0.85
    core::detector::DetectorParameters direct;
    direct.sampleInterval_s = 1.0 / kRate_hz;
    direct.threshold = 0.8;
    const auto expected = directOutputs(recorded.stored, direct);

    std::size_t decisions = 0;
    // From the start, deep into the first stretch, across the gap, just after it, and to the end.
    for (const auto& [first, count] : {std::pair<std::uint64_t, std::uint64_t>{0, 700},
                                       {4'000, 1'500},
                                       {5'900, 600},
                                       {6'400, 300},
                                       {11'000, 1'000}}) {
        const auto values = channels.read(first, count);
        ASSERT_EQ(values.size(), 2u);
        ASSERT_EQ(values[0].size(), count);
        for (std::uint64_t i = 0; i < count; ++i) {
            const auto index = first + i;
            if (index >= kGapFirst && index < kGapEnd) {
                EXPECT_TRUE(std::isnan(values[0][i])) << index;
                continue;
            }
            const auto& o = expected[index].combined;
            const double best = std::max(o.rab, o.rba);
            ASSERT_NEAR(values[0][i], best, 1e-7) << "sample " << index;
            if (std::abs(best - 0.8) > 1e-6) {
                ASSERT_EQ(values[1][i], o.decision) << "sample " << index;
            }
            decisions += o.decision != 0;
        }
    }
    EXPECT_GT(decisions, 0u) << "the windows should hold crossings of the dent";

    // The overview: each stretch's extremes of the same outputs.
    const auto overview = channels.overview(0, 4'000, 1'000, 10);
    ASSERT_EQ(overview.size(), 10u);
    for (const auto& point : overview) {
        double low = 2.0, high = -2.0;
        for (std::uint64_t i = point.firstIndex; i < point.firstIndex + point.count; ++i) {
            const auto& o = expected[i].combined;
            low = std::min(low, std::max(o.rab, o.rba));
            high = std::max(high, std::max(o.rab, o.rba));
        }
        EXPECT_NEAR(point.min, low, 1e-7);
        EXPECT_NEAR(point.max, high, 1e-7);
    }
    for (const char* suffix : {"", "-wal", "-shm", "-recorder.lock"}) std::filesystem::remove(path + suffix);
}
