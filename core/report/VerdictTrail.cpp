// VerdictTrail: each decision compared with the one before it.
#include "core/report/VerdictTrail.h"

#include "core/detector/ProbeDecisionCheck.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <sstream>

namespace tactiscope::core::report {
namespace {

// "2026-11-23T14:13:05.123Z" → day "2026-11-23", minute "14:13".
struct UtcParts {
    std::string day;
    std::string minute;
};

UtcParts partsOf(const std::string& utc)
{
    if (utc.size() < 16 || utc[10] != 'T') return {utc, {}};
    return {utc.substr(0, 10), utc.substr(11, 5)};
}

// A session of several devices is decided by its parts: the worst of their
// verdicts, each named by its device.
std::string partsBasisText(const nlohmann::json& basis)
{
    std::ostringstream text;
    text << "the worst of its parts'";
    const auto parts = basis.find("parts");
    if (parts == basis.end() || !parts->is_array()) return text.str();
    const char* separator = ": ";
    for (const auto& part : *parts) {
        if (!part.is_object() || !part.value("device", nlohmann::json()).is_string() ||
            !part.value("verdict", nlohmann::json()).is_string())
            continue;
        text << separator << part["device"].get<std::string>() << " " << part["verdict"].get<std::string>();
        separator = ", ";
    }
    return text.str();
}

}  // namespace

std::string basisText(const std::string& basisJson)
{
    const auto basis = nlohmann::json::parse(basisJson, nullptr, false);
    if (!basis.is_object() || !basis.contains("analysis") || !basis["analysis"].is_string()) return {};
    if (basis["analysis"] == "parts") return partsBasisText(basis);
    const auto count = [&](const char* key) {
        return basis.contains(key) && basis[key].is_number_unsigned() ? basis[key].get<std::size_t>() : 0;
    };
    const std::size_t defects = count("defects");
    const std::size_t sites = count("sites");
    std::ostringstream text;
    text << basis["analysis"].get<std::string>() << " detector: " << defects << (defects == 1 ? " defect" : " defects");
    if (defects > 0) text << " at " << sites << (sites == 1 ? " site" : " sites");
    if (basis.contains("threshold") && basis["threshold"].is_number())
        text << ", threshold " << basis["threshold"].get<double>();
    // A probe's own decisions beside the workstation's: how far they agreed.
    if (const auto probe = basis.find("probe"); probe != basis.end() && probe->is_object()) {
        const auto probeCount = [&](const char* key) -> std::optional<std::uint64_t> {
            const auto v = probe->find(key);
            return v != probe->end() && v->is_number_unsigned() ? std::optional(v->get<std::uint64_t>()) : std::nullopt;
        };
        if (const auto agreeing = probeCount("agreeing"), compared = probeCount("compared"); agreeing && compared)
            text << "; " << detector::agreementText({*compared, *agreeing});
    }
    return text.str();
}

std::vector<std::string> verdictTrailLines(std::span<const storage::VerdictDecision> trail, const DecisionTime& time)
{
    std::vector<std::string> lines;
    std::optional<Verdict> previous;
    std::string previousDay;
    for (const storage::VerdictDecision& d : trail) {
        std::string line(toString(d.role));
        if (d.role != VerdictRole::Automatic)
            line += " " + (d.decidedBy.empty() ? std::string("(unnamed)") : d.decidedBy);
        const std::string verdict(toString(d.verdict));
        if (d.role == VerdictRole::Automatic || !previous)
            line += (d.role == VerdictRole::Automatic ? ": " : " decided: ") + verdict;
        else
            line += *previous == d.verdict ? " kept it" : " changed it to " + verdict;
        if (const std::string basis = basisText(d.basisJson); !basis.empty()) line += " (" + basis + ")";
        const UtcParts when = partsOf(d.decidedUtc);
        line += ", " + (time ? time(d.decidedUtc)
                             : (when.day == previousDay ? std::string() : when.day + " ") + when.minute + " UTC");
        if (!d.note.empty()) line += ": \"" + d.note + "\"";
        lines.push_back(std::move(line));
        previous = d.verdict;
        previousDay = when.day;
    }
    return lines;
}

std::string unjudgedTrailLine(const std::string& unjudged)
{
    return unjudged.empty() ? std::string() : "automatic: none, " + unjudged;
}

}  // namespace tactiscope::core::report
