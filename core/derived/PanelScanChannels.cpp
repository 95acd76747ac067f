// PanelScanChannels: the recorded parameters, then the offline detector
// over each read range and the warm-up before it.
#include "core/derived/PanelScanChannels.h"

#include "core/ModeCapability.h"
#include "core/derived/ExactOverview.h"
#include "core/detector/StreamingDetection.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace tactiscope::core::derived {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

detector::DetectorParameters recordedDetectorParameters(const std::vector<storage::VerdictDecision>& verdicts,
                                                        double sampleRate_hz)
{
    detector::DetectorParameters parameters;
    parameters.sampleInterval_s = 1.0 / sampleRate_hz;
    parameters.lags_s = detector::liveLags_s(sampleRate_hz);
    const auto automatic = std::ranges::find(verdicts, VerdictRole::Automatic, &storage::VerdictDecision::role);
    if (automatic == verdicts.end()) return parameters;
    const auto basis = nlohmann::json::parse(automatic->basisJson, nullptr, false);
    if (!basis.is_object()) return parameters;
    const auto number = [&](const char* key, double& into) {
        if (basis.contains(key) && basis[key].is_number()) into = basis[key].get<double>();
    };
    number("threshold", parameters.threshold);
    number("epsilon", parameters.epsilon);
    if (basis.contains("face_to_face") && basis["face_to_face"].is_boolean())
        parameters.faceToFace = basis["face_to_face"].get<bool>();
    if (basis.contains("lambda") && basis["lambda"] == "fixed") {
        parameters.lambdaRule = detector::LambdaRule::Fixed;
        number("lambda_s", parameters.fixedLambda_s);
    }
    if (basis.contains("window_s") && basis["window_s"].is_number())
        parameters.window_s = basis["window_s"].get<double>();
    return parameters;
}

PanelScanChannels::PanelScanChannels(storage::SessionSource& store, std::int64_t session)
    : m_store(store),
      m_session(session)
{
    const auto summary = store.session(session);
    if (!summary) throw storage::StorageError("there is no session " + std::to_string(session));
    if (summary->metadata.mode != Mode::PanelScan)
        throw std::invalid_argument("session " + std::to_string(session) + " is not a panel-scan session");
    std::vector<ChannelDescriptor> raw;
    for (const auto& channel : store.channels(session)) raw.push_back(channel.descriptor);
    const auto picked = modeChannels(Mode::PanelScan, raw);
    if (!picked) throw std::invalid_argument(*modeRefusal(Mode::PanelScan, raw));
    m_cantilevers = *picked;
    m_sampleCount = summary->sampleCount;
    m_parameters = recordedDetectorParameters(store.verdicts(session), summary->sampleRate_hz);
    const auto resolved = detector::resolve(m_parameters);  // throws for a rate the detector cannot run at
    const double longestMemory_s = m_parameters.lambdaRule == detector::LambdaRule::Fixed ? m_parameters.fixedLambda_s
                                                                                          : m_parameters.lags_s.back();
    m_warmUp = resolved.maxLag() + (resolved.window > 0
                                        ? resolved.window
                                        : static_cast<std::uint64_t>(std::ceil(kWarmUpMemories * longestMemory_s /
                                                                               m_parameters.sampleInterval_s)));
    std::ostringstream basis;
    basis << "the detector of seed 000 on " << m_cantilevers.size() << " cantilevers, lags "
          << m_parameters.lags_s.front() * 1e3 << "–" << m_parameters.lags_s.back() * 1e3 << " ms, threshold "
          << m_parameters.threshold << ", ε " << m_parameters.epsilon * 1e6 << " µε";
    m_basis = basis.str();
}

std::vector<ChannelDescriptor> PanelScanChannels::channels() const
{
    return {{"best_r", "", ChannelKind::Other}, {"decision", "", ChannelKind::Other}};
}

std::vector<std::vector<double>> PanelScanChannels::read(std::uint64_t first, std::uint64_t count)
{
    const std::uint64_t end = std::min(m_sampleCount, first + std::min(count, m_sampleCount));
    const std::uint64_t n = end > first ? end - first : 0;
    if (!m_cached.empty() && m_cachedFirst == first && m_cached.front().size() == n) return m_cached;
    std::vector<std::vector<double>> out(2, std::vector<double>(n, kNaN));
    const std::uint64_t start = first > m_warmUp ? first - m_warmUp : 0;
    std::vector<std::vector<double>> strains;
    m_store.readChannels(m_session, m_cantilevers, start, end - start, strains);
    // Each stretch without a lost sample restarts the detector, as the live one did.
    detector::StreamingDetection detection(m_cantilevers.size(), {m_parameters, 0.0, std::nullopt, 1}, 0.0,
                                           [&](std::uint64_t runFirst, std::span<const detector::ProbeOutput> outputs) {
                                               for (std::size_t i = 0; i < outputs.size(); ++i) {
                                                   const std::uint64_t index = start + runFirst + i;
                                                   if (index < first) continue;
                                                   const auto& o = outputs[i].combined;
                                                   out[0][index - first] = std::max(o.rab, o.rba);
                                                   out[1][index - first] = o.decision;
                                               }
                                           });
    const std::vector<std::span<const double>> series(strains.begin(), strains.end());
    detection.push(series);
    m_cachedFirst = first;
    m_cached = out;
    return out;
}

std::vector<storage::OverviewPoint> PanelScanChannels::overview(std::size_t channel, std::uint64_t first,
                                                                std::uint64_t count, std::size_t points)
{
    if (channel >= 2) throw std::out_of_range("no detector channel " + std::to_string(channel));
    const std::uint64_t end = std::min(m_sampleCount, first + std::min(count, m_sampleCount));
    if (end <= first || points == 0 || end - first > kExactLimit) return {};
    std::vector<storage::OverviewPoint> result;
    appendExactOverview(read(first, end - first)[channel], first, points, result);
    return result;
}

}  // namespace tactiscope::core::derived
