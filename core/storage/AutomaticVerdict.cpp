// AutomaticVerdict: the grounds written as a JSON object.
#include "core/storage/AutomaticVerdict.h"

#include "core/modes/ModeDefinition.h"

#include <nlohmann/json.hpp>

#include <string_view>

namespace tactiscope::core::storage {

VerdictDecision automaticDecision(const std::string& analysis, std::size_t defects, std::size_t sites,
                                  const detector::DetectorParameters& parameters,
                                  const std::optional<detector::ProbeAgreement>& probe)
{
    nlohmann::ordered_json basis;
    basis["analysis"] = analysis;
    basis["defects"] = defects;
    basis["sites"] = sites;
    basis["threshold"] = parameters.threshold;
    basis["epsilon"] = parameters.epsilon;
    if (!parameters.lags_s.empty()) {
        basis["lag_min_s"] = parameters.lags_s.front();
        basis["lag_max_s"] = parameters.lags_s.back();
    }
    basis["lambda"] = parameters.lambdaRule == detector::LambdaRule::EqualsLag ? "lag" : "fixed";
    if (parameters.lambdaRule == detector::LambdaRule::Fixed) basis["lambda_s"] = parameters.fixedLambda_s;
    if (parameters.window_s) basis["window_s"] = *parameters.window_s;
    basis["face_to_face"] = parameters.faceToFace;
    if (probe) basis["probe"] = {{"agreeing", probe->agreeing}, {"compared", probe->compared}};

    VerdictDecision decision;
    decision.role = VerdictRole::Automatic;
    decision.verdict = automaticVerdict(sites);
    decision.basisJson = basis.dump();
    return decision;
}

std::optional<VerdictDecision> partsDecision(std::span<const SessionSummary> parts)
{
    const SessionSummary* decided = nullptr;
    bool unjudged = false;
    nlohmann::ordered_json judged = nlohmann::ordered_json::array();
    for (const SessionSummary& part : parts) {
        if (!part.verdict) {
            // A part whose mode judges, or any part that says why its
            // readings cannot be trusted (past a critical limit).
            unjudged = unjudged || definitionOf(part.metadata.mode).detectsDefects || !part.unjudged.empty();
            continue;
        }
        judged.push_back({{"device", part.metadata.deviceName},
                          {"session", part.id},
                          {"verdict", std::string(toString(*part.verdict))}});
        if (!decided || (*part.verdict == Verdict::DefectsFound && *decided->verdict != Verdict::DefectsFound))
            decided = &part;
    }
    if (!decided || (unjudged && *decided->verdict != Verdict::DefectsFound)) return std::nullopt;
    nlohmann::ordered_json basis;
    basis["analysis"] = "parts";
    basis["decided_by_part"] = decided->metadata.deviceName;
    basis["part_session"] = decided->id;
    basis["parts"] = std::move(judged);
    VerdictDecision decision;
    decision.role = VerdictRole::Automatic;
    decision.verdict = *decided->verdict;
    decision.basisJson = basis.dump();
    return decision;
}

std::string unjudgedReason(const std::string& unjudged)
{
    return unjudged.starts_with(kNotJudged) ? unjudged.substr(kNotJudged.size()) : unjudged;
}

std::string partsUnjudged(std::span<const SessionSummary> parts)
{
    std::string why;
    for (const SessionSummary& part : parts)
        if (!part.unjudged.empty()) why += (why.empty() ? "" : "; ") + part.metadata.deviceName + ": " + part.unjudged;
    return why;
}

}  // namespace tactiscope::core::storage
