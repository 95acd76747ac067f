// "NAME=VALUE,NAME=VALUE" lists of the command line (--roles, --units):
// split and trimmed in one place, so each option reads its values alike.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tactiscope::core::text {

// The items in order, names and values trimmed of spaces and tabs; empty
// items are skipped. Throws std::invalid_argument naming an item with no
// '=' ("'a' is not NAME=ROLE (e.g. a=cantilever-a)", from `form`), with no
// name, or with a name given twice (" is given two " + `valueWord` + "s").
std::vector<std::pair<std::string, std::string>> parseNamedList(std::string_view text, std::string_view form,
                                                                std::string_view valueWord);

}  // namespace tactiscope::core::text
