// Defect sites: in a reciprocating scan one surface deflection is crossed
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
// number of strokes nearest its length), and one stroke shape for the
// whole scan:
//  - harmonic (a hand or crank): x = −d·A·cos φ, with the half-stroke A the
//    median over crossings of v/(ω·sin φ), ω = π/T (from x = −A·cos ωτ,
//    v = A·ω·sin ωτ), v the detector's speed (spacing / best lag);
//  - constant speed (a machine): x = d·V·(τ − (T − τ))/2, V the median speed.
// d is the direction (+1: A then B). Both stay within the stroke (|x| ≤ A,
// |x| ≤ V·T/2) by construction. The shape is chosen from the crossings'
// speeds when they were seen at different sin φ (the one whose speeds fit
// better: v ∝ sin φ, or v the same); with one sin φ only (a single dent) it is
// not identifiable, harmonic is assumed and the method says so.
//
// What is placed: the probe's centre at the event's middle (the defect
// between the two cantilevers: measured on the simulator at +30 mm, the two
// directions agree within 0.3 mm).
//
// Grouping: one stroke crosses each defect once, so the crossings of one
// stroke are different sites. The typical number k of crossings per stroke
// gives k sites, each at the median place of the strokes' j-th crossing;
// every crossing goes to the nearest, and one farther than kSiteReach_m
// from all of them starts a site of its own. Sites closer than
// kMinSiteSeparation_m are one (a crossing the detector split).
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
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tactiscope::core::detector {

inline constexpr double kShortRunFraction = 0.35;
// How far after (or before) a crossing, in its own lags, the detector's
// memory (λ = c) can still give a run: e⁻³ of its weight is left there.
inline constexpr double kEchoReach = 3.0;
inline constexpr double kMinStrokeFraction = 0.4;
// A stroke longer than this many typical ones hides strokes without a
// crossing seen (next: 3, a stroke each way with nothing detected).
inline constexpr double kLongStrokeFactor = 1.75;
// How far apart the crossings' sin φ must lie for the stroke shape to be told.
inline constexpr double kMinSineSpread = 0.04;
inline constexpr double kSiteReach_m = 0.015;
inline constexpr double kMinSiteSeparation_m = 0.010;
// Unplaced crossings are grouped by passes only from this many on.
inline constexpr std::size_t kMinPasses = 3;
// Farther than any stroke over a panel goes, by hand or machine (the
// paper's is about 200 mm).
inline constexpr double kMaxStroke_m = 1.0;

// Where each event was placed, and why some were not.
struct CrossingPlaces {
    std::vector<std::optional<double>> position_m;  // from the stroke's centre, + towards where A leads
    std::vector<std::optional<std::size_t>>
        stroke;  // the stroke (0, 1, …, hidden ones counted) of each placed crossing
    std::vector<std::optional<std::size_t>> partOf;  // a short or implausible run: the crossing it belongs to
    std::optional<double> halfStroke_m;              // the stroke's half-length, when placed
    std::string model;                               // how the crossings were placed, for people
};

CrossingPlaces placeCrossings(std::span<const DefectEvent> events);

struct DefectSite {
    std::optional<double> position_m;    // median of its crossings' places; none when unplaced
    double spread_m = 0.0;               // largest distance of a crossing from that position
    std::vector<std::size_t> crossings;  // indices into the events, in time order
    std::vector<std::size_t> parts;      // short runs that belong to its crossings
    std::size_t forward = 0;             // crossings A then B
    std::size_t backward = 0;            // crossings B then A
    double first_s = 0.0;
    double last_s = 0.0;
};

struct SiteGrouping {
    std::vector<DefectSite> sites;  // placed ones by position, then unplaced ones by time
    // How the events were placed, for reports: "scan speed, harmonic strokes", …, "not placed".
    std::string method;
};

SiteGrouping groupSites(std::span<const DefectEvent> events, const CrossingPlaces& places);

// placeCrossings() then groupSites(): the sites of a panel scan's events.
SiteGrouping scanSites(std::span<const DefectEvent> events);

// A site's place as people read it: "37 mm ± 2 mm (6 crossings)", "37 mm
// (6 crossings within 1 mm)", "position unknown: no reversal (6 crossings)".
std::string siteText(const DefectSite& site);

}  // namespace tactiscope::core::detector
