// Reference stiffnesses of tissues from the literature the paper cites
// (seed 001, §2.1 step 2), kept as data in resources/reference-tissues.json
// so they can be extended without touching code; a reading is placed
// against them.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tactiscope::core::compliance {

struct ReferenceTissue {
    std::string name;
    double min_n_per_m = 0.0;  // equal to max for a single value
    double max_n_per_m = 0.0;
    std::string source;
};

struct TissuePlacement {
    const ReferenceTissue* tissue = nullptr;
    double distance_n_per_m = 0.0;  // 0 inside the tissue's range
};

class ReferenceTissueError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// File format: {"tissues": [{"name": "...", "stiffness_n_per_m": 40,
// "source": "..."} or with "stiffness_min_n_per_m"/"stiffness_max_n_per_m"]}.
std::vector<ReferenceTissue> parseReferenceTissues(std::string_view json, const std::string& source);
std::vector<ReferenceTissue> loadReferenceTissues(const std::string& path);

// The tissues ordered by how close their stiffness is to the reading.
std::vector<TissuePlacement> placeReading(const std::vector<ReferenceTissue>& tissues, double stiffness_n_per_m);

}  // namespace tactiscope::core::compliance
