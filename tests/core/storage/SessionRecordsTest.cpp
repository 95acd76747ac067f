// Events, readings, annotations and calibrations round trip through a real
// store; sessions are filtered by date, mode, subject, operator, verdict
// and text; deleting a session takes its records with it.
#include "core/storage/SessionStore.h"

#include "support/TempDirectory.h"

#include <gtest/gtest.h>

using namespace tactiscope::core;
using namespace tactiscope::core::storage;

namespace {

using SessionRecordsTest = tactiscope::testing::TempDirectoryTest;

const std::vector<ChannelDescriptor> kOneChannel{{"f", "N", ChannelKind::Force}};

std::int64_t begin(SessionStore& store, tactiscope::core::Mode mode, const std::string& subject,
                   const std::string& operatorName, const std::string& notes = {})
{
    SessionMetadata metadata;
    metadata.mode = mode;
    metadata.subject = subject;
    metadata.operatorName = operatorName;
    metadata.notes = notes;
    return store.beginSession(metadata, kOneChannel, 100.0);
}

std::vector<std::int64_t> idsOf(const std::vector<SessionSummary>& sessions)
{
    std::vector<std::int64_t> ids;
    for (const auto& s : sessions) ids.push_back(s.id);
    return ids;
}

calibration::CalibrationRecord gaugeCalibration(const std::string& sensor, const std::string& when, double factor)
{
    calibration::CalibrationRecord record;
    record.kind = "gauge_factor";
    record.sensorName = sensor;
    record.operatorName = "Grace";
    record.timestampUtc = when;
    record.values = {{"gauge_factor", factor}, {"offset_strain", -1.5e-6}};
    record.fit.slope = factor * 1e-3;
    record.fit.intercept = 0.25;
    record.fit.rSquared = 0.9995;
    record.fit.slopeStandardError = 1e-5;
    record.fit.interceptStandardError = 2e-5;
    record.fit.residualStandardDeviation = 3e-5;
    record.fit.residuals = {1e-5, -2e-5, 1e-5};
    record.fit.points = 3;
    return record;
}

}  // namespace

TEST_F(SessionRecordsTest, EventsOfEachAnalysisRoundTrip)
{
    SessionStore store(file("r.tactiscope"));
    const auto id = begin(store, tactiscope::core::Mode::PanelScan, "door-1", "Ada");
    const std::vector<SessionEvent> live{
        {0, kLiveAnalysis, tactiscope::core::EventKind::Defect, 1.25, 1.5, 1, 0.93, 0.052, 0.96, ""},
        {0, kLiveAnalysis, tactiscope::core::EventKind::Marker, 0.5, 0.5, 0, std::nullopt, std::nullopt, std::nullopt,
         "scratch seen here"},
        {0, kLiveAnalysis, tactiscope::core::EventKind::Alarm, 2.0, 2.0, 0, std::nullopt, std::nullopt, std::nullopt,
         "samples lost"},
    };
    store.addEvents(id, live);
    store.addEvents(id, std::vector<SessionEvent>{{0, "threshold 0.9", tactiscope::core::EventKind::Defect, 1.3, 1.45,
                                                   -1, 0.91, 0.05, std::nullopt, ""}});

    const auto events = store.events(id);
    ASSERT_EQ(events.size(), 3u);  // in time order, the re-analysis apart
    EXPECT_EQ(events[0].kind, tactiscope::core::EventKind::Marker);
    EXPECT_EQ(events[0].note, "scratch seen here");
    EXPECT_FALSE(events[0].peakR);
    EXPECT_EQ(events[1].kind, tactiscope::core::EventKind::Defect);
    EXPECT_EQ(events[1].start_s, 1.25);
    EXPECT_EQ(events[1].end_s, 1.5);
    EXPECT_EQ(events[1].direction, 1);
    EXPECT_EQ(events[1].peakR, 0.93);
    EXPECT_EQ(events[1].lag_s, 0.052);
    EXPECT_EQ(events[1].speed_m_per_s, 0.96);
    EXPECT_GT(events[1].id, 0);
    EXPECT_EQ(store.analyses(id), (std::vector<std::string>{"live", "threshold 0.9"}));
    const auto again = store.events(id, "threshold 0.9");
    ASSERT_EQ(again.size(), 1u);
    EXPECT_EQ(again[0].direction, -1);
    EXPECT_FALSE(again[0].speed_m_per_s);
    EXPECT_EQ(store.session(id)->eventCount, 3u);  // live events only
}

TEST_F(SessionRecordsTest, ReadingsAndAnnotationsRoundTrip)
{
    SessionStore store(file("r.tactiscope"));
    const auto id = begin(store, tactiscope::core::Mode::Palpation, "phantom-3", "Lin");
    const auto reading = store.addReading(id, {0, tactiscope::core::ReadingKind::Compliance, 3.0, 4.5, "stiffness",
                                               812.5, "N/m", 12.25, "B3", R"({"slope":0.97})"});
    store.addReading(
        id, {0, tactiscope::core::ReadingKind::Compliance, 1.0, 2.0, "stiffness", 400.0, "N/m", std::nullopt, "", ""});
    const auto readings = store.readings(id);
    ASSERT_EQ(readings.size(), 2u);
    EXPECT_EQ(readings[0].value, 400.0);
    EXPECT_FALSE(readings[0].standardError);
    EXPECT_EQ(readings[1].id, reading);
    EXPECT_EQ(readings[1].end_s, 4.5);
    EXPECT_EQ(readings[1].quantity, "stiffness");
    EXPECT_EQ(readings[1].unit, "N/m");
    EXPECT_EQ(readings[1].standardError, 12.25);
    EXPECT_EQ(readings[1].site, "B3");
    EXPECT_EQ(readings[1].detailsJson, R"({"slope":0.97})");

    const auto note = store.addAnnotation(id, {0, 3.5, "Dr. Reviewer", "press too fast", "", ""});
    store.addAnnotation(id, {0, 0.25, "Dr. Reviewer", "probe warming up", "", ""});
    store.updateAnnotation(note, "press too fast; repeat at site B3");
    auto annotations = store.annotations(id);
    ASSERT_EQ(annotations.size(), 2u);
    EXPECT_EQ(annotations[1].id, note);
    EXPECT_EQ(annotations[1].time_s, 3.5);
    EXPECT_EQ(annotations[1].author, "Dr. Reviewer");
    EXPECT_EQ(annotations[1].text, "press too fast; repeat at site B3");
    EXPECT_EQ(annotations[1].createdUtc.size(), 24u);
    EXPECT_GE(annotations[1].modifiedUtc, annotations[1].createdUtc);
    store.deleteAnnotation(annotations[0].id);
    EXPECT_EQ(store.annotations(id).size(), 1u);
    EXPECT_THROW(store.updateAnnotation(9999, "x"), StorageError);
    EXPECT_THROW(store.deleteAnnotation(9999), StorageError);
}

TEST_F(SessionRecordsTest, CalibrationsAreKeptAcrossSessionsWithTheirStatistics)
{
    SessionStore store(file("r.tactiscope"));
    const auto older = store.addCalibration(gaugeCalibration("beam-A", "2026-10-01T08:00:00Z", 2.05));
    const auto newer = store.addCalibration(gaugeCalibration("beam-A", "2026-11-01T08:00:00Z", 2.11));
    const auto other = store.addCalibration(gaugeCalibration("beam-B", "2026-10-15T08:00:00Z", 1.98));
    const auto first = begin(store, tactiscope::core::Mode::PanelScan, "door-1", "Ada");
    const auto second = begin(store, tactiscope::core::Mode::PanelScan, "door-2", "Ada");
    store.linkCalibration(first, older);
    store.linkCalibration(second, newer);
    store.linkCalibration(second, other);
    store.linkCalibration(second, other);  // once is enough

    const auto history = store.calibrations("beam-A");
    ASSERT_EQ(history.size(), 2u);
    EXPECT_EQ(history[0].id, older);
    EXPECT_EQ(history[1].record.value("gauge_factor"), 2.11);
    const auto stored = store.calibration(newer)->record;
    const auto original = gaugeCalibration("beam-A", "2026-11-01T08:00:00Z", 2.11);
    EXPECT_EQ(stored.toJson(), original.toJson());  // every field, in order, to the last digit
    EXPECT_EQ(stored.fit.residuals, original.fit.residuals);
    EXPECT_EQ(store.calibrations().size(), 3u);
    EXPECT_FALSE(store.calibration(12345));

    EXPECT_EQ(store.calibrationsOfSession(second), (std::vector<std::int64_t>{newer, other}));
    EXPECT_EQ(store.sessionsUsingCalibration(older), (std::vector<std::int64_t>{first}));
    // A calibration in use cannot vanish; a deleted session lets go of it.
    EXPECT_THROW(store.database().exec("DELETE FROM calibrations WHERE id = " + std::to_string(older)), StorageError);
    store.endSession(first, tactiscope::core::SessionStatus::Complete);
    store.deleteSession(first);
    EXPECT_TRUE(store.sessionsUsingCalibration(older).empty());
}

TEST_F(SessionRecordsTest, DeletingASessionDeletesItsRecords)
{
    SessionStore store(file("r.tactiscope"));
    const auto id = begin(store, tactiscope::core::Mode::Capacitive, "beam-7", "Mo");
    store.addEvents(id, std::vector<SessionEvent>{
                            {0, kLiveAnalysis, tactiscope::core::EventKind::Alarm, 1, 1, 0, {}, {}, {}, "x"}});
    store.addReading(id, {0, tactiscope::core::ReadingKind::Capacitive, 1, 2, "force", 12.5, "uN", 0.5, "", ""});
    store.addAnnotation(id, {0, 1.0, "me", "hello", "", ""});
    store.endSession(id, tactiscope::core::SessionStatus::Complete);
    store.deleteSession(id);
    for (const char* table : {"events", "readings", "annotations", "channels", "lod"}) {
        auto count = store.database().prepare(std::string("SELECT count(*) FROM ") + table);
        ASSERT_TRUE(count.step());
        EXPECT_EQ(count.int64(0), 0) << table;
    }
}

TEST_F(SessionRecordsTest, SessionsAreFilteredByEveryField)
{
    SessionStore store(file("r.tactiscope"));
    const auto a = begin(store, tactiscope::core::Mode::PanelScan, "door-17", "Ada", "left fender, 50% speed");
    const auto b = begin(store, tactiscope::core::Mode::PanelScan, "door-18", "Grace");
    const auto c = begin(store, tactiscope::core::Mode::Palpation, "phantom-3", "Ada");
    const auto d = begin(store, tactiscope::core::Mode::Capacitive, "beam-7", "Lin", "Door seal test");
    // Known start times, so the date filter has something to bite on.
    const char* starts[] = {"2026-11-01T09:00:00.000Z", "2026-11-02T09:00:00.000Z", "2026-11-03T09:00:00.000Z",
                            "2026-11-04T09:00:00.000Z"};
    for (std::int64_t id : {a, b, c, d}) {
        store.database()
            .prepare("UPDATE sessions SET started_utc = ? WHERE id = ?")
            .bind(1, std::string_view(starts[id - a]))
            .bind(2, id)
            .run();
    }
    store.setVerdict(a, tactiscope::core::Verdict::DefectsFound);
    store.setVerdict(b, tactiscope::core::Verdict::Pass);
    EXPECT_THROW(store.setVerdict(999, tactiscope::core::Verdict::Pass), StorageError);

    const auto query = [&](const SessionFilter& f) { return idsOf(store.sessions(f)); };
    const auto by = []<typename Field>(Field SessionFilter::*field, const Field& value) {
        SessionFilter filter;
        filter.*field = value;
        return filter;
    };
    EXPECT_EQ(query({}), (std::vector<std::int64_t>{d, c, b, a}));  // newest first
    SessionFilter dates = by(&SessionFilter::startedFrom, std::string("2026-11-02"));
    dates.startedBefore = "2026-11-04";
    EXPECT_EQ(query(dates), (std::vector<std::int64_t>{c, b}));
    EXPECT_EQ(query(by(&SessionFilter::mode, std::optional(tactiscope::core::Mode::PanelScan))),
              (std::vector<std::int64_t>{b, a}));
    EXPECT_EQ(query(by(&SessionFilter::subject, std::string("phantom-3"))), (std::vector<std::int64_t>{c}));
    EXPECT_EQ(query(by(&SessionFilter::operatorName, std::string("Ada"))), (std::vector<std::int64_t>{c, a}));
    EXPECT_EQ(query(by(&SessionFilter::verdict, std::optional(tactiscope::core::Verdict::Pass))),
              (std::vector<std::int64_t>{b}));
    // Text is found in the subject or the notes, in any case.
    EXPECT_EQ(query(by(&SessionFilter::text, std::string("door"))), (std::vector<std::int64_t>{d, b, a}));
    EXPECT_EQ(query(by(&SessionFilter::text, std::string("50%"))),
              (std::vector<std::int64_t>{a}));  // % is not a wildcard
    EXPECT_EQ(query(by(&SessionFilter::text, std::string("5_%"))), (std::vector<std::int64_t>{}));
    SessionFilter all = by(&SessionFilter::mode, std::optional(tactiscope::core::Mode::PanelScan));
    all.operatorName = "Ada";
    all.text = "fender";
    EXPECT_EQ(query(all), (std::vector<std::int64_t>{a}));
    // A limit keeps the newest, after the other conditions.
    EXPECT_EQ(query(by(&SessionFilter::limit, std::size_t{2})), (std::vector<std::int64_t>{d, c}));
    SessionFilter newestDoor = by(&SessionFilter::text, std::string("door"));
    newestDoor.limit = 1;
    EXPECT_EQ(query(newestDoor), (std::vector<std::int64_t>{d}));
}
