// A session's signal setup: its words, its JSON and its checks.
#include "core/signal/SignalSetup.h"

#include "core/JsonText.h"
#include "core/NumberRanges.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tactiscope::core::signal {
namespace {

std::optional<double> optionalNumber(const nlohmann::json& item, const char* key)
{
    if (!item.contains(key) || item[key].is_null()) return std::nullopt;
    if (!item[key].is_number() || !std::isfinite(item[key].get<double>()))
        throw std::invalid_argument(std::string("a filter's ") + key + " is not a number");
    return item[key].get<double>();
}

nlohmann::json filterJson(const ChannelFilterSetting& filter)
{
    const auto number = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); };
    const dsp::FilterSettings& s = filter.settings;
    return {{"channel", filter.channel},
            {"notch_hz", number(s.notch_hz)},
            {"highpass_hz", number(s.highpass_hz)},
            {"lowpass_hz", number(s.lowpass_hz)},
            {"order", s.order},
            {"moving_average_s", s.movingAverage_s},
            {"zero_phase", s.zeroPhase}};
}

ChannelFilterSetting filterFromJson(const nlohmann::json& item)
{
    if (!item.is_object() || !item.contains("channel") || !item["channel"].is_string())
        throw std::invalid_argument("a filter names no channel");
    ChannelFilterSetting filter{item["channel"].get<std::string>(), {}};
    dsp::FilterSettings& s = filter.settings;
    s.notch_hz = optionalNumber(item, "notch_hz");
    s.highpass_hz = optionalNumber(item, "highpass_hz");
    s.lowpass_hz = optionalNumber(item, "lowpass_hz");
    if (const auto order = optionalNumber(item, "order")) {
        if (!kFilterOrderRange.holds(*order) || *order != std::floor(*order))
            throw std::invalid_argument("a filter's order is " + kFilterOrderRange.text());
        s.order = static_cast<int>(*order);
    }
    s.movingAverage_s = optionalNumber(item, "moving_average_s").value_or(0.0);
    s.zeroPhase = item.contains("zero_phase") && item["zero_phase"].is_boolean() && item["zero_phase"].get<bool>();
    return filter;
}

}  // namespace

const dsp::FilterSettings* SignalSetup::filterOf(const std::string& channel) const
{
    const auto found = std::ranges::find(filters, channel, &ChannelFilterSetting::channel);
    return found == filters.end() ? nullptr : &found->settings;
}

std::string SignalSetup::text() const
{
    std::string joined;
    const auto add = [&joined](const std::string& part) { joined += (joined.empty() ? "" : "; ") + part; };
    for (const auto& filter : filters) add(filter.channel + ": " + filter.settings.text());
    for (const auto& definition : math) add(definition.text());
    if (analysisFiltered && !filters.empty()) add("the mode analyses the filtered channels");
    return joined.empty() ? "none" : joined;
}

std::string signalSetupJson(const SignalSetup& setup)
{
    if (setup.empty()) return {};
    nlohmann::json filters = nlohmann::json::array();
    for (std::size_t f = 0; f < setup.filters.size(); ++f) {
        filters.push_back(filterJson(setup.filters[f]));
        if (f < setup.startState.size())
            filters.back()["start_state"] =
                setup.startState[f] ? nlohmann::json(*setup.startState[f]) : nlohmann::json();
    }
    nlohmann::json math = nlohmann::json::array();
    for (const auto& definition : setup.math) math.push_back(definition.text());
    return nlohmann::json{{"filters", filters}, {"math", math}, {"analysis_filtered", setup.analysisFiltered}}.dump();
}

SignalSetup signalSetupFromJson(const std::string& json)
{
    if (json.empty()) return {};
    nlohmann::json root;
    try {
        root = parseJsonText(json, "the signal setup");
    } catch (const JsonTextError& e) {
        throw std::invalid_argument(e.what());
    }
    if (!root.is_object()) throw std::invalid_argument("the signal setup is not a JSON object");
    SignalSetup setup;
    if (root.contains("filters")) {
        if (!root["filters"].is_array()) throw std::invalid_argument("the signal setup's filters are not a list");
        bool anyState = false;
        for (const auto& item : root["filters"]) {
            setup.filters.push_back(filterFromJson(item));
            std::optional<std::vector<double>> state;
            if (item.contains("start_state") && !item["start_state"].is_null()) {
                const auto& numbers = item["start_state"];
                if (!numbers.is_array() || !std::ranges::all_of(numbers, [](const nlohmann::json& n) {
                        return n.is_number() && std::isfinite(n.get<double>());
                    }))
                    throw std::invalid_argument("a filter's start_state is not a list of numbers");
                state = numbers.get<std::vector<double>>();
                anyState = true;
            }
            setup.startState.push_back(std::move(state));
        }
        if (!anyState) setup.startState.clear();
    }
    if (root.contains("math")) {
        if (!root["math"].is_array()) throw std::invalid_argument("the signal setup's math is not a list");
        for (const auto& item : root["math"]) {
            if (!item.is_string()) throw std::invalid_argument("a math channel is not NAME[UNIT]=EXPR text");
            try {
                setup.math.push_back(math::parseMathDefinition(item.get<std::string>()));
            } catch (const math::MathError& e) {
                throw std::invalid_argument(e.what());
            }
        }
    }
    setup.analysisFiltered = root.contains("analysis_filtered") && root["analysis_filtered"].is_boolean() &&
                             root["analysis_filtered"].get<bool>();
    return setup;
}

std::string signalSetupText(const std::string& json)
{
    try {
        return signalSetupFromJson(json).text();
    } catch (const std::invalid_argument& e) {
        return std::string("unreadable: ") + e.what();
    }
}

std::optional<AnalysisFilters> analysisFilters(const SignalSetup& setup, const std::vector<std::string>& channels)
{
    if (!setup.analysisFiltered) return std::nullopt;
    AnalysisFilters analysis;
    for (const std::string& channel : channels) {
        const auto found = std::ranges::find(setup.filters, channel, &ChannelFilterSetting::channel);
        const auto f = static_cast<std::size_t>(found - setup.filters.begin());
        analysis.filters.push_back(found == setup.filters.end() ? dsp::FilterSettings{} : found->settings);
        analysis.startStates.push_back(f < setup.startState.size() ? setup.startState[f] : std::nullopt);
        if (found != setup.filters.end())
            analysis.text += (analysis.text.empty() ? "" : "; ") + channel + ": " + found->settings.text();
    }
    if (analysis.text.empty()) return std::nullopt;
    return analysis;
}

std::optional<std::string> signalSetupRefusal(const SignalSetup& setup, const std::vector<std::string>& channels,
                                              double sampleRate_hz)
{
    if (!setup.startState.empty() && setup.startState.size() != setup.filters.size())
        return "the filters' start states are not one per filter";
    for (std::size_t i = 0; i < setup.filters.size(); ++i) {
        const auto& filter = setup.filters[i];
        if (std::ranges::find(channels, filter.channel) == channels.end())
            return "no channel called '" + filter.channel + "' to filter";
        for (std::size_t j = 0; j < i; ++j)
            if (setup.filters[j].channel == filter.channel)
                return "channel '" + filter.channel + "' is given two filters; give it one";
        if (filter.settings.zeroPhase) return "a live filter is causal; zero-phase is for review";
        if (filter.settings.empty()) return "the filter on '" + filter.channel + "' filters nothing";
        if (auto refusal = dsp::filterRefusal(filter.settings, sampleRate_hz))
            return "'" + filter.channel + "': " + *refusal;
    }
    return std::nullopt;
}

}  // namespace tactiscope::core::signal
