// PressTable: readings filtered to stiffness, details parsed, sites summed up.
#include "core/report/PressTable.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace tactiscope::core::report {
namespace {

std::optional<double> numberIn(const nlohmann::json& json, const char* key)
{
    if (!json.is_object() || !json.contains(key) || !json[key].is_number()) return std::nullopt;
    return json[key].get<double>();
}

}  // namespace

std::optional<GridCell> gridCellOf(const std::string& site)
{
    if (site.size() < 2 || site.size() > 4 || site[0] < 'A' || site[0] > 'Z') return std::nullopt;
    int column = 0;
    for (std::size_t i = 1; i < site.size(); ++i) {
        if (site[i] < '0' || site[i] > '9') return std::nullopt;
        column = column * 10 + (site[i] - '0');
    }
    if (column < 1) return std::nullopt;
    return GridCell{site[0] - 'A', column - 1};
}

std::vector<PressRow> pressRows(const std::vector<storage::SessionReading>& readings)
{
    std::vector<PressRow> rows;
    for (const auto& r : readings) {
        if (r.kind != ReadingKind::Compliance || r.quantity != "stiffness") continue;
        const auto details = nlohmann::json::parse(r.detailsJson, nullptr, false);
        rows.push_back({r.start_s, r.end_s, r.site, r.value, r.standardError, numberIn(details, "displacement_min_m"),
                        numberIn(details, "displacement_max_m")});
    }
    std::ranges::stable_sort(rows, {}, &PressRow::start_s);
    return rows;
}

SiteSummary summaryOf(const std::string& site, const std::vector<double>& values)
{
    const auto n = static_cast<double>(values.size());
    double sum = 0.0;
    for (const double v : values) sum += v;
    SiteSummary summary{site, values.size(), sum / n, std::nullopt, 0.0, 0.0};
    if (values.size() > 1) {
        double squares = 0.0;
        for (const double v : values) squares += (v - summary.mean_n_per_m) * (v - summary.mean_n_per_m);
        summary.standardDeviation_n_per_m = std::sqrt(squares / (n - 1.0));
    }
    const auto [low, high] = std::ranges::minmax(values);
    summary.min_n_per_m = low;
    summary.max_n_per_m = high;
    return summary;
}

std::vector<SiteSummary> siteSummaries(const std::vector<PressRow>& presses)
{
    std::map<std::string, std::vector<double>> bySite;
    for (const auto& press : presses)
        if (!press.site.empty()) bySite[press.site].push_back(press.stiffness_n_per_m);
    std::vector<SiteSummary> summaries;
    for (const auto& [site, values] : bySite) summaries.push_back(summaryOf(site, values));
    return summaries;
}

std::vector<SiteSummary> scaleMarks(const std::vector<PressRow>& presses, const std::string& allLabel)
{
    auto sites = siteSummaries(presses);
    if (!sites.empty() || presses.empty()) return sites;
    std::vector<double> values;
    for (const auto& press : presses) values.push_back(press.stiffness_n_per_m);
    return {summaryOf(allLabel, values)};
}

}  // namespace tactiscope::core::report
