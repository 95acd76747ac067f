// ClockAlignment: the four fastest pairs per bin; the lower hull of the
// fastest; the segments' floor points and the line through them.
#include "core/timing/ClockAlignment.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace tactiscope::core::timing {

namespace {

// The floor points' scatter about their line, in units of their expected
// spread, beyond which the delivery is not random at the floor. On
// exponential, uniform and bursty links it stays below 17 in thousands of
// streams; on a link polled on 1 ms ticks it reaches 70 to 10⁵ once a
// second or more of frames come in (tests/core/timing/ClockAlignmentTest).
constexpr double kMostScatter = 30.0;
constexpr double kMostBelow = 4.0;
// How far a floor that is not sharp moves with the load on the host: four
// emulated probes recorded at once through ptys, 40 s each, read their
// drifts 1.1 ppm off (root mean square of 16, up to 2.0 ppm), a floor
// moving some 45 µs over the span, which neither the points' scatter nor
// the hull's bound showed (they stated 0.3 to 0.9 ppm: 3 of 16 within ±u).
// A uniform half-width of 70 µs covers that at the rate a standard
// uncertainty claims (docs/multi-device.md).
constexpr double kFloorMovement_s = 70e-6;
// No clock a device runs on is this far off the host's (a ceramic
// resonator is within 0.5 %, an uncalibrated RC oscillator a few percent);
// and frames this much later than that allows were held up.
constexpr double kMostDrift = 0.05;
constexpr double kHeldUp_s = 0.1;

// The bins from `first` on.
struct Bins {
    const std::deque<ClockAlignment::Bin>& all;
    std::size_t first = 0;

    std::size_t size() const { return all.size() - first; }
    const ClockAlignment::Bin& operator[](std::size_t i) const { return all[first + i]; }
    const ClockAlignment::Bin& front() const { return all[first]; }
    const ClockAlignment::Bin& back() const { return all.back(); }
    auto begin() const { return all.begin() + static_cast<std::ptrdiff_t>(first); }
    auto end() const { return all.end(); }
};

// The bins from the first whose fastest frame was not held up. A frame
// was held up when a later one came through faster by more than any
// clock's drift (about the one expected) explains: a port's backlog read
// at once, a board catching up on what it could not send while nobody
// read. At the start of the window nothing earlier holds the floor down,
// and their lags, falling a period per period, would tilt the hull's
// line; later on they lie above the floor and do no harm.
Bins onTime(const std::deque<ClockAlignment::Bin>& bins, double expectedDrift)
{
    const auto bound = [expectedDrift](const ClockAlignment::Point& p) {
        return p.lag_s + (kMostDrift - expectedDrift) * p.device_s;
    };
    // The least bound over the bins after each.
    std::vector<double> leastAfter(bins.size(), std::numeric_limits<double>::infinity());
    for (std::size_t i = bins.size() - 1; i-- > 0;)
        leastAfter[i] = std::min(leastAfter[i + 1], bound(bins[i + 1].fastest[0]));
    std::size_t first = 0;
    while (first + 2 < bins.size() && bound(bins[first].fastest[0]) > leastAfter[first] + kHeldUp_s) ++first;
    return {bins, first};
}

struct Line {
    double x0, y0, slope;  // y = y0 + slope·(x − x0)
    double at(double x) const { return y0 + slope * (x - x0); }
};

// The lower hull's edge over the fastest pairs' mean device time.
Line hullLine(const Bins& bins, double& meanX)
{
    const auto point = [&](std::size_t i) { return bins[i].fastest[0]; };
    const double x0 = point(0).device_s, y0 = point(0).lag_s;
    const auto x = [&](std::size_t i) { return point(i).device_s - x0; };
    const auto y = [&](std::size_t i) { return point(i).lag_s - y0; };
    std::vector<std::size_t> hull;
    meanX = 0.0;
    for (std::size_t i = 0; i < bins.size(); ++i) {
        meanX += x(i);
        // Andrew's monotone chain, lower half: pop while the last two and
        // this one do not turn left (the middle one is not below the chord).
        while (hull.size() >= 2) {
            const std::size_t a = hull[hull.size() - 2], b = hull.back();
            if ((x(b) - x(a)) * (y(i) - y(a)) - (y(b) - y(a)) * (x(i) - x(a)) > 0.0) break;
            hull.pop_back();
        }
        hull.push_back(i);
    }
    meanX /= static_cast<double>(bins.size());
    // The edge over the mean: of all lines under every point, the one whose
    // sum of distances to them is least.
    std::size_t edge = 0;
    while (edge + 2 < hull.size() && x(hull[edge + 1]) < meanX) ++edge;
    const std::size_t a = hull[edge], b = hull[edge + 1];
    meanX += x0;
    return {point(a).device_s, point(a).lag_s, (y(b) - y(a)) / (x(b) - x(a))};
}

struct FloorPoint {
    double device_s;
    double above_s;  // the segment's fastest, above the hull's line
    double frames;   // in its segment
};

// Each segment's fastest frame, and the gaps above it scaled to the
// inverse of the delays' density at their floor: of n exponential
// spacings, the (q+1)-th gap is 1/((n−q−1)·density) on average. False
// when a segment holds too few frames.
bool floorPoints(const Bins& bins, const Line& hull, std::vector<FloorPoint>& points,
                 std::vector<double>& inverseDensities)
{
    std::vector<FloorPoint> candidates;
    for (std::size_t j = 0; j < kClockSegments; ++j) {
        const auto first = static_cast<std::size_t>(std::lround(static_cast<double>(j * bins.size()) / kClockSegments));
        const auto last =
            static_cast<std::size_t>(std::lround(static_cast<double>((j + 1) * bins.size()) / kClockSegments));
        std::size_t frames = 0;
        candidates.clear();
        for (std::size_t b = first; b < last; ++b) {
            frames += bins[b].frames;
            for (std::size_t k = 0; k < bins[b].kept; ++k) {
                const auto& p = bins[b].fastest[k];
                candidates.push_back({p.device_s, p.lag_s - hull.at(p.device_s), 0.0});
            }
        }
        if (frames < kClockFramesPerSegment || candidates.size() < ClockAlignment::kKeptPerBin) return false;
        const auto end = candidates.begin() + ClockAlignment::kKeptPerBin;
        std::partial_sort(candidates.begin(), end, candidates.end(),
                          [](const FloorPoint& a, const FloorPoint& b) { return a.above_s < b.above_s; });
        const auto n = static_cast<double>(frames);
        points.push_back({candidates[0].device_s, candidates[0].above_s, n});
        for (std::size_t q = 0; q + 1 < ClockAlignment::kKeptPerBin; ++q)
            inverseDensities.push_back((candidates[q + 1].above_s - candidates[q].above_s) *
                                       (n - static_cast<double>(q) - 1.0));
    }
    return true;
}

// Whether the stated floor lies above a frame that came through by more
// than kMostBelow of its uncertainty there: no floor can, so the points it
// rests on were not random draws above it (a delivery locked to a poll,
// whose segments' fastest fall wherever the beat leaves them).
bool floorAboveFastest(const Bins& bins, const ClockMapping& floor)
{
    for (const auto& bin : bins) {
        const auto& p = bin.fastest[0];
        if (floor.host_s(p.device_s) - (p.device_s + p.lag_s) > kMostBelow * *floor.uncertainty_s(p.device_s))
            return true;
    }
    return false;
}

}  // namespace

const char* describe(ClockUncertaintyBasis basis)
{
    switch (basis) {
    case ClockUncertaintyBasis::Spread:
        return "from the spread of the fastest frames' delays";
    case ClockUncertaintyBasis::Bound:
        return "an upper bound: the link delays its frames unevenly (a polled link, or rare fast frames)";
    case ClockUncertaintyBasis::TooFewFrames:
        return "too few frames to tell";
    case ClockUncertaintyBasis::Exact:
        return "exact: the source times its samples by the host's clock";
    }
    return "";
}

std::optional<double> ClockMapping::uncertainty_s(double device_s) const
{
    if (basis == ClockUncertaintyBasis::TooFewFrames) return std::nullopt;
    return std::hypot(offset_u_s, drift_u * (device_s - reference_s), samplePeriodUncertainty_s());
}

double ClockMapping::samplePeriodUncertainty_s() const
{
    return samplePeriod_s / std::sqrt(12.0);
}

std::optional<double> relativeUncertainty_s(const ClockMapping& a, const ClockMapping& b, double from_s, double to_s)
{
    std::optional<double> largest;
    for (const double host_s : {from_s, to_s}) {
        // A mapping's own time there: the drift's part of it is far below
        // what moves its uncertainty.
        const auto ua = a.uncertainty_s(host_s - a.offset_s);
        const auto ub = b.uncertainty_s(host_s - b.offset_s);
        if (!ua || !ub) return std::nullopt;
        largest = std::max(largest.value_or(0.0), std::hypot(*ua, *ub));
    }
    return largest;
}

std::size_t ClockAlignment::pointsKept() const
{
    std::size_t kept = 0;
    for (const Bin& bin : m_bins) kept += bin.kept;
    return kept;
}

void ClockAlignment::add(double device_s, double arrival_s)
{
    if (!std::isfinite(device_s) || !std::isfinite(arrival_s)) return;
    const auto index = static_cast<long long>(std::floor(device_s / kClockBin_s));
    if (!m_bins.empty() && index < m_bins.back().index) return;  // a stamp gone back: not this clock
    ++m_pairs;
    if (m_bins.empty() || index != m_bins.back().index) m_bins.push_back(Bin{index});
    Bin& bin = m_bins.back();
    ++bin.frames;
    // Insert by lag among the fastest kept; a slower one than all four is dropped.
    const Point point{device_s, arrival_s - device_s};
    std::size_t at = bin.kept;
    while (at > 0 && point.lag_s < bin.fastest[at - 1].lag_s) --at;
    if (at == kKeptPerBin) return;
    for (std::size_t k = std::min(bin.kept, kKeptPerBin - 1); k > at; --k) bin.fastest[k] = bin.fastest[k - 1];
    bin.fastest[at] = point;
    bin.kept = std::min(bin.kept + 1, kKeptPerBin);
    const auto windowBins = static_cast<long long>(kClockWindow_s / kClockBin_s);
    while (m_bins.size() > 2 && index - m_bins.front().index > windowBins) m_bins.pop_front();
}

std::optional<ClockMapping> ClockAlignment::mapping() const
{
    if (m_bins.size() < 2) return std::nullopt;
    const Bins bins = onTime(m_bins, m_expectedDrift);
    ClockMapping mapping;  // the hull's, and no uncertainty
    double meanX = 0.0;
    const Line hull = hullLine(bins, meanX);
    mapping.reference_s = meanX;
    mapping.offset_s = hull.at(meanX);
    mapping.drift = hull.slope;
    mapping.span_s = bins.back().fastest[0].device_s - bins.front().fastest[0].device_s;
    mapping.pairs = m_pairs;

    std::vector<FloorPoint> points;
    std::vector<double> gaps;
    if (!floorPoints(bins, hull, points, gaps)) return mapping;
    double inverseDensity = 0.0;
    for (const double g : gaps) inverseDensity += g / static_cast<double>(gaps.size());
    // The fastest of n lies above the floor by 1/(n·density) on average,
    // with as much spread: lowered by it, each segment gives a point on
    // the floor with that standard deviation.
    const auto lift = [&](const FloorPoint& p) { return inverseDensity / p.frames; };
    const auto m = static_cast<double>(points.size());
    double meanT = 0.0, meanY = 0.0, meanLift = 0.0;
    for (const auto& p : points) {
        meanT += p.device_s / m;
        meanY += (p.above_s - lift(p)) / m;
        meanLift += lift(p) / m;
    }
    double sxx = 0.0, sxy = 0.0;
    for (const auto& p : points) {
        sxx += (p.device_s - meanT) * (p.device_s - meanT);
        sxy += (p.device_s - meanT) * (p.above_s - lift(p) - meanY);
    }
    const double slope = sxy / sxx;
    double scatter = 0.0, offsetVariance = 0.0, slopeVariance = 0.0;
    for (const auto& p : points) {
        const double r = p.above_s - lift(p) - meanY - slope * (p.device_s - meanT);
        scatter += r * r / (lift(p) * lift(p) * (m - 2.0));
        offsetVariance += lift(p) * lift(p) / (m * m);
        slopeVariance += (p.device_s - meanT) * (p.device_s - meanT) * lift(p) * lift(p) / (sxx * sxx);
    }
    // The lifts taken off are known to 1/√(gaps) of themselves, together.
    offsetVariance += meanLift * meanLift / static_cast<double>(gaps.size());
    ClockMapping floor = mapping;
    floor.basis = ClockUncertaintyBasis::Spread;
    floor.reference_s = meanT;
    floor.offset_s = hull.at(meanT) + meanY;
    floor.drift = hull.slope + slope;
    floor.offset_u_s = std::sqrt(offsetVariance);
    floor.drift_u = std::sqrt(slopeVariance);
    if (inverseDensity > 0.0 && scatter <= kMostScatter && !floorAboveFastest(bins, floor)) return floor;
    // Not sharp: the floor lies between the hull's line and this one.
    // Their difference, meanY + slope·(t − meanT), bounds it; as the
    // half-width of a uniform distribution its standard uncertainty is
    // a third of its square, term by term. Such a floor also moves with
    // the host's load by up to kFloorMovement_s over the span: a uniform
    // doubt of that half-width in the offset, and of it over the span in
    // the drift.
    const double span = std::max(mapping.span_s, kClockBin_s);
    offsetVariance += kFloorMovement_s * kFloorMovement_s / 3.0;
    slopeVariance += kFloorMovement_s * kFloorMovement_s / (3.0 * span * span);
    mapping.basis = ClockUncertaintyBasis::Bound;
    mapping.reference_s = meanT;
    mapping.offset_s = hull.at(meanT);
    mapping.offset_u_s = std::sqrt(offsetVariance + meanY * meanY / 3.0);
    mapping.drift_u = std::sqrt(slopeVariance + slope * slope / 3.0);
    return mapping;
}

}  // namespace tactiscope::core::timing
