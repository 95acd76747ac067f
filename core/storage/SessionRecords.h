// What a session holds beside its samples: events (detector defects,
// contacts and presses, alarms, operator markers), readings (a compliance
// or capacitive result), a reviewer's annotations, and the calibration
// records the store keeps for every sensor. Times are seconds from the
// session start, like the samples'.
#pragma once

#include "core/Vocabulary.h"
#include "core/calibration/CalibrationRecord.h"

#include <cstdint>
#include <optional>
#include <string>

namespace tactiscope::core::storage {

// The analysis that recorded events live; a re-analysis saved by a
// reviewer gets its own name, so the live events are never overwritten.
inline constexpr const char* kLiveAnalysis = "live";
// The decisions a probe's own detector sent (firmware/probe-detector).
inline constexpr const char* kProbeAnalysis = "probe";

struct SessionEvent {
    std::int64_t id = 0;  // given by the store
    std::string analysis = kLiveAnalysis;
    EventKind kind = EventKind::Marker;
    double start_s = 0.0;
    double end_s = 0.0;
    int direction = 0;  // a defect's order: +1 A then B, −1 B then A
    std::optional<double> peakR;
    std::optional<double> lag_s;
    std::optional<double> speed_m_per_s;
    std::string note;  // an alarm's message, a marker's note
};

struct SessionReading {
    std::int64_t id = 0;
    ReadingKind kind = ReadingKind::Compliance;
    double start_s = 0.0;
    double end_s = 0.0;
    std::string quantity;  // e.g. "stiffness", "force"
    double value = 0.0;
    std::string unit;                     // e.g. "N/m", "uN"
    std::optional<double> standardError;  // in `unit`
    std::string site;                     // where on the subject, e.g. a phantom grid cell "B3"
    std::string detailsJson;              // the rest, e.g. displacement range and slope of a press
    // Whose reading: the recording's (kLiveAnalysis) or a saved re-analysis's
    // (e.g. the presses read again through another calibration).
    std::string analysis = std::string(kLiveAnalysis);
};

struct Annotation {
    std::int64_t id = 0;
    double time_s = 0.0;
    std::string author;
    std::string text;
    std::string createdUtc;   // set by the store when empty (an import gives the recorded one)
    std::string modifiedUtc;  // likewise
};

// One decision on a session's verdict; a session's trail is its decisions
// in order, and the last one is its verdict.
struct VerdictDecision {
    std::int64_t id = 0;
    VerdictRole role = VerdictRole::Automatic;
    Verdict verdict = Verdict::Pass;
    std::string decidedBy;   // the operator's or reviewer's name; empty for the automatic one
    std::string decidedUtc;  // set by the store when empty (an import gives the recorded one)
    std::string note;        // why, in the decider's words
    // The automatic verdict's grounds, a JSON object: the analysis, its
    // parameters and what it found (e.g. {"analysis":"live","defects":21,
    // "sites":3,"threshold":0.85}).
    std::string basisJson;
};

// A zero the live processor read a session's samples on, from a sample on:
// a JSON object of raw values in the channels' units, e.g.
// {"high": 2051.3, "low": 1998.7} for a compliance probe's two beams.
struct SessionZero {
    std::uint64_t firstIndex = 0;
    std::string valuesJson;
};

struct StoredCalibration {
    std::int64_t id = 0;
    calibration::CalibrationRecord record;
};

}  // namespace tactiscope::core::storage
