// What an inspection report of one session says, gathered from the store
// without loading the samples (but for Q, see core/derived): the session's fields, the sensor and the
// calibrations it was recorded with, its live events, readings, operator
// notes and gaps, and each channel's min/max overview (from the store's
// level-of-detail pyramid) for the plots. A time range narrows everything to
// part of the session.
#pragma once

#include "core/calibration/CalibrationRecord.h"
#include "core/detector/DefectSites.h"
#include "core/report/SignalQuality.h"
#include "core/storage/SessionStore.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tactiscope::core::report {

struct ReportTrace {
    storage::StoredChannel channel;
    std::vector<storage::OverviewPoint> points;  // min/max per stretch, across the range
    std::optional<double> threshold;             // the level the lane is read against, if any
};

struct ReportRange {
    std::optional<double> from_s;  // session seconds; from the start when empty
    std::optional<double> to_s;    // to the end when empty
};

// What a report covers and which analysis's defects or readings it shows.
struct ReportRequest {
    ReportRange range;
    std::string analysis = storage::kLiveAnalysis;  // the recording's, or a saved re-analysis
};

// What a capacitive session's readings went through.
struct CapacitiveBasis {
    std::vector<double> baselines_f;  // C0 in use over the range: at its start, then each tare or drift step
    std::optional<calibration::CalibrationRecord> calibration;  // none: the beam model
    double perNewton_f = 0.0;                                   // the sensitivity used, F/N and F/m
    double perMetre_f = 0.0;
};

// A report's plot is a page of lanes at most: a session of 2 500 channels
// once took 7.4 GB and minutes for one image nobody could read.
inline constexpr std::size_t kMostReportTraces = 24;

struct ReportData {
    storage::SessionSummary session;
    std::string sensorName;  // the profile's name; empty when none was stored
    std::vector<calibration::CalibrationRecord> calibrations;
    double from_s = 0.0;
    double to_s = 0.0;
    std::string analysis;                            // whose defects `events` and whose `readings` hold
    std::vector<storage::SessionEvent> events;       // the analysis's defects and the live other events in the range
    detector::SiteGrouping sites;                    // the defects grouped by place along the stroke
    std::vector<storage::VerdictDecision> verdicts;  // the verdict's trail, oldest first
    std::vector<storage::SessionReading> readings;
    std::vector<storage::Annotation> annotations;
    std::vector<storage::SampleGap> gaps;
    // The key plot's lanes, as the review shows them (core/derived/SessionLanes.h).
    std::vector<ReportTrace> traces;
    // Lanes not plotted: a report plots at most kMostReportTraces (a page
    // of lanes); the export holds every channel.
    std::size_t tracesLeftOut = 0;
    std::string derivedBasis;    // what the derived lanes were computed with; empty without them
    std::string derivedProblem;  // why the mode's quantities could not be computed, if so
    std::optional<CapacitiveBasis> capacitive;
    // Each channel's health over the range, the filters and math channels
    // recorded, a capacitive beam's detection limits.
    SignalQuality quality;

    bool wholeSession() const;
};

// The basis of a capacitive session's samples [first, end); none when the
// session has no usable profile. Throws storage::StorageError.
// `calibration`: another record than the recorded one (see CapacitiveChannels).
std::optional<CapacitiveBasis> capacitiveBasis(storage::SessionSource& store, const storage::SessionSummary& session,
                                               std::uint64_t first, std::uint64_t end,
                                               const std::optional<calibration::CalibrationRecord>& calibration = {});

// Throws storage::StorageError for an unknown session and
// std::invalid_argument for a range outside the session or backwards, or an
// analysis the session does not have (the message lists the ones it has).
ReportData gatherReport(storage::SessionSource& store, std::int64_t session, const ReportRequest& request = {},
                        std::size_t overviewPoints = 1000);

}  // namespace tactiscope::core::report
