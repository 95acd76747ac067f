// Turns per-sample detector outputs into DefectEvents.
//
// An event is a run of equal non-zero decisions. A gap of zeros shorter than
// the hold time between two runs of the same direction is bridged, so one
// dent that makes the output flicker gives one event, not several; a run of
// the opposite direction always ends the event at once. The peak is taken
// over the samples whose decision matched the direction.
//
// Streaming: push samples as they come; an event is reported once it can no
// longer grow (the hold time has passed, or the direction changed).
#pragma once

#include "core/detector/DefectEvent.h"
#include "core/detector/DetectorOutput.h"

#include <optional>
#include <vector>

namespace tactiscope::core::detector {

class EventSegmenter {
public:
    // Throws std::invalid_argument for a negative hold or a non-positive spacing.
    explicit EventSegmenter(double hold_s = 0.0, std::optional<double> spacing_m = std::nullopt);

    // One sample at time t_s (increasing) with its lags in seconds. Appends
    // events that are complete to `completed`.
    void push(double t_s, const DetectorOutput& output, double sampleInterval_s, std::vector<DefectEvent>& completed);

    // Ends the stream: reports the event still open, if any.
    void finish(std::vector<DefectEvent>& completed);
    void reset();

private:
    void close(std::vector<DefectEvent>& completed);

    double m_hold_s;
    std::optional<double> m_spacing_m;
    std::optional<DefectEvent> m_open;
    double m_lastActive_s = 0.0;  // time of the open event's last matching sample
};

}  // namespace tactiscope::core::detector
