// Panel scans with known answers for the probe's detector (issue 38): two
// cantilevers 15 mm apart slid over sheet metal with a wavy surface and one
// dent, written as the simulator's CSV (t [s], a [strain], b [strain]).
// The dent's strain is a bipolar bump of 36 µε peak over a few millimetres;
// each gauge adds 0.3 µε of white noise. A leads B unless the stroke runs
// backwards; the dent passes A at 2 s.
#pragma once

#include "core/text/NumberFormat.h"

#include <cmath>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace tactiscope::testing {

struct GeneratedScan {
    std::string name;
    std::vector<double> t, a, b;
    bool faceToFace = false;  // b as a face-to-face gauge gives it: negated
    int direction = 1;        // +1 A then B, −1 B then A, 0 no dent
};

struct ScanShape {
    std::string name;
    double speed_m_per_s = 0.3;  // negative: the stroke runs backwards, B leads
    bool dent = true;
    double noise = 0.3e-6;  // σ per gauge, strain
    double offset = 0.0;    // DC on both gauges, strain
    bool faceToFace = false;
};

inline GeneratedScan generateScan(const ScanShape& shape, unsigned seed, double seconds = 8.0, double dt = 0.002)
{
    constexpr double spacing = 0.015, width = 0.004, amplitude = 60e-6, wave = 0.1, waviness = 5e-6;
    const double v = shape.speed_m_per_s;
    const double dentAt = std::abs(v) * 2.0;  // where A meets it, 2 s in (B a spacing before or after)
    const auto surface = [&](double x) {
        const double u = (x - dentAt) / width;
        const double dent = shape.dent ? amplitude * u * std::exp(-0.5 * u * u) : 0.0;
        return dent + waviness * std::sin(2.0 * std::numbers::pi * x / wave);
    };
    std::mt19937_64 random(seed);
    std::normal_distribution<double> noise(0.0, shape.noise);
    GeneratedScan scan{shape.name, {}, {}, {}, shape.faceToFace, shape.dent ? (v > 0 ? 1 : -1) : 0};
    const auto samples = static_cast<std::size_t>(std::lround(seconds / dt));
    for (std::size_t i = 0; i < samples; ++i) {
        const double t = static_cast<double>(i) * dt;
        // A's place on the panel; B sits the spacing behind it in x, so it
        // meets the dent first when the stroke runs backwards.
        const double x = v > 0 ? v * t : 2.0 * dentAt + v * t;
        const double xb = x - spacing;
        scan.t.push_back(t);
        scan.a.push_back(surface(x) + shape.offset + noise(random));
        const double b = surface(xb) + shape.offset + noise(random);
        scan.b.push_back(shape.faceToFace ? -b : b);
    }
    return scan;
}

// The scans the probe is checked on: slow, fast, no dent, face to face, a
// DC offset ten times the signal, backwards, and noise that keeps R near
// the threshold.
inline std::vector<GeneratedScan> generatedScans(unsigned seed)
{
    return {generateScan({"slow", 0.12}, seed),
            generateScan({"fast", 0.6}, seed + 1),
            generateScan({"none", 0.3, false}, seed + 2),
            generateScan({"face-to-face", 0.3, true, 0.3e-6, 0.0, true}, seed + 3),
            generateScan({"offset", 0.2, true, 0.3e-6, 2e-4}, seed + 4),
            generateScan({"backwards", -0.3}, seed + 5),
            generateScan({"near-threshold", 0.3, true, 2.5e-6}, seed + 6)};
}

// As `tactiscope-cli simulate --output` writes a scan.
inline void writeScanCsv(const std::string& path, const GeneratedScan& scan)
{
    std::string text = "t [s],a [strain],b [strain]\n";
    for (std::size_t i = 0; i < scan.t.size(); ++i) {
        core::text::appendShortest(text, scan.t[i]);
        text += ',';
        core::text::appendShortest(text, scan.a[i]);
        text += ',';
        core::text::appendShortest(text, scan.b[i]);
        text += '\n';
    }
    std::ofstream(path, std::ios::binary) << text;
}

}  // namespace tactiscope::testing
