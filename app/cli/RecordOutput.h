// What `tactiscope-cli record` prints of the live pipeline
// (devices/session/LivePipeline): each poll's news on stderr as it comes
// (what a link noticed, limit alarms, the trigger's state; times in
// seconds since the device connected, one clock for every session a
// trigger cuts, where the store keeps each session's own), and each
// recording that ended on stdout, in the contract lines: for a session of
// one device "Recorded session N: S samples per channel, L lost, C CRC
// errors (K channels at R Hz, into DB); MODE: ANALYSIS", for one of
// several "Recorded session N: D devices, into DB" and a line per device.
// The samples lost are those the store marks lost, read back, so the line
// and the store agree to the sample.
#pragma once

#include "core/trigger/TriggerMachine.h"
#include "devices/session/LivePipeline.h"

#include <QString>

#include <optional>
#include <string>

namespace tactiscope::cli {

class RecordOutput {
public:
    RecordOutput(std::string db, const devices::session::LivePipeline& pipeline,
                 std::optional<core::trigger::TriggerSettings> trigger, bool stopOnCritical);

    // Tells the news; a critical alarm when asked to stop on one is kept
    // (criticalStop()), and each ended recording is reported.
    void tell(const devices::session::PipelineNews& news);
    void report(const devices::session::RecordingEnd& end);

    // "stopped on a critical alarm at T s: TEXT", once one was raised.
    const std::optional<QString>& criticalStop() const { return m_criticalStop; }
    unsigned sessionsReported() const { return m_reported; }
    // kExitFailure once a recording ended badly (its disk, a lost probe).
    int exitCode() const { return m_exit; }

private:
    void reportOne(const devices::session::RecordingEnd& end);
    void reportSeveral(const devices::session::RecordingEnd& end);
    void tellEndProblem(const std::string& device, const devices::session::RecordingSummary& summary);
    void tellDetectorHum(const std::string& device, std::int64_t session);
    void tellHoles(const std::string& device, const devices::session::RecordingSummary& summary,
                   const std::vector<core::ChannelDescriptor>& channels);
    // The line a trigger's new state is told by; none when nothing is said.
    std::optional<QString> triggerText(const devices::session::TriggerStatus& status);
    std::size_t deviceIndex(const std::string& name) const;

    bool m_clockSaid = false;  // the clock of the timed lines, said before the first
    std::string m_db;
    const devices::session::LivePipeline& m_pipeline;
    std::optional<core::trigger::TriggerSettings> m_trigger;
    bool m_stopOnCritical = false;
    std::optional<QString> m_criticalStop;
    unsigned m_reported = 0;
    unsigned m_triggered = 0;  // sessions the trigger has started
    int m_exit = 0;
};

}  // namespace tactiscope::cli
