// A detector's defect as a session record, and back: the one place a
// DefectEvent becomes a stored "defect" event, whether live, from `tactiscope-cli
// analyze --save` or from a re-analysis saved in the review window.
#pragma once

#include "core/detector/DefectEvent.h"
#include "core/storage/SessionRecords.h"

#include <span>
#include <string>
#include <vector>

namespace tactiscope::core::storage {

// An alarm of the record, from start_s to end_s (an instant: the same),
// with what it says: the live session's and its units' alike.
inline SessionEvent alarmRecord(double start_s, double end_s, std::string note)
{
    SessionEvent event;
    event.kind = EventKind::Alarm;
    event.start_s = start_s;
    event.end_s = end_s;
    event.note = std::move(note);
    return event;
}

// A note at one instant: what the user marked, or what the recording must
// carry from its start (how a text board's rate was found).
inline SessionEvent noteRecord(double time_s, std::string note)
{
    SessionEvent event;
    event.kind = EventKind::Marker;
    event.start_s = event.end_s = time_s;
    event.note = std::move(note);
    return event;
}

inline SessionEvent defectRecord(const detector::DefectEvent& e, const std::string& analysis = kLiveAnalysis)
{
    SessionEvent event;
    event.analysis = analysis;
    event.kind = EventKind::Defect;
    event.start_s = e.start_s;
    event.end_s = e.end_s;
    event.direction = e.direction;
    event.peakR = e.peakR;
    event.lag_s = e.peakLag_s;
    event.speed_m_per_s = e.speed_m_per_s;
    return event;
}

inline std::vector<SessionEvent> defectRecords(std::span<const detector::DefectEvent> events,
                                               const std::string& analysis)
{
    std::vector<SessionEvent> records;
    records.reserve(events.size());
    for (const auto& e : events) records.push_back(defectRecord(e, analysis));
    return records;
}

// The stored defects among `events` back as the detector's (other kinds
// are left out), e.g. to group them into sites.
inline std::vector<detector::DefectEvent> defectEventsOf(std::span<const SessionEvent> events)
{
    std::vector<detector::DefectEvent> defects;
    for (const SessionEvent& e : events) {
        if (e.kind != EventKind::Defect) continue;
        // No position: a stored session's is read from its channel (StoredSites.h).
        defects.push_back({e.start_s, e.end_s, e.direction, e.peakR.value_or(0.0), e.lag_s.value_or(0.0),
                           e.speed_m_per_s, std::nullopt});
    }
    return defects;
}

}  // namespace tactiscope::core::storage
