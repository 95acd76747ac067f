// Reciprocating panel scans with known dent places, written for the tests
// independently of the simulator (issue 55): the probe's centre goes back
// and forth along a stroke whose shape, length and duration the test
// chooses, with a hand's jitter from stroke to stroke; its two cantilevers,
// 15 mm apart, each give the surface inclination under them high-passed by
// the capsule, a strain common to both from the probe's acceleration, and
// white noise. A dent may catch the probe in one direction only (a burr).
// The truth is the dents' places along the stroke of the probe's centre:
// the centre is over a dent half-way between its two cantilevers' crossings.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace tactiscope::testing {

enum class StrokeShape {
    Sine,       // a hand or a crank: x = −A·cos(π·τ/T)
    Trapezoid,  // a machine: constant speed, accelerating over the first and last kRampShare of the stroke
};

struct Dent {
    double place_m = 0.0;    // from the stroke's centre, + where A leads
    int onlyWhenMoving = 0;  // 0: both ways; +1 or −1: only while the probe moves that way
    double width_m = 0.004;  // the Gaussian profile's σ; its depth 12.5 µm per mm of it (the same steepest slope)
};

struct ReciprocatingScan {
    StrokeShape shape = StrokeShape::Sine;
    double halfStroke_m = 0.104;
    double stroke_s = 1.0;  // one way, reversal to reversal
    double jitter = 0.0;    // each stroke's half-length and duration × (1 + jitter·U(−1, 1))
    std::vector<Dent> dents;
    double seconds = 30.0;
    double sampleRate_hz = 500.0;
    double noise = 0.5e-6;  // σ per gauge, strain
    std::uint64_t seed = 1;
};

struct ScanSignals {
    std::vector<double> a, b;           // strain, cantilever A (ahead when moving +) and B
    std::vector<double> centre_m;       // the probe's centre, for tests that want the truth per sample
    std::vector<double> halfStrokes_m;  // each stroke's half-length as made
    // The mean midpoint of the scan's strokes: a hand's strokes wander
    // about the nominal centre, and places are measured from theirs.
    double strokeCentre_m = 0.0;
};

inline constexpr double kRampShare = 0.15;
inline constexpr double kScanSpacing_m = 0.015;

// The fraction of a stroke's length covered after a fraction f of its time.
inline double strokeProgress(StrokeShape shape, double f)
{
    if (shape == StrokeShape::Sine) return 0.5 * (1.0 - std::cos(std::numbers::pi * f));
    // Speed rises linearly over the ramp, stays, falls: the distance is the
    // area under that trapezoid, normalised by its whole area (1 − r).
    const double r = kRampShare;
    const double area = 1.0 - r;
    if (f < r) return 0.5 * f * f / r / area;
    if (f > 1.0 - r) return 1.0 - 0.5 * (1.0 - f) * (1.0 - f) / r / area;
    return (0.5 * r + (f - r)) / area;
}

inline ScanSignals generateReciprocatingScan(const ReciprocatingScan& scan)
{
    std::mt19937_64 random(scan.seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::normal_distribution<double> gauss(0.0, 1.0);
    // Strokes: reversal k at time tk, place ek = ±A_k alternating.
    std::vector<double> reversal_s{-std::uniform_real_distribution<double>(0.0, scan.stroke_s)(random)};
    std::vector<double> end_m;
    ScanSignals out;
    for (int k = 0; reversal_s.back() < scan.seconds + scan.stroke_s; ++k) {
        const double half = scan.halfStroke_m * (1.0 + scan.jitter * unit(random));
        out.halfStrokes_m.push_back(half);
        end_m.push_back(k % 2 == 0 ? -half : half);
        reversal_s.push_back(reversal_s.back() + scan.stroke_s * (1.0 + scan.jitter * unit(random)));
    }
    // The place at the last reversal, after the scan ends (its nominal one).
    end_m.push_back(end_m.size() % 2 == 0 ? -scan.halfStroke_m : scan.halfStroke_m);
    double centres = 0.0;
    std::size_t strokes = 0;
    for (std::size_t k = 0; k + 1 < end_m.size(); ++k)
        if (reversal_s[k + 1] > 0.0 && reversal_s[k] < scan.seconds) {
            centres += 0.5 * (end_m[k] + end_m[k + 1]);
            ++strokes;
        }
    out.strokeCentre_m = centres / static_cast<double>(strokes);
    const auto centreAt = [&](double t) {
        const auto next = std::upper_bound(reversal_s.begin(), reversal_s.end(), t);
        const auto k = static_cast<std::size_t>(next - reversal_s.begin()) - 1;
        const double f = (t - reversal_s[k]) / (reversal_s[k + 1] - reversal_s[k]);
        return end_m[k] + (end_m[k + 1] - end_m[k]) * strokeProgress(scan.shape, f);
    };
    // Surface slope under a cantilever: each dent a Gaussian, 50 µm deep at σ = 4 mm.
    constexpr double steepness = 50e-6 / 0.004, gain = 4e-3, perAcceleration = 3e-6, capsule_s = 0.15;
    const auto slope = [&](double x, double velocity) {
        double s = 0.0;
        for (const Dent& dent : scan.dents) {
            if (dent.onlyWhenMoving * velocity < 0.0) continue;
            const double u = (x - dent.place_m) / dent.width_m;
            s += steepness * u * std::exp(-0.5 * u * u);
        }
        return s;
    };
    const double dt = 1.0 / scan.sampleRate_hz;
    const double keep = capsule_s / (capsule_s + dt);  // y[n] = keep·(y[n−1] + u[n] − u[n−1])
    const auto n = static_cast<std::size_t>(std::lround(scan.seconds * scan.sampleRate_hz));
    double lastA = 0.0, lastB = 0.0, hpA = 0.0, hpB = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) * dt;
        const double x = centreAt(t);
        const double velocity = (centreAt(t + 0.5 * dt) - centreAt(t - 0.5 * dt)) / dt;
        const double acceleration = (centreAt(t + dt) - 2.0 * x + centreAt(t - dt)) / (dt * dt);
        const double inA = gain * slope(x + 0.5 * kScanSpacing_m, velocity);
        const double inB = gain * slope(x - 0.5 * kScanSpacing_m, velocity);
        if (i == 0) lastA = inA, lastB = inB;
        hpA = keep * (hpA + inA - lastA);
        hpB = keep * (hpB + inB - lastB);
        lastA = inA, lastB = inB;
        out.a.push_back(hpA + perAcceleration * acceleration + scan.noise * gauss(random));
        out.b.push_back(hpB + perAcceleration * acceleration + scan.noise * gauss(random));
        out.centre_m.push_back(x);
    }
    return out;
}

}  // namespace tactiscope::testing
