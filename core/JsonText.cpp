// JsonText: nlohmann's parser, with the key of an error found by a second,
// event-driven pass over the text (only when there is an error).
#include "core/JsonText.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace tactiscope::core {
namespace {

// Follows the path of keys and array positions while the parser reads, and
// keeps it at the first error.
class PathFinder : public nlohmann::json_sax<nlohmann::json> {
public:
    std::string path() const
    {
        std::string text;
        for (const auto& step : m_steps) {
            if (step.inArray)
                text += "[" + std::to_string(step.index) + "]";
            else if (!step.key.empty())
                text += (text.empty() ? "" : ".") + step.key;
        }
        return text;
    }

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override
    {
        m_steps.push_back({});
        return true;
    }
    bool key(string_t& key) override
    {
        m_steps.back().key = key;
        return true;
    }
    bool end_object() override { return end(); }
    bool start_array(std::size_t) override
    {
        m_steps.push_back({{}, true, 0});
        return true;
    }
    bool end_array() override { return end(); }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

private:
    struct Step {
        std::string key;
        bool inArray = false;
        std::size_t index = 0;
    };
    bool value()
    {
        if (!m_steps.empty() && m_steps.back().inArray) ++m_steps.back().index;
        return true;
    }
    bool end()
    {
        m_steps.pop_back();
        return value();
    }
    std::vector<Step> m_steps;
};

template <typename Json>
Json parse(std::string_view text, const std::string& source)
{
    try {
        return Json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        PathFinder finder;
        nlohmann::json::sax_parse(text, &finder);
        const std::string where = finder.path();
        std::string why = e.what();
        if (const auto bracket = why.find("] "); bracket != std::string::npos) why.erase(0, bracket + 2);
        // The parser quotes the bad token whole: a 9000-digit number, once.
        constexpr std::size_t kMostQuoted = 120;
        if (why.size() > kMostQuoted)
            why = why.substr(0, kMostQuoted) + "… (" + std::to_string(why.size()) + " characters)";
        if (dynamic_cast<const nlohmann::json::parse_error*>(&e))
            throw JsonTextError(source + ": not valid JSON (" + (where.empty() ? "" : "at " + where + ": ") + why +
                                ")");
        throw JsonTextError(source + ": " + (where.empty() ? "" : where + ": ") + why);
    }
}

}  // namespace

nlohmann::json parseJsonText(std::string_view text, const std::string& source)
{
    return parse<nlohmann::json>(text, source);
}

nlohmann::ordered_json parseOrderedJsonText(std::string_view text, const std::string& source)
{
    return parse<nlohmann::ordered_json>(text, source);
}

}  // namespace tactiscope::core
