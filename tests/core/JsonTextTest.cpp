// JSON from outside the program: a syntax error or a number beyond a
// double is an error naming the file and the key, never an abort.
#include "core/JsonText.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

using tactiscope::core::JsonTextError;
using tactiscope::core::parseJsonText;

namespace {

std::string errorOf(std::string_view text)
{
    try {
        parseJsonText(text, "probe.json");
    } catch (const JsonTextError& e) {
        return e.what();
    }
    return {};
}

}  // namespace

TEST(JsonText, ReadsWhatIsValid)
{
    const auto json = parseJsonText(R"({"high": {"length_m": 0.05}})", "probe.json");
    EXPECT_DOUBLE_EQ(json["high"]["length_m"].get<double>(), 0.05);
}

TEST(JsonText, ANumberBeyondADoubleNamesItsKey)
{
    EXPECT_EQ(errorOf(R"({"name": "p", "high": {"width_m": 0.01, "length_m": 1e400}})"),
              "probe.json: high.length_m: number overflow parsing '1e400'");
}

TEST(JsonText, AnErrorInAListNamesItsPlace)
{
    const std::string error = errorOf(R"({"tissues": [{"k": 1}, {"k": 2}, {"k": 4e400}]})");
    EXPECT_EQ(error, "probe.json: tissues[2].k: number overflow parsing '4e400'");
}

TEST(JsonText, ASyntaxErrorIsAnErrorToo)
{
    const std::string error = errorOf(R"({"name": )");
    EXPECT_EQ(error.rfind("probe.json: not valid JSON (at name: parse error", 0), 0u) << error;
}
