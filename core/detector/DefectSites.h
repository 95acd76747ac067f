// Defect sites (placing: CrossingPlacement.cpp; grouping and the sites'
// texts: SiteGrouping.cpp; their shared arithmetic: SiteArithmetic.h): in
// a reciprocating scan one surface deflection is crossed
// again and again, once per stroke, so the detector's events are crossings,
// not defects. This places each crossing along the stroke and groups the
// crossings into sites, with rules that keep a wrong number from appearing:
//
// Which events are crossings: the detector also gives short opposite runs
// (a few samples, between two events or near a reversal). An event much
// shorter than the scan's typical event (kShortRunFraction of the median)
// whose direction is against the nearest full event's, and which lies
// within that event's echo (kEchoReach of its lag), makes no reversal and
// is no crossing of its own: it is part of the crossing nearest in time
// (DefectSite::parts). A short event along its neighbour's direction is a
// crossing (a fast one is short), and so is one beyond the echo: a weak
// crossing (on the simulator every short run is one, in the direction the
// probe moves).
//
// Reversals: between two crossings of opposite direction. A stroke (from
// one reversal to the next) much shorter than the scan's median
// (kMinStrokeFraction) is not plausible: the crossings inside it are taken
// as parts of their neighbours and its two reversals are dropped, until
// every stroke is plausible.
//
// Where: by the phase of the crossing within its stroke, φ = π·τ/T (τ from
// the reversal behind, T the stroke's duration; the median stroke at either
// end of the scan; a stroke longer than kLongStrokeFactor typical ones
// hides strokes where nothing was detected, and is split into the odd
// number of strokes nearest its length), under two stroke shapes:
//  - harmonic (a hand or a crank): x = −d·A·cos φ, A = v·T/(π·sin φ) the
//    crossing's own stroke's half-length (from x = −A·cos ωτ,
//    v = A·ω·sin ωτ, ω = π/T; near a reversal, sin φ < kConditionedSine,
//    the scan's median A instead), v the detector's speed (spacing / lag);
//  - constant speed (a machine): x = d·v·(τ − T/2), exact on a machine's
//    stroke wherever it moves at its speed.
// d is the direction (+1: A then B). The constant-speed place always lies
// nearer the centre (|tan πg|/π ≥ |g| for g = τ/T − ½).
//
// Which shape: told only where the crossings' speeds say it beyond their
// own scatter. Per site (its crossings grouped by their harmonic places),
// w = v·T is π·A·sin φ on a harmonic stroke and the stroke's length on a
// constant-speed one; each site's mean w, with the standard error its own
// crossings show (a hand's jitter from stroke to stroke is in it), is
// fitted both ways, and a shape is taken when its χ² is lower by
// kShapeEvidence. Otherwise (one dent, dents at one |x|, or speeds that
// fit either) the harmonic place is kept and the method says so; the
// truth then lies between it and the constant-speed place, and each site's
// ± counts that doubt as the whole difference Δ between them (a machine's
// stroke, whose place is the constant-speed one, lies one standard
// uncertainty away at most; measured on generated trapezoids, the harmonic
// place is 0.8–1.3 Δ off once the detector's scatter is in: Δ/√3, the
// root-mean-square of a place uniformly between, covered only 82 % at 2u).
//
// Bounds: no place lies beyond the stroke's half-length as inferred
// between reversals (the median of the crossings' own half-lengths, under
// the shape used): a crossing computed beyond it (its reversals inferred
// wrongly) is a part of the nearest placed one; with the shape not told,
// harmonic places are held within it. Strokes longer than a panel probe's
// (kMaxStroke_m) place nothing: the crossings' times and speeds also fit a
// probe that rests between strokes (a panel line), as a long stroke with
// the dent near its end. Nor does a scan whose placed crossings mostly
// meet none of their site the other way (kTwoWayShare): its reversals lie
// between crossings of different dents at speeds too alike to tell.
//
// Ghosts: the speed of a stroke rises from one reversal and falls to the
// next, never dipping between (a hand's or a machine's). A crossing slower
// than both its neighbours in the same stroke by more than
// kGhostSpeedShare is not a crossing of a dent: it is the detector pairing
// one cantilever's view of one dent with the other's of the next (between
// two dents, the ridge they leave), and is part of the nearer neighbour.
//
// When: the detector decides a crossing after its trailing cantilever has
// passed the dent and its memory (λ = c) has gathered the correlation, so
// an event's middle comes kDetectionDelay of its lag after the probe's
// centre was over the dent. Each crossing is timed at that moment; a
// delay the same in every crossing would cancel, but it is a lag's
// fraction, longer at the slow ends of a stroke than in its middle.
//
// Grouping: one stroke crosses each defect once, so the crossings of one
// stroke are different sites. The typical number k of crossings per stroke
// gives k sites, each at the median place of the strokes' j-th crossing;
// every crossing goes to the nearest, and one farther than kSiteReach_m
// from all of them starts a site of its own. Sites closer than
// kMinSiteSeparation_m are one (a crossing the detector split).
// A site's place is the mean of its crossings' places, its standard
// uncertainty (k = 1) their standard deviation over √n, widened for few
// crossings to the spread of Student's t (×√((n−1)/(n−3))), combined with
// the shape's doubt. Fewer than kMinPlacedCrossings crossings cannot show
// their own scatter: by phase, such a site is "too few crossings to
// place"; by a position channel it is placed, its ± a uniform doubt over
// its crossings' range and half a run's extent. A site
// whose crossings one way lie apart from those the other way (beyond
// kMinSiteSeparation_m and three standard errors) is two dents each seen
// one way, or placed by reversals the detector's misses hid: its crossings
// each way are a site of their own, unplaced.
// Spans: a site whose crossings each cover, at their speed, more than
// kSpanExtent_m of the surface (the median over its crossings) is one
// event covering two dents or a long one, reported from–to.
// Crossings that cannot be placed (no speed, no reversal: a dent seen in
// one direction only) are grouped the same way by their order within each
// pass (passes split at the long gaps between crossings): a dent seen one
// way is one site "position unknown", not one per crossing. Fewer than
// kMinPasses unplaced crossings show no rhythm: each is a site of its own.
// The exception is a single stroke out and back (nothing placed; the
// crossings change direction once, as many each way): each dent on the way
// out is on the way back, so the crossings pair mirrored about the
// reversal, the last out with the first back, one site per pair, as long
// as each pair has its speeds and lies close enough in time for the probe
// to have gone to the turn and back (kMaxStroke_m each way).
#pragma once

#include "core/detector/DefectEvent.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tactiscope::core::detector {

inline constexpr double kShortRunFraction = 0.35;
// Measured on generated scans at the paper's settings: the event's middle
// comes 0.80–0.89 of its lag after the centre was over the dent (12–13 mm
// of travel at the 15 mm spacing, dents 3–4 mm wide, 0.1–0.6 m/s).
inline constexpr double kDetectionDelay = 0.85;
// Its spread over those scans (0.80–0.89): a Type B of the place a position
// channel gives, as a share of the travel in a lag (the spacing).
inline constexpr double kDetectionDelayUncertainty = 0.05;
// How far after (or before) a crossing, in its own lags, the detector's
// memory (λ = c) can still give a run: e⁻³ of its weight is left there.
inline constexpr double kEchoReach = 3.0;
inline constexpr double kMinStrokeFraction = 0.4;
// A stroke longer than this many typical ones hides strokes without a
// crossing seen (next: 3, a stroke each way with nothing detected).
inline constexpr double kLongStrokeFactor = 1.75;
// Crossings nearer a reversal than this (sin φ) give no stroke length of
// their own: their harmonic place uses the scan's.
inline constexpr double kConditionedSine = 0.3;
// How much lower one shape's χ² must be for it to be taken (a likelihood
// ratio of e⁵, about 150 to 1).
inline constexpr double kShapeEvidence = 10.0;
inline constexpr double kGhostSpeedShare = 0.9;
// One dent crossed out and back is crossed at one speed, but for a hand's
// jitter from one stroke to the next: crossings out and back at one end of
// the stroke whose speeds differ on average by more than this (and by
// more than three standard errors) are of two different dents.
inline constexpr double kSameDentSpeeds = 0.15;
// A reversal between one dent's crossings out and back has about the
// typical gap at its end of the stroke: one longer by more than this share
// (or three standard deviations of the gaps there, for a hand's jitter) is
// between two different dents (the outer one missed there).
inline constexpr double kPairedGapFactor = 1.3;
// Below this share of placed crossings meeting their site the other way,
// the reversals are not known and nothing is placed.
inline constexpr double kTwoWayShare = 0.5;
// The standard deviation of a normal scatter is 1.4826 median absolute deviations.
inline constexpr double kMadToSigma = 1.4826;
inline constexpr std::size_t kMinPlacedCrossings = 4;
// The detector's speed (spacing over the lag of peak R) sets the scale of
// every place, and is not exact: on generated scans with known speeds its
// places read 0.3–2.3 % off, the same way in every crossing of a site
// (a Type B, relative standard uncertainty).
inline constexpr double kSpeedScaleUncertainty = 0.01;
// Farther than one dent's crossing covers at the prototype's spacing (a
// 4 mm dent's event covers about 3 mm at any speed; measured on generated
// scans, tests/support/ReciprocatingScans.h).
inline constexpr double kSpanExtent_m = 0.015;
inline constexpr double kSiteReach_m = 0.015;
inline constexpr double kMinSiteSeparation_m = 0.010;
// Unplaced crossings are grouped by passes only from this many on.
inline constexpr std::size_t kMinPasses = 3;
// Gaps within a pass are shorter than those between passes by more than
// this (a missed crossing makes a gap 2 or 3 cycles long, never 1/3).
inline constexpr double kPassGapRatio = 3.0;
// Farther than any stroke over a panel goes, by hand or machine (the
// paper's is about 200 mm).
inline constexpr double kMaxStroke_m = 1.0;

enum class StrokeShape {
    Harmonic,
    ConstantSpeed,
    Unknown,  // not told by the speeds: harmonic places, the constant-speed ones in their ±
};

// Where each event was placed, and why some were not.
struct CrossingPlaces {
    std::vector<std::optional<double>> position_m;       // from the stroke's centre, + towards where A leads
    std::vector<std::optional<double>> constantSpeed_m;  // the place on a constant-speed stroke (the shape's doubt)
    std::vector<std::optional<std::size_t>>
        stroke;  // the stroke (0, 1, …, hidden ones counted) of each placed crossing
    std::vector<std::optional<std::size_t>> partOf;  // a short or implausible run: the crossing it belongs to
    std::optional<double> halfStroke_m;              // the stroke's half-length, when placed; no place lies beyond
    StrokeShape shape = StrokeShape::Unknown;
    bool fromPosition = false;  // placed by a position channel, not by their phase
    std::string model;          // how the crossings were placed, for people
};

// Where the probe was along its stroke at a time (m, on the position
// channel's own scale), from a channel with the role `position` (an
// encoder or a linear potentiometer on the rig); none where it is not known.
using PositionAt = std::function<std::optional<double>(double t_s)>;

// Samples at t0 + i·dt, linearly interpolated: none outside them or beside
// a sample without a value (NaN, a gap).
PositionAt positionFromSamples(std::vector<double> samples, double t0_s, double dt_s);

// Copies of the events, each with position_m where the position channel
// had the probe when its centre was over the dent (the event's middle less
// the detector's delay).
std::vector<DefectEvent> withPositions(std::span<const DefectEvent> events, const PositionAt& positionAt);

// Each crossing at its position_m (none: not placed): no phase, no stroke
// shape. Short opposite runs are parts as above; strokes are counted from
// the crossings' changes of direction.
CrossingPlaces placeByPosition(std::span<const DefectEvent> events);

CrossingPlaces placeCrossings(std::span<const DefectEvent> events);

enum class SiteKind {
    Site,      // one dent, at position_m ± position_u_m
    Span,      // one event covering several dents or a long one, from_m to to_m
    Unplaced,  // crossings seen but not placed
};

struct DefectSite {
    SiteKind kind = SiteKind::Unplaced;
    std::optional<double> position_m;  // mean of its crossings' places; none when unplaced
    double position_u_m = 0.0;         // its standard uncertainty (k = 1)
    double from_m = 0.0, to_m = 0.0;   // a span's ends
    // Why an unplaced site has no place, for people ("too few crossings to
    // place"); empty when nothing (no reversal, no speed) could place it.
    std::string unplacedWhy;
    double spread_m = 0.0;               // largest distance of a crossing from that position
    std::vector<std::size_t> crossings;  // indices into the events, in time order
    // Events counted with it but not placed: short runs of its crossings,
    // ghosts beside them, crossings placed beyond the stroke or apart from
    // every site by a reversal the detector's misses moved.
    std::vector<std::size_t> parts;
    std::size_t forward = 0;   // crossings A then B
    std::size_t backward = 0;  // crossings B then A
    double first_s = 0.0;
    double last_s = 0.0;
};

struct SiteGrouping {
    std::vector<DefectSite> sites;  // placed ones by position, then unplaced ones by time
    // How the events were placed, for reports: "scan speed, harmonic strokes", …, "not placed".
    std::string method;
};

SiteGrouping groupSites(std::span<const DefectEvent> events, const CrossingPlaces& places);

// placeCrossings() then groupSites(): the sites of a panel scan's events;
// placeByPosition() instead when the rig gives the probe's position, read
// at each crossing or already on the events (`byPosition`: stamped by a
// PositionTrail).
SiteGrouping scanSites(std::span<const DefectEvent> events, bool byPosition = false);
SiteGrouping scanSites(std::span<const DefectEvent> events, const PositionAt& positionAt);

// A site's place as people read it: "37.2 ± 1.9 mm (6 crossings)", "span
// 20–52 mm: two dents or a long one (6 crossings)", "position unknown:
// too few crossings to place (2 crossings)", "position unknown (6 crossings)".
std::string siteText(const DefectSite& site);
// Only its place, without unit for a column headed by one or with it:
// "37.2 ± 1.9", "span 1 to 19", "unknown: too few crossings to place".
std::string sitePlaceText(const DefectSite& site, bool withUnit);

}  // namespace tactiscope::core::detector
