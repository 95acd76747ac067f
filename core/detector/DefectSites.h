// Defect sites: in a reciprocating scan one surface deflection is crossed
// again and again, once per stroke, so the detector's events are crossings,
// not defects. This groups them by where along the stroke they happened.
//
// Where: each event is placed within its own stroke, between the reversal
// before it and the one after it (a reversal lies between two events of
// opposite direction). The stroke is taken as locally harmonic, like a hand
// or crank moving back and forth: at a point passed at speed v, τ seconds
// from a reversal of a stroke lasting T/2, the distance to that reversal is
// v·tan(ωτ/2)/ω with ω = π/(T/2) (from x = A·(1 − cos ωτ), v = A·ω·sin ωτ).
// The event's speed is the detector's (cantilever spacing / best lag). The
// two distances, to the reversal behind and the one ahead, place the event
// relative to that stroke's centre, so a hand that drifts along the panel
// does not carry errors from one stroke into the next. A reversal's time
// between two events is set by their speeds (near a reversal the speed
// grows linearly with the time from it); an event at either end of the
// scan, with one reversal only, uses the median stroke's length.
//
// What is placed: the probe's centre at the event's middle. An event lasts
// from about when the leading cantilever's signal is matched to when the
// trailing one's fades, so its middle finds the defect between the two
// (measured on the simulator at +30 mm: the two directions agree within
// 0.3 mm; placing it under the trailing cantilever puts them a spacing apart).
//
// Limits: events without a speed (no spacing known) or in a scan with no
// reversal cannot be placed and are sites of their own; a stroke that turns
// back before reaching a defect is invisible to this (no event marks that
// reversal), so it assumes every stroke crosses the sites it lies between.
#pragma once

#include "core/detector/DefectEvent.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tactiscope::core::detector {

// Each event's place along the stroke, in metres from the stroke's centre
// (positive: towards where A leads); none when it cannot be placed.
std::vector<std::optional<double>> strokePositions(std::span<const DefectEvent> events);

struct DefectSite {
    std::optional<double> position_m;    // mean of its crossings' places; none when unplaced
    double spread_m = 0.0;               // largest distance of a crossing from that mean
    std::vector<std::size_t> crossings;  // indices into the events, in time order
    std::size_t forward = 0;             // crossings A then B
    std::size_t backward = 0;            // crossings B then A
    double first_s = 0.0;
    double last_s = 0.0;
};

struct SiteGrouping {
    std::vector<DefectSite> sites;  // placed ones by position, then unplaced ones by time
    // How the events were placed, for reports: "scan speed", "position channel" or "not placed".
    std::string method;
};

// The default tolerance: wider than the scatter of one defect's places
// (a few mm from lag quantisation) and narrower than two defects a
// craftsworker's finger would tell apart.
inline constexpr double kSiteTolerance_m = 0.020;

// Crossings whose places lie within `tolerance_m` of their neighbours form
// one site; unplaced events are sites of their own. `positions` has one
// entry per event (std::invalid_argument otherwise).
SiteGrouping groupSites(std::span<const DefectEvent> events, std::span<const std::optional<double>> positions,
                        double tolerance_m = kSiteTolerance_m, std::string method = "scan speed");

// strokePositions() then groupSites(): the sites of a panel scan's events.
SiteGrouping scanSites(std::span<const DefectEvent> events);

}  // namespace tactiscope::core::detector
