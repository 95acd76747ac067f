// Filter settings: their words, their checks, and their JSON.
#include "core/dsp/FilterSettings.h"

#include "core/NumberRanges.h"
#include "core/dsp/ButterworthDesign.h"
#include "core/dsp/MainsNotch.h"
#include "core/text/NumberFormat.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <stdexcept>

namespace tactiscope::core::dsp {
namespace {

std::string hertz(double value)
{
    return text::formatShortest(value) + " Hz";
}

std::optional<double> optionalNumber(const nlohmann::json& item, const char* key)
{
    if (!item.contains(key) || item[key].is_null()) return std::nullopt;
    if (!item[key].is_number() || !std::isfinite(item[key].get<double>()))
        throw std::invalid_argument(std::string("a filter's ") + key + " is not a number");
    return item[key].get<double>();
}

}  // namespace

std::string FilterSettings::text() const
{
    if (empty()) return "none";
    std::vector<std::string> parts;
    if (notch_hz) parts.push_back("mains notch " + hertz(*notch_hz) + " and harmonics");
    const std::string butterworth = " (Butterworth, order " + std::to_string(order) + ")";
    if (highpass_hz && lowpass_hz)
        parts.push_back("band-pass " + text::formatShortest(*highpass_hz) + "–" + hertz(*lowpass_hz) + butterworth);
    else if (highpass_hz)
        parts.push_back("high-pass " + hertz(*highpass_hz) + butterworth);
    else if (lowpass_hz)
        parts.push_back("low-pass " + hertz(*lowpass_hz) + butterworth);
    if (movingAverage_s > 0.0) parts.push_back("moving average " + text::formatShortest(movingAverage_s * 1e3) + " ms");
    if (zeroPhase) parts.push_back("zero-phase");
    std::string joined;
    for (const std::string& part : parts) joined += (joined.empty() ? "" : ", ") + part;
    return joined;
}

std::optional<std::string> filterRefusal(const FilterSettings& settings, double sampleRate_hz)
{
    if (!(sampleRate_hz > 0.0) || !std::isfinite(sampleRate_hz)) return "the channel has no sample rate to filter at";
    if (settings.notch_hz && *settings.notch_hz != 50.0 && *settings.notch_hz != 60.0)
        return "the mains notch is at 50 or 60 Hz, not " + hertz(*settings.notch_hz);
    try {
        if (settings.notch_hz) mainsNotches(*settings.notch_hz, sampleRate_hz);
        if (settings.highpass_hz) butterworth(PassBand::High, settings.order, *settings.highpass_hz, sampleRate_hz);
        if (settings.lowpass_hz) butterworth(PassBand::Low, settings.order, *settings.lowpass_hz, sampleRate_hz);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    if (settings.highpass_hz && settings.lowpass_hz && !(*settings.highpass_hz < *settings.lowpass_hz))
        return "a band-pass's high-pass cut-off (" + hertz(*settings.highpass_hz) +
               ") must lie below its low-pass's (" + hertz(*settings.lowpass_hz) + ")";
    if (!kMovingAverageRange.holds(settings.movingAverage_s))
        return "a moving average is " + kMovingAverageRange.text() + " long, not " +
               text::formatShortest(settings.movingAverage_s) + " s";
    return std::nullopt;
}

std::string filtersJson(const std::vector<ChannelFilterSetting>& filters)
{
    nlohmann::json list = nlohmann::json::array();
    const auto number = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); };
    for (const ChannelFilterSetting& filter : filters) {
        const FilterSettings& s = filter.settings;
        list.push_back({{"channel", filter.channel},
                        {"notch_hz", number(s.notch_hz)},
                        {"highpass_hz", number(s.highpass_hz)},
                        {"lowpass_hz", number(s.lowpass_hz)},
                        {"order", s.order},
                        {"moving_average_s", s.movingAverage_s},
                        {"zero_phase", s.zeroPhase}});
    }
    return list.dump();
}

std::vector<ChannelFilterSetting> filtersFromJson(const std::string& json)
{
    const nlohmann::json list = nlohmann::json::parse(json, nullptr, false);
    if (!list.is_array()) throw std::invalid_argument("the filters are not a JSON list");
    std::vector<ChannelFilterSetting> filters;
    for (const nlohmann::json& item : list) {
        if (!item.is_object() || !item.contains("channel") || !item["channel"].is_string())
            throw std::invalid_argument("a filter names no channel");
        ChannelFilterSetting filter{item["channel"].get<std::string>(), {}};
        FilterSettings& s = filter.settings;
        s.notch_hz = optionalNumber(item, "notch_hz");
        s.highpass_hz = optionalNumber(item, "highpass_hz");
        s.lowpass_hz = optionalNumber(item, "lowpass_hz");
        const auto order = optionalNumber(item, "order");
        if (order &&
            (*order < kLeastButterworthOrder || *order > kMostButterworthOrder || *order != std::floor(*order)))
            throw std::invalid_argument("a filter's order is 2 to 8");
        if (order) s.order = static_cast<int>(*order);
        s.movingAverage_s = optionalNumber(item, "moving_average_s").value_or(0.0);
        s.zeroPhase = item.contains("zero_phase") && item["zero_phase"].is_boolean() && item["zero_phase"].get<bool>();
        filters.push_back(std::move(filter));
    }
    return filters;
}

}  // namespace tactiscope::core::dsp
