// ReportData: the range in samples, the records that overlap it, and the
// copies of profile and calibrations the session carries.
#include "core/report/ReportData.h"

#include "core/derived/CapacitiveChannels.h"
#include "core/derived/SessionLanes.h"
#include "core/storage/DefectRecords.h"
#include "core/storage/StoredSites.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tactiscope::core::report {
namespace {

using Json = nlohmann::json;

std::string profileName(const std::string& profileJson)
{
    if (profileJson.empty()) return {};
    const Json json = Json::parse(profileJson, nullptr, false);
    return json.is_object() && json.contains("name") && json["name"].is_string() ? json["name"].get<std::string>()
                                                                                 : std::string();
}

std::string listed(const std::vector<std::string>& names)
{
    std::string text;
    for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
    return text.empty() ? "none" : text;
}

bool overlaps(double start_s, double end_s, double from_s, double to_s)
{
    return end_s >= from_s && start_s <= to_s;
}

}  // namespace

bool ReportData::wholeSession() const
{
    return from_s <= 0.0 && to_s >= session.duration_s();
}

std::optional<CapacitiveBasis> capacitiveBasis(storage::SessionSource& store, const storage::SessionSummary& session,
                                               std::uint64_t first, std::uint64_t end,
                                               const std::optional<calibration::CalibrationRecord>& calibration)
{
    try {
        const derived::CapacitiveChannels channels(store, session.id, calibration);
        CapacitiveBasis basis{
            {}, channels.calibration(), channels.sensitivity().perNewton_f, channels.sensitivity().perMetre_f};
        const auto baselines = channels.baselines();
        for (std::size_t b = 0; b < baselines.size(); ++b) {
            const std::uint64_t next = b + 1 < baselines.size() ? baselines[b + 1].first : session.sampleCount;
            if (next > first && baselines[b].first < end) basis.baselines_f.push_back(baselines[b].second);
        }
        return basis;
    } catch (const std::invalid_argument&) {
        return std::nullopt;  // no usable profile: the lanes' problem says so
    }
}

ReportData gatherReport(storage::SessionSource& store, std::int64_t session, const ReportRequest& request,
                        std::size_t overviewPoints)
{
    const ReportRange& range = request.range;
    const auto summary = store.session(session);
    if (!summary) throw storage::StorageError("no session " + std::to_string(session) + " in the store");
    if (const auto refusal = storage::oneDeviceRefusal(store, session, "a report"))
        throw std::invalid_argument(*refusal);
    ReportData data;
    data.session = *summary;
    data.sensorName = profileName(summary->metadata.profileJson);
    data.calibrations = calibration::recordsFromJsonArray(summary->metadata.calibrationsJson);
    const double duration_s = summary->duration_s();
    data.from_s = range.from_s.value_or(0.0);
    data.to_s = range.to_s.value_or(duration_s);
    if (!(data.from_s >= 0.0) || !(data.to_s <= duration_s) || !(data.from_s < data.to_s))
        throw std::invalid_argument("the range must lie within the session (0 to " + std::to_string(duration_s) +
                                    " s) and end after it starts");

    const auto analyses = store.analyses(session);
    if (request.analysis != storage::kLiveAnalysis && std::ranges::find(analyses, request.analysis) == analyses.end())
        throw std::invalid_argument("session " + std::to_string(session) + " has no analysis '" + request.analysis +
                                    "' (it has: " + listed(analyses) + ")");
    data.analysis = request.analysis;
    // The analysis's defects; alarms, markers, contacts and presses are the recording's.
    std::vector<storage::SessionEvent> events = store.events(session, request.analysis);
    if (request.analysis != storage::kLiveAnalysis) {
        for (auto& event : store.events(session))
            if (event.kind != EventKind::Defect) events.push_back(std::move(event));
        std::ranges::stable_sort(events, {}, &storage::SessionEvent::start_s);
    }
    for (auto& event : events)
        if (overlaps(event.start_s, event.end_s, data.from_s, data.to_s)) data.events.push_back(std::move(event));
    data.sites = storage::storedSites(store, session, storage::defectEventsOf(data.events));
    data.verdicts = store.verdicts(session);
    for (auto& reading : store.readings(session, request.analysis))
        if (overlaps(reading.start_s, reading.end_s, data.from_s, data.to_s))
            data.readings.push_back(std::move(reading));
    for (auto& annotation : store.annotations(session))
        if (overlaps(annotation.time_s, annotation.time_s, data.from_s, data.to_s))
            data.annotations.push_back(std::move(annotation));

    const double rate_hz = summary->sampleRate_hz;
    const auto first = static_cast<std::uint64_t>(std::floor(data.from_s * rate_hz));
    const auto end = std::min(summary->sampleCount, static_cast<std::uint64_t>(std::ceil(data.to_s * rate_hz)));
    for (const auto& gap : store.gaps(session))
        if (gap.firstIndex < end && gap.firstIndex + gap.count > first) data.gaps.push_back(gap);
    if (summary->metadata.mode == Mode::Capacitive) data.capacitive = capacitiveBasis(store, *summary, first, end);
    std::optional<double> perNewton_f, calibrationLimit_n;
    if (data.capacitive) {
        perNewton_f = data.capacitive->perNewton_f;
        if (data.capacitive->calibration)
            if (const auto limit_mn = data.capacitive->calibration->value("detection_limit_mn"))
                calibrationLimit_n = *limit_mn * 1e-3;
    }
    data.quality = gatherSignalQuality(store, *summary, first, end, perNewton_f, calibrationLimit_n, kMostReportTraces);
    auto lanes = derived::sessionLanes(store, *summary);
    data.derivedBasis = lanes.basis;
    data.derivedProblem = lanes.problem;
    for (const auto& lane : lanes.lanes) {
        if (data.traces.size() == kMostReportTraces) {  // the rest are summarised, not read
            ++data.tracesLeftOut;
            continue;
        }
        auto points = lane->overview(first, end - first, overviewPoints);
        // k_o is in the readings table, per press; a lane with nothing to
        // draw (Q over a range too long to read exactly) is left out.
        if (points.empty() || lane->descriptor().name == "stiffness") continue;
        data.traces.push_back({{lane->descriptor(), rate_hz}, std::move(points), lane->threshold()});
    }
    return data;
}

}  // namespace tactiscope::core::report
