// A station's store written through the store API with everything a
// session can hold, for tests that copy sessions between stores: a panel
// scan with a gap, live and saved events, an annotation, a verdict trail
// and its channels' roles; a palpation session with readings, a zero and a calibration it
// used; and an interrupted capacitive session. Sample values are irrational-looking binary32s (see valueAt).
#pragma once

#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"

#include <cmath>
#include <string>
#include <vector>

namespace tactiscope::testing {

inline double stationValueAt(std::size_t channel, std::uint64_t index, int seed)
{
    return std::sin(0.001 * static_cast<double>(index) * (1 + seed)) * 1e-4 + static_cast<double>(channel) * 0.1;
}

// Samples [first, first + count) of `channels` channels at `rate_hz`.
inline core::SampleBlock stationBlock(std::size_t channels, std::uint64_t first, std::size_t count, double rate_hz,
                                      int seed)
{
    core::SampleBlock b(channels, count, static_cast<double>(first) / rate_hz, 1.0 / rate_hz, first);
    for (std::size_t c = 0; c < channels; ++c)
        for (std::size_t s = 0; s < count; ++s) b.channel(c)[s] = stationValueAt(c, first + s, seed);
    return b;
}

// Writes `samples` per channel in blocks of 500, leaving out
// [gapFirst, gapFirst + gapCount).
inline void writeSamples(core::storage::SessionStore& store, std::int64_t session, std::size_t channels,
                         std::uint64_t samples, double rate_hz, int seed, std::uint64_t gapFirst = 0,
                         std::uint64_t gapCount = 0)
{
    for (std::uint64_t first = 0; first < samples; first += 500) {
        const auto count = static_cast<std::size_t>(std::min<std::uint64_t>(500, samples - first));
        if (gapCount > 0 && first >= gapFirst && first < gapFirst + gapCount) continue;
        store.appendBlocks(session, std::vector{stationBlock(channels, first, count, rate_hz, seed)});
    }
}

struct StationStoreOptions {
    std::string subjectPrefix = "door";
    int seed = 0;
    std::uint64_t panelSamples = 6000;  // per channel, at 2 kHz
};

// Returns the number of sessions written.
inline int writeStationStore(const std::string& path, const StationStoreOptions& o = {})
{
    using namespace core;
    using namespace core::storage;
    SessionStore store(path);

    const std::vector<ChannelDescriptor> panelChannels{{"a", "", ChannelKind::Strain, ChannelRole::CantileverA},
                                                       {"b", "", ChannelKind::Strain, ChannelRole::CantileverB}};
    SessionMetadata panel;
    panel.mode = Mode::PanelScan;
    panel.subject = o.subjectPrefix + "-17";
    panel.operatorName = "Ada";
    panel.site = "line 2";
    panel.notes = "left door, ünïcode note";
    panel.deviceSerial = "SN-" + std::to_string(o.seed);
    const auto scan = store.beginSession(panel, panelChannels, 2000.0);
    writeSamples(store, scan, 2, o.panelSamples, 2000.0, o.seed, 1000, 500);
    SessionEvent defect;
    defect.kind = EventKind::Defect;
    defect.start_s = 0.25;
    defect.end_s = 0.3;
    defect.direction = 1;
    defect.peakR = 0.91;
    defect.lag_s = 0.0125;
    defect.speed_m_per_s = 0.4;
    SessionEvent saved = defect;
    saved.analysis = "second look";
    saved.direction = -1;
    store.addEvents(scan, std::vector{defect, saved});
    store.addAnnotation(scan,
                        {0, 0.27, "Grace", "a dent, 2 mm", "2026-11-24T10:00:05.000Z", "2026-11-24T10:00:05.000Z"});
    store.decideVerdict(scan, {0, VerdictRole::Automatic, Verdict::DefectsFound, "", "2026-11-24T10:00:04.000Z", "",
                               R"({"analysis":"live","defects":1})"});
    store.decideVerdict(
        scan, {0, VerdictRole::Operator, Verdict::DefectsFound, "Ada", "2026-11-24T10:00:06.000Z", "confirmed", ""});
    store.endSession(scan, SessionStatus::Complete);

    const std::vector<ChannelDescriptor> palpationChannels{{"high", "N", ChannelKind::Force},
                                                           {"low", "N", ChannelKind::Force}};
    SessionMetadata palpation;
    palpation.mode = Mode::Palpation;
    palpation.subject = "phantom-" + std::to_string(o.seed);
    palpation.operatorName = "Dr. Lin";
    const auto palp = store.beginSession(palpation, palpationChannels, 500.0);
    writeSamples(store, palp, 2, 1500, 500.0, o.seed + 1);
    store.addZero(palp, {0, R"({"high": 2051.3, "low": 1998.7})"});
    store.addReading(
        palp, {0, ReadingKind::Compliance, 0.5, 1.5, "stiffness", 812.5, "N/m", 12.25, "B3", R"({"presses":3})"});
    calibration::CalibrationRecord record;
    record.kind = "gauge_factor";
    record.sensorName = "probe-" + std::to_string(o.seed);
    record.operatorName = "Grace";
    record.timestampUtc = "2026-11-20T09:00:00Z";
    record.values = {{"gauge_factor", 2.1}};
    record.fit.slope = 2.1e-3;
    record.fit.rSquared = 0.9995;
    record.fit.points = 3;
    record.fit.residuals = {1e-5, -2e-5, 1e-5};
    store.linkCalibration(palp, store.addCalibration(record));
    store.endSession(palp, SessionStatus::Complete);

    const std::vector<ChannelDescriptor> capacitiveChannels{{"C", "pF", ChannelKind::Capacitance}};
    SessionMetadata capacitive;
    capacitive.mode = Mode::Capacitive;
    capacitive.subject = "beam-" + std::to_string(o.seed);
    const auto cap = store.beginSession(capacitive, capacitiveChannels, 100.0);
    writeSamples(store, cap, 1, 700, 100.0, o.seed + 2);
    store.markLostUntil(cap, 750);
    store.endSession(cap, SessionStatus::Interrupted, "");
    return 3;
}

}  // namespace tactiscope::testing
