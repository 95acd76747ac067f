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

// One JSON object: samples, lags, elapsed_s, samples_per_s, kernel, threads,
// events, sites (placed by `sites` when given: a stored session's, which
// may come from its position channel), and probe_agreement {agreeing,
// compared} when a probe's own decisions were compared.
std::string eventsJson(std::size_t samples, std::size_t lags, double elapsed_s,
                       const std::vector<core::detector::DefectEvent>& events, const DetectorOptions& options,
                       const std::optional<core::detector::ProbeAgreement>& probe = std::nullopt,
                       const std::optional<core::detector::SiteGrouping>& sites = std::nullopt);
// The human summary: what ran, how fast, and a table of the events.
void printDetection(const QString& source, std::size_t samples, double dt_s, std::size_t lags, double elapsed_s,
                    const std::vector<core::detector::DefectEvent>& events, const DetectorOptions& options);

}  // namespace tactiscope::cli
