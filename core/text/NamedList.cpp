// NamedList: splitting "NAME=VALUE" lists.
#include "core/text/NamedList.h"

#include "core/text/ShortQuote.h"

#include <algorithm>
#include <stdexcept>

namespace tactiscope::core::text {
namespace {

std::string_view trimmed(std::string_view text)
{
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
    return text;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> parseNamedList(std::string_view text, std::string_view form,
                                                                std::string_view valueWord)
{
    std::vector<std::pair<std::string, std::string>> items;
    while (!trimmed(text).empty()) {
        const auto comma = text.find(',');
        const std::string_view item = trimmed(text.substr(0, comma));
        text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
        if (item.empty()) continue;
        const auto equals = item.find('=');
        if (equals == std::string_view::npos)
            throw std::invalid_argument(quoteShort(item) + " is not " + std::string(form));
        std::string name(trimmed(item.substr(0, equals)));
        if (name.empty()) throw std::invalid_argument(quoteShort(item) + " names no channel");
        if (std::ranges::find(items, name, &std::pair<std::string, std::string>::first) != items.end())
            throw std::invalid_argument("channel '" + name + "' is given two " + std::string(valueWord) + "s");
        items.emplace_back(std::move(name), std::string(trimmed(item.substr(equals + 1))));
    }
    return items;
}

}  // namespace tactiscope::core::text
