// The detector's command-line options and event output, shared by `detect`
// (a CSV file) and `analyze` (a stored session), so both take the same
// options and print events the same way.
#pragma once

#include "core/detector/DefectSites.h"
#include "core/detector/DetectorParameters.h"
#include "core/detector/EventSegmenter.h"
#include "core/detector/StreamingDetection.h"

#include <QCommandLineParser>
#include <QString>

#include <optional>
#include <string>
#include <vector>

namespace tactiscope::cli {

struct DetectorOptions {
    core::detector::DetectorParameters parameters;  // sampleInterval_s is the caller's
    double hold_s = 0.020;
    std::optional<double> spacing_m;
    unsigned threads = 1;
    bool json = false;
    core::detector::DetectorEngine engine = core::detector::DetectorEngine::Workstation;
};

// --lags-ms, --lambda-ms, --epsilon, --threshold, --face-to-face,
// --window-ms, --spacing-mm, --hold-ms, --threads and --json.
void addDetectorOptions(QCommandLineParser& parser);
// Fills `options`; returns an error message for a bad value.
std::optional<QString> readDetectorOptions(const QCommandLineParser& parser, DetectorOptions& options);

// What ran and what it found: the events and the sites they make (placed
// by their phases, or by the rig's position channel).
struct DetectionOutput {
    std::size_t samples = 0;
    std::size_t lags = 0;
    double elapsed_s = 0.0;
    const std::vector<core::detector::DefectEvent>& events;
    const core::detector::SiteGrouping& sites;
};

// One JSON object: samples, lags, elapsed_s, samples_per_s, kernel, threads,
// events, sites, sites_method, and probe_agreement {agreeing, compared}
// when a probe's own decisions were compared.
std::string eventsJson(const DetectionOutput& output, const DetectorOptions& options,
                       const std::optional<core::detector::ProbeAgreement>& probe = std::nullopt);
// The human summary: what ran, how fast, a table of the events and the sites.
void printDetection(const QString& source, double dt_s, const DetectionOutput& output, const DetectorOptions& options);

}  // namespace tactiscope::cli
