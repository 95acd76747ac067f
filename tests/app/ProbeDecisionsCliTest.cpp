// A probe that runs the detector itself and says what it decided (issue
// 38): the emulated panel-scan probe (`emulate --probe-detector`) sends its
// decisions as channels of kind decision; `record` stores them, records
// the probe's defects as the analysis "probe" beside the live detector's,
// and states their agreement, which the report repeats; `analyze` compares
// the recorded decisions with its own run. A probe whose
// detector is built wrong (`--fault wrong-decisions`: it misses every
// defect) raises the disagreement alarm at the defects the workstation
// finds.
#include "core/storage/SessionStore.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/PdfText.h"

#include <QRegularExpression>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace tactiscope;
namespace storage = tactiscope::core::storage;

namespace {

struct Recorded {
    tactiscope::testing::CliResult result;
    std::vector<core::storage::SessionEvent> events;
};

Recorded recordProbe(const QTemporaryDir& dir, const QString& db, const QStringList& emulatorExtra)
{
    Recorded r;
    r.result =
        tactiscope::testing::recordEmulated(dir.path(), db, QStringLiteral("panel-scan"), 12, {"--subject", "door-9"},
                                            QStringList{"--probe-detector"} + emulatorExtra);
    if (r.result.exitCode == 0) {
        core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
        const auto id = store.sessions().front().id;
        r.events = store.events(id);  // the live analysis: the workstation's defects and the alarms
        const auto probe = store.events(id, "probe");
        r.events.insert(r.events.end(), probe.begin(), probe.end());
    }
    return r;
}

std::size_t count(const std::vector<core::storage::SessionEvent>& events, core::EventKind kind,
                  const std::string& analysis)
{
    return static_cast<std::size_t>(std::ranges::count_if(events, [&](const auto& e) {
        return e.kind == kind && (kind != core::EventKind::Defect || e.analysis == analysis);
    }));
}

}  // namespace

TEST(ProbeDecisionsCli, AProbesDecisionsAreRecordedBesideTheWorkstationsAndAgree)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope");
    const auto r = recordProbe(dir, db, {});
    ASSERT_EQ(r.result.exitCode, 0) << r.result.err.toStdString();
    // "probe and workstation agree on N of N decisions", N the samples after the 4 s warm-up.
    const auto agreement =
        QRegularExpression(QStringLiteral("agree on (\\d+) of (\\d+) decisions")).match(r.result.out);
    ASSERT_TRUE(agreement.hasMatch()) << r.result.out.toStdString();
    EXPECT_EQ(agreement.captured(1), agreement.captured(2));
    EXPECT_GT(agreement.captured(2).toInt(), 3000);  // 12 s at 500 Hz less the warm-up
    // The probe's defects, as many as the workstation's (same code, same samples), and no alarm.
    const std::size_t live = count(r.events, core::EventKind::Defect, "live");
    EXPECT_GT(live, 5U);
    EXPECT_EQ(count(r.events, core::EventKind::Defect, "probe"), live);
    EXPECT_EQ(count(r.events, core::EventKind::Alarm, {}), 0U);
    // The channels are kept as the probe sent them.
    const auto shown = tactiscope::testing::runCli({"sessions", "--db", db, "show", "last"});
    EXPECT_TRUE(shown.out.contains("out [decision], rab [decision], rba [decision]")) << shown.out.toStdString();
    // analyze runs the workstation's detector again on the stored samples and compares.
    const auto analyzed = tactiscope::testing::runCli({"analyze", "--db", db, "--session", "last", "--json"});
    ASSERT_EQ(analyzed.exitCode, 0) << analyzed.err.toStdString();
    const QJsonObject compared = tactiscope::testing::jsonOf(analyzed)["probe_agreement"].toObject();
    EXPECT_GT(compared["compared"].toInt(), 3000);
    EXPECT_EQ(compared["agreeing"].toInt(), compared["compared"].toInt());

    if (*tactiscope::testing::pdfTextMissing()) GTEST_SKIP() << tactiscope::testing::pdfTextMissing();
    const QString pdf = dir.filePath("r.pdf");
    ASSERT_EQ(tactiscope::testing::runCli({"report", "--db", db, "--session", "last", "--output", pdf}).exitCode, 0);
    const QString text = tactiscope::testing::pdfText(pdf).simplified();
    EXPECT_TRUE(
        text.contains(QStringLiteral("probe and workstation agree on %1 of %1 decisions").arg(agreement.captured(2))))
        << text.toStdString();
}

TEST(ProbeDecisionsCli, AProbeWhoseDetectorIsWrongRaisesTheDisagreementAlarm)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("w.tactiscope");
    const auto r = recordProbe(dir, db, {"--fault", "wrong-decisions"});
    ASSERT_EQ(r.result.exitCode, 0) << r.result.err.toStdString();
    const auto agreement =
        QRegularExpression(QStringLiteral("agree on (\\d+) of (\\d+) decisions")).match(r.result.out);
    ASSERT_TRUE(agreement.hasMatch()) << r.result.out.toStdString();
    EXPECT_LT(agreement.captured(1).toInt(), agreement.captured(2).toInt());
    // It misses every defect: each one the workstation finds after the warm-up is an alarm.
    std::size_t afterWarmUp = 0, alarms = 0;
    for (const auto& e : r.events) {
        if (e.kind == core::EventKind::Defect && e.analysis == "live" && e.start_s > 4.1) ++afterWarmUp;
        if (e.kind == core::EventKind::Alarm) {
            ++alarms;
            EXPECT_NE(e.note.find("the probe says no defect"), std::string::npos) << e.note;
        }
    }
    EXPECT_GT(afterWarmUp, 3U);
    EXPECT_EQ(alarms, afterWarmUp);
    EXPECT_EQ(count(r.events, core::EventKind::Defect, "probe"), 0U);
    const auto analyzed = tactiscope::testing::runCli({"analyze", "--db", db, "--session", "last"});
    ASSERT_EQ(analyzed.exitCode, 0) << analyzed.err.toStdString();
    const auto again = QRegularExpression(QStringLiteral("agree on (\\d+) of (\\d+) decisions")).match(analyzed.out);
    ASSERT_TRUE(again.hasMatch()) << analyzed.out.toStdString();
    EXPECT_LT(again.captured(1).toInt(), again.captured(2).toInt());
}
