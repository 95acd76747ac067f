// Reference tissue table: loading and placing a reading.
#include "core/compliance/ReferenceTissues.h"

#include "core/JsonText.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace tactiscope::core::compliance {

std::vector<ReferenceTissue> parseReferenceTissues(std::string_view text, const std::string& source)
{
    using Json = nlohmann::json;
    Json json;
    try {
        json = parseJsonText(text, source);
    } catch (const JsonTextError& e) {
        throw ReferenceTissueError(e.what());
    }
    if (!json.is_object() || !json.contains("tissues") || !json["tissues"].is_array())
        throw ReferenceTissueError(source + ": tissues: missing or not a list");
    std::vector<ReferenceTissue> tissues;
    for (std::size_t i = 0; i < json["tissues"].size(); ++i) {
        const Json& t = json["tissues"][i];
        const std::string where = source + ": tissues[" + std::to_string(i) + "]";
        const auto number = [&](const char* key) {
            if (!t.contains(key) || !t[key].is_number() || !(t[key].get<double>() > 0.0))
                throw ReferenceTissueError(where + "." + key + ": must be a positive number");
            return t[key].get<double>();
        };
        if (!t.is_object() || !t.contains("name") || !t["name"].is_string())
            throw ReferenceTissueError(where + ".name: missing");
        ReferenceTissue tissue;
        tissue.name = t["name"].get<std::string>();
        if (t.contains("stiffness_n_per_m")) {
            tissue.min_n_per_m = tissue.max_n_per_m = number("stiffness_n_per_m");
        } else {
            tissue.min_n_per_m = number("stiffness_min_n_per_m");
            tissue.max_n_per_m = number("stiffness_max_n_per_m");
            if (tissue.max_n_per_m < tissue.min_n_per_m)
                throw ReferenceTissueError(where + ": stiffness_max_n_per_m is below stiffness_min_n_per_m");
        }
        if (t.contains("source") && t["source"].is_string()) tissue.source = t["source"].get<std::string>();
        tissues.push_back(std::move(tissue));
    }
    return tissues;
}

std::vector<ReferenceTissue> loadReferenceTissues(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    if (!file) throw ReferenceTissueError(path + ": cannot open the file");
    std::ostringstream text;
    text << file.rdbuf();
    return parseReferenceTissues(text.str(), path);
}

std::vector<TissuePlacement> placeReading(const std::vector<ReferenceTissue>& tissues, double k)
{
    std::vector<TissuePlacement> placements;
    for (const auto& tissue : tissues) {
        const double distance =
            k < tissue.min_n_per_m ? tissue.min_n_per_m - k : (k > tissue.max_n_per_m ? k - tissue.max_n_per_m : 0.0);
        placements.push_back({&tissue, distance});
    }
    std::stable_sort(placements.begin(), placements.end(),
                     [](const auto& a, const auto& b) { return a.distance_n_per_m < b.distance_n_per_m; });
    return placements;
}

}  // namespace tactiscope::core::compliance
