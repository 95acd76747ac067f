// The probe's own detector (firmware/probe-detector, single precision,
// issue 38) against the workstation's double-precision detector on scans
// with known answers: the same decisions on every sample of slow, fast,
// dent-free, face-to-face, offset and backwards scans, R within 1e-4; on a
// noisy scan whose R hovers at the threshold, any decision that differs
// is a near tie (its R within 1e-4 of θ), and each is reported.
#include "core/detector/FirmwarePairDetector.h"
#include "core/detector/PairDetector.h"
#include "support/GeneratedScans.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace tactiscope::core::detector;
using tactiscope::testing::GeneratedScan;

namespace {

struct Comparison {
    std::size_t differing = 0;       // samples whose decisions differ
    std::size_t decided = 0;         // samples the workstation decides ±1 on
    std::size_t rightWay = 0;        // of those, in the scan's true direction
    double largestDeltaR = 0.0;      // |ΔR| over every sample and both directions
    double farthestFromTheta = 0.0;  // of the differing samples, the largest |R − θ|
    double closestToTheta = 1.0;     // of all samples, the smallest |R − θ| (how near a tie came)
};

Comparison compare(const GeneratedScan& scan)
{
    DetectorParameters parameters;
    parameters.faceToFace = scan.faceToFace;
    PairDetector workstation(parameters);
    FirmwarePairDetector probe(parameters);
    std::vector<DetectorOutput> ws(scan.a.size()), fw(scan.a.size());
    workstation.process(scan.a, scan.b, ws);
    probe.process(scan.a, scan.b, fw);
    Comparison c;
    for (std::size_t i = 0; i < ws.size(); ++i) {
        c.largestDeltaR = std::max({c.largestDeltaR, std::abs(ws[i].rab - fw[i].rab), std::abs(ws[i].rba - fw[i].rba)});
        c.closestToTheta = std::min(
            {c.closestToTheta, std::abs(ws[i].rab - parameters.threshold), std::abs(ws[i].rba - parameters.threshold)});
        if (ws[i].decision != 0) {
            ++c.decided;
            if (ws[i].decision == scan.direction) ++c.rightWay;
        }
        if (ws[i].decision == fw[i].decision) continue;
        ++c.differing;
        const double off =
            std::min(std::abs(ws[i].rab - parameters.threshold), std::abs(ws[i].rba - parameters.threshold));
        c.farthestFromTheta = std::max(c.farthestFromTheta, off);
        std::cout << scan.name << ": sample " << i << " workstation " << int(ws[i].decision) << " (R_ab " << ws[i].rab
                  << ", R_ba " << ws[i].rba << "), probe " << int(fw[i].decision) << ", |R − θ| " << off << '\n';
    }
    std::cout << scan.name << ": " << ws.size() << " samples, the workstation decides " << c.decided
              << ", the probe differs on " << c.differing << "; largest |ΔR| " << c.largestDeltaR
              << ", closest |R − θ| " << c.closestToTheta << '\n';
    return c;
}

}  // namespace

TEST(FirmwareDetector, DecidesAsTheWorkstationOnEveryGeneratedScan)
{
    for (const GeneratedScan& scan : tactiscope::testing::generatedScans(38)) {
        SCOPED_TRACE(scan.name);
        const Comparison c = compare(scan);
        EXPECT_LT(c.largestDeltaR, 1e-4);
        if (scan.name == "near-threshold") {
            // Rounding may tip a sample whose R is a hair from θ either way, nothing more.
            EXPECT_LT(c.farthestFromTheta, 1e-4);
            continue;
        }
        EXPECT_EQ(c.differing, 0U);
        if (scan.direction == 0) {
            EXPECT_EQ(c.decided, 0U);
        } else {
            // The dent is found, and in its direction: the comparison is not of two silences.
            EXPECT_GT(c.decided, 5U);
            EXPECT_EQ(c.rightWay, c.decided);
        }
    }
}

TEST(FirmwareDetector, RefusesWhatAProbeCannotRun)
{
    DetectorParameters window;
    window.window_s = 0.1;
    EXPECT_THROW(FirmwarePairDetector{window}, std::invalid_argument);  // the sliding window
    DetectorParameters many;
    many.lags_s = lagRange_s(0.002, 0.300, 0.002);  // 150 lags
    EXPECT_THROW(FirmwarePairDetector{many}, std::invalid_argument);
    DetectorParameters paper;  // 75 lags of 1…75 samples at 500 Hz: what it is built for
    EXPECT_NO_THROW(FirmwarePairDetector{paper});
}
