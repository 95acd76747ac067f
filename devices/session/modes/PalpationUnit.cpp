// PalpationUnit: the probe's forces, its presses and zeros.
#include "devices/session/modes/PalpationUnit.h"

#include "core/calibration/CalibrationRecord.h"
#include "core/storage/DefectRecords.h"
#include "core/storage/Recorder.h"
#include "core/text/CountText.h"
#include "devices/session/modes/StoredCalibrationLookup.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <variant>

namespace tactiscope::devices::session {

PalpationUnit::PalpationUnit(const LiveUnitSetup& setup)
{
    const auto& probe = std::get<core::sensors::CompliancePairProfile>(*setup.profile);
    // Each beam reads through its newest gauge-factor calibration, if any.
    std::vector<core::storage::StoredCalibration> newest;
    for (const bool stiff : {true, false}) {
        if (auto record = newestCalibration(setup, core::calibration::kGaugeFactorKind,
                                            core::calibration::beamSensorName(probe.name, stiff)))
            newest.push_back(std::move(*record));
    }
    std::vector<core::calibration::CalibrationRecord> records;
    for (const auto& stored : newest) records.push_back(stored.record);
    std::vector<std::size_t> usable;
    const auto settings = core::compliance::palpationSettings(probe, setup.rate_hz, setup.channels, records, &usable);
    try {
        m_palpation = std::make_shared<core::compliance::LivePalpation>(setup.channels, setup.rate_hz, settings,
                                                                        setup.displaySeconds);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("the profile '" + probe.name + "' cannot be used: " + e.what());
    }
    for (const std::size_t i : usable) m_calibrations.push_back(newest[i]);
    // Said when the probe is set up too, not only in each record.
    if (const auto unjudged = m_palpation->unjudgedClipping(); unjudged && setup.problems)
        setup.problems->push_back(*unjudged);
    if (const auto* previous = dynamic_cast<const PalpationUnit*>(setup.previous)) {
        m_palpation->inheritZero(*previous->m_palpation);
        m_siteGrid = previous->m_siteGrid;  // the phantom is the same
    }
}

void PalpationUnit::setSiteGrid(std::optional<core::compliance::SiteGrid> grid)
{
    // The same grid keeps its selection (the view sets it on every poll).
    if (grid && m_siteGrid && grid->rows() == m_siteGrid->rows() && grid->columns() == m_siteGrid->columns()) return;
    if (grid && m_siteGrid) grid->select(m_siteGrid->current());
    m_siteGrid = std::move(grid);
}

void PalpationUnit::selectSite(core::compliance::SiteCell cell)
{
    if (m_siteGrid) m_siteGrid->select(cell);
}

// The zero in use reads the session's first samples (it applies from
// index 0); those taken before were dropped. A beam whose clipping is not
// judged is said in the record, since its readings rest on it.
void PalpationUnit::startRecording(core::storage::Recorder& recorder)
{
    if (const auto zero = m_palpation->currentZero())
        recorder.addZero(zero->firstIndex, core::compliance::zeroJson(zero->zero));
    if (const auto unjudged = m_palpation->unjudgedClipping())
        recorder.addEvents({core::storage::noteRecord(0.0, *unjudged)});
}

namespace {

// Why a press gave no stiffness, for the record.
std::string unreadPressText(const core::compliance::PressReading& press)
{
    char span[64];
    std::snprintf(span, sizeof span, "the press at %.2f–%.2f s", press.start_s, press.end_s);
    switch (press.status) {
    case core::compliance::PressStatus::Clipped:
        return std::string(span) + " reached a beam's converter limit: no reading (press less deep)";
    case core::compliance::PressStatus::BelowRange:
    case core::compliance::PressStatus::AboveRange:
        return std::string(span) + " is outside the probe's range (its force ratio gives no stiffness): no reading";
    case core::compliance::PressStatus::Ok:
        break;
    }
    return span;
}

}  // namespace

void PalpationUnit::take(const LiveTake& take)
{
    std::vector<core::storage::SessionReading> stored;
    std::vector<core::storage::SessionEvent> notes;
    for (auto& press : resultsForLists(m_later, m_palpation->takeReadings(), take)) {
        PressRecord record{std::move(press), m_siteGrid ? m_siteGrid->currentName() : take.recordingSite, false};
        // Out of range or clipped is a state, not a stiffness: shown, not stored as a number.
        if (take.recorder && record.press.status == core::compliance::PressStatus::Ok) {
            core::storage::SessionReading reading;
            reading.kind = core::ReadingKind::Compliance;
            reading.quantity = "stiffness";
            reading.unit = "N/m";
            reading.start_s = record.press.start_s;
            reading.end_s = record.press.end_s;
            reading.value = record.press.stiffness.objectStiffness_n_per_m;
            reading.standardError = record.press.uncertainty_n_per_m();
            reading.site = record.site;
            reading.detailsJson = core::compliance::pressDetailsJson(record.press);
            stored.push_back(std::move(reading));
            record.stored = true;
            if (m_siteGrid) m_siteGrid->advance();  // the site has its reading: the next press is the next site's
        } else if (take.recorder) {
            // A press that gives no number is said in the record, so that it
            // is not taken for one that was never made.
            notes.push_back(core::storage::noteRecord(record.press.start_s, unreadPressText(record.press)));
        }
        m_presses.push_back(std::move(record));
    }
    // A press begun in the recording and not ended in it gives no reading
    // there: said, as a clipped one is (its samples past the end are not
    // the recording's).
    if (take.recorder && take.recordingEnds) {
        std::vector<double> unended;
        for (const auto& press : m_later)
            if (press.start_s <= take.recordedUntil_s) unended.push_back(press.start_s);
        if (const auto start = m_palpation->state().pressStart_s; start && *start <= take.recordedUntil_s)
            unended.push_back(*start);
        for (const double start_s : unended) {
            char text[112];
            std::snprintf(text, sizeof text,
                          "the press at %.2f s was still under way when the recording ended: no reading",
                          take.listTime_s(start_s));
            notes.push_back(core::storage::noteRecord(take.listTime_s(start_s), text));
        }
    }
    if (!stored.empty()) take.recorder->addReadings(std::move(stored));
    if (!notes.empty()) take.recorder->addEvents(std::move(notes));
}

// A zero taken again because the one before was under a load is told,
// and kept as a note where it was taken: what came before read wrongly.
void PalpationUnit::takeZeros(const LiveTake& take)
{
    std::vector<core::storage::SessionEvent> notes;
    for (const auto& zero : m_palpation->takeZeroChanges()) {
        if (!zero.note.empty()) {
            if (take.tell) take.tell(zero.time_s, zero.note);
            if (take.recorder) notes.push_back(core::storage::noteRecord(take.listTime_s(zero.time_s), zero.note));
        }
        if (take.recorder) take.recorder->addZero(zero.firstIndex, core::compliance::zeroJson(zero.zero));
    }
    if (!notes.empty()) take.recorder->addEvents(std::move(notes));
}

std::string PalpationUnit::storedText(const RecordingSummary&) const
{
    const auto stored = static_cast<std::size_t>(std::ranges::count_if(m_presses, &PressRecord::stored));
    std::string text = core::text::countText(stored, "stiffness reading", "stiffness readings") + " stored";
    const auto unread = static_cast<std::size_t>(std::ranges::count_if(
        m_presses, [](const PressRecord& record) { return record.press.status != core::compliance::PressStatus::Ok; }));
    if (unread > 0)
        text += "; " + core::text::countText(unread, "press", "presses") +
                " gave none (clipped or out of the probe's range: the notes say which)";
    return text;
}

}  // namespace tactiscope::devices::session
