// Parsing a JSON text a person or another program wrote, so that nothing in
// it can abort the program: a syntax error or a number beyond a double
// (1e400) is a JsonTextError that names the file and the key it sits under
// ("profile.json: high.length_m: number overflow parsing '1e400'"), the way
// the readers of profiles, tissues and calibration records report.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <stdexcept>
#include <string>
#include <string_view>

namespace tactiscope::core {

class JsonTextError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// `source` names the text in messages (a path). Throws JsonTextError.
nlohmann::json parseJsonText(std::string_view text, const std::string& source);
nlohmann::ordered_json parseOrderedJsonText(std::string_view text, const std::string& source);

}  // namespace tactiscope::core
