// ClockMappingJson: the stored form of a clock mapping, and the shift onto
// a session's clocks.
#include "core/timing/ClockMappingJson.h"

#include "core/JsonText.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace tactiscope::core::timing {

namespace {

constexpr double kMostDrift = 0.01;
// A device sampling slower than once an hour is no stream: the text was altered.
constexpr double kLongestPeriod_s = 3600.0;

// Each basis and its stored word, one table for writing and reading.
struct BasisWord {
    ClockUncertaintyBasis basis;
    const char* word;
};
constexpr BasisWord kBasisWords[] = {{ClockUncertaintyBasis::Spread, "spread"},
                                     {ClockUncertaintyBasis::Bound, "bound"},
                                     {ClockUncertaintyBasis::TooFewFrames, "too-few-frames"},
                                     {ClockUncertaintyBasis::Exact, "exact"}};

}  // namespace

const char* toString(ClockUncertaintyBasis basis)
{
    for (const auto& entry : kBasisWords)
        if (entry.basis == basis) return entry.word;
    return "too-few-frames";
}

std::string toJson(const ClockMapping& m)
{
    nlohmann::ordered_json json;
    json["reference_s"] = m.reference_s;
    json["offset_s"] = m.offset_s;
    json["drift"] = m.drift;
    json["span_s"] = m.span_s;
    json["pairs"] = m.pairs;
    json["uncertainty"] = toString(m.basis);
    json["offset_u_s"] = m.offset_u_s;
    json["drift_u"] = m.drift_u;
    json["sample_period_s"] = m.samplePeriod_s;
    return json.dump();
}

std::optional<ClockMapping> clockMappingFromJson(std::string_view text)
{
    nlohmann::json json;
    try {
        json = parseJsonText(text, "clock mapping");
    } catch (const JsonTextError&) {
        return std::nullopt;
    }
    if (!json.is_object()) return std::nullopt;
    ClockMapping m;
    const auto number = [&](const char* key, double& into) {
        const auto found = json.find(key);
        if (found == json.end() || !found->is_number()) return false;
        into = found->get<double>();
        return std::isfinite(into);
    };
    double pairs = 0.0;
    if (!number("reference_s", m.reference_s) || !number("offset_s", m.offset_s) || !number("drift", m.drift) ||
        !number("span_s", m.span_s) || !number("pairs", pairs) || !number("offset_u_s", m.offset_u_s) ||
        !number("drift_u", m.drift_u))
        return std::nullopt;
    if (std::abs(m.drift) > kMostDrift || m.offset_u_s < 0.0 || m.drift_u < 0.0 || m.span_s < 0.0 || pairs < 0.0 ||
        pairs > 1e15)
        return std::nullopt;
    m.pairs = static_cast<std::size_t>(pairs);
    // Stores before issue 55 did not keep the sample period: no doubt for it.
    if (json.contains("sample_period_s") &&
        (!number("sample_period_s", m.samplePeriod_s) || m.samplePeriod_s < 0.0 || m.samplePeriod_s > kLongestPeriod_s))
        return std::nullopt;
    const auto basis = json.find("uncertainty");
    if (basis == json.end() || !basis->is_string()) return std::nullopt;
    const std::string word = basis->get<std::string>();
    const auto* entry = std::ranges::find_if(kBasisWords, [&](const BasisWord& e) { return word == e.word; });
    if (entry == std::end(kBasisWords)) return std::nullopt;
    m.basis = entry->basis;
    // An exact mapping states no uncertainty: one that does was altered.
    if (m.basis == ClockUncertaintyBasis::Exact && (m.offset_u_s != 0.0 || m.drift_u != 0.0)) return std::nullopt;
    return m;
}

// host = a + offset + drift·(a − ref) with a = s + origin, and the
// session's time is host − start: s + (origin + offset − start) +
// drift·(s − (ref − origin)).
ClockMapping onSessionClocks(const ClockMapping& mapping, double origin_s, double sessionStart_host_s)
{
    ClockMapping shifted = mapping;
    shifted.reference_s = mapping.reference_s - origin_s;
    shifted.offset_s = origin_s + mapping.offset_s - sessionStart_host_s;
    return shifted;
}

}  // namespace tactiscope::core::timing
