// A palpation session's presses in the clinician's terms, for the review
// window and the report alike: each press's site, object stiffness k_o ±
// its standard error and the depth range it was read over (from the
// details the live reading stored), and each site's repeated presses summed
// up (n, mean, sample standard deviation, range).
#pragma once

#include "core/storage/SessionStore.h"

#include <optional>
#include <string>
#include <vector>

namespace tactiscope::core::report {

struct PressRow {
    double start_s = 0.0;
    double end_s = 0.0;
    std::string site;  // empty when the press had none
    double stiffness_n_per_m = 0.0;
    std::optional<double> standardError_n_per_m;
    std::optional<double> depthMin_m;  // the displacement range of the press
    std::optional<double> depthMax_m;
};

struct SiteSummary {
    std::string site;
    std::size_t presses = 0;
    double mean_n_per_m = 0.0;
    std::optional<double> standardDeviation_n_per_m;  // from two presses on
    double min_n_per_m = 0.0;
    double max_n_per_m = 0.0;
};

// A phantom grid cell named as the live site map names it: a row letter
// and a column number from 1 ("B3" → row 1, column 2).
struct GridCell {
    int row = 0;
    int column = 0;
};
std::optional<GridCell> gridCellOf(const std::string& site);

// The stiffness readings among `readings`, in time order.
std::vector<PressRow> pressRows(const std::vector<storage::SessionReading>& readings);
// One summary per named site, in site order (A1, A2, …, B1 as text sorts).
std::vector<SiteSummary> siteSummaries(const std::vector<PressRow>& presses);
// One press or more summed up under `site`.
SiteSummary summaryOf(const std::string& site, const std::vector<double>& values_n_per_m);
// What a tissue scale marks: each site's summary, or, when no press named
// a site, every press summed up under `allLabel`.
std::vector<SiteSummary> scaleMarks(const std::vector<PressRow>& presses, const std::string& allLabel);

}  // namespace tactiscope::core::report
