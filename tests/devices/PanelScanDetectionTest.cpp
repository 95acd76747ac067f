// End to end on the simulated panel scan: the fast detector makes the same
// decisions as the direct Eigen implementation on every sample, and its
// events follow the scan's kinematics.
#include "DirectDetector.h"
#include "core/SampleBlock.h"
#include "core/detector/OfflineDetection.h"
#include "core/detector/PairDetector.h"
#include "devices/simulator/PanelScanScenario.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace tactiscope;
using core::detector::DetectorOutput;
using core::detector::DetectorParameters;

namespace {

struct Scan {
    std::vector<double> a, b;
};

Scan simulate(double seconds, std::uint64_t seed)
{
    devices::simulator::PanelScanParameters p;
    p.seed = seed;
    devices::simulator::PanelScanScenario scenario(p);
    core::SampleBlock block(2, static_cast<std::size_t>(seconds * 500.0), 0.0, 0.002);
    scenario.generate(block);
    return {{block.channel(0).begin(), block.channel(0).end()}, {block.channel(1).begin(), block.channel(1).end()}};
}

}  // namespace

TEST(PanelScanDetection, FastAndDirectDetectorsDecideAlikeOnEverySample)
{
    const Scan scan = simulate(12.0, 3);
    const DetectorParameters p;  // the paper's settings
    std::vector<DetectorOutput> fast(scan.a.size()), direct(scan.a.size());
    core::detector::PairDetector(p).process(scan.a, scan.b, fast);
    reference::DirectDetector(p).process(scan.a, scan.b, direct);
    std::size_t differ = 0, detections = 0;
    for (std::size_t i = 0; i < fast.size(); ++i) {
        differ += fast[i].decision != direct[i].decision;
        detections += direct[i].decision != 0;
        ASSERT_NEAR(fast[i].rab, direct[i].rab, 1e-9) << "sample " << i;
    }
    EXPECT_EQ(differ, 0u);
    EXPECT_GT(detections, 50u);  // the comparison covered real detections
}

TEST(PanelScanDetection, EventsFollowTheStrokeAndTheLagIsTheCrossingTime)
{
    // x(t) = 0.1·sin(πt) m; the dent's centre is at 30 mm and B trails A by
    // 15 mm, so on each pass B reaches the dent (asin 0.45 − asin 0.30)/π =
    // 51.5 ms after A: the detector's lag, within a sample. Moving towards +x
    // (cos πt > 0) the order is A then B.
    const Scan scan = simulate(20.0, 4);
    const DetectorParameters p;
    const auto outputs = core::detector::detectSeries({0.0, {scan.a, scan.b}, {}}, p);
    const auto events = core::detector::segmentEvents(outputs, 0.002, 0.020, 0.015);
    ASSERT_EQ(events.size(), 20u);  // two passes per 2 s stroke, 10 strokes
    const double crossing_s = (std::asin(0.45) - std::asin(0.30)) / std::numbers::pi;
    for (const auto& e : events) {
        const int moving = std::cos(std::numbers::pi * e.start_s) > 0.0 ? 1 : -1;
        EXPECT_EQ(e.direction, moving) << "event at " << e.start_s << " s";
        EXPECT_NEAR(e.peakLag_s, crossing_s, 0.002) << "event at " << e.start_s << " s";
        EXPECT_NEAR(*e.speed_m_per_s, 0.015 / crossing_s, 0.015 / crossing_s * 0.05);
    }
}
