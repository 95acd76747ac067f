// What the live session says of itself to its owners and its mode units:
// the lists' clock, a press as the views list it, and a recording's
// summary at its end.
#pragma once

#include "core/Vocabulary.h"
#include "core/compliance/StiffnessReadings.h"
#include "core/detector/ProbeDecisionCheck.h"
#include "core/storage/Recorder.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tactiscope::devices::session {

// The clock of the live lists (defects, presses) and what they are.
enum class LiveClock {
    SinceConnect,  // no recording: seconds since the device connected; nothing of it stored
    Recording,     // the recording's seconds, as stored
    Recorded,      // the stopped recording's, exactly as stored, until the next event
};

struct LiveLists {
    // Changes whenever the lists start again (a recording starts, the
    // first event after a stop, other roles): a view clears and refills.
    // Unique across the process's live sessions, so a view bound to a new
    // device's session starts its lists again too; never 0.
    std::uint64_t generation = 0;
    LiveClock clock = LiveClock::SinceConnect;
    std::int64_t session = 0;  // the recording's (Recording, Recorded)
    double origin_s = 0.0;     // the stream time of the clock's 0 (since connect: 0)
};

// A completed press on the lists' clock (LiveLists), the site it was taken
// at (empty without a site grid), and whether it went into the recording.
struct PressRecord {
    core::compliance::PressReading press;
    std::string site;
    bool stored = false;  // went into the recording
};

struct RecordingSummary {
    std::int64_t session = 0;
    core::storage::RecorderStats stats;
    std::optional<core::Verdict> verdict;  // the automatic one, stored with the session (panel scan)
    // Why a mode that judges gave none: "too short to judge (0.01 s of the
    // 0.6 s the detector needs)"; empty otherwise.
    std::string notJudged;
    std::size_t defects = 0;  // of this recording's panel: crossings
    std::size_t sites = 0;    // where they are: a defect crossed N times is one site
    // What the verdict was decided on, a line each, for the one who judges
    // it: a panel's sites, "Site 1: 37 mm ± 2 mm (6 crossings), 4 A then B,
    // 2 B then A, 3.2–9.8 s".
    std::vector<std::string> findings;
    // A probe that sends its own decisions: how far they agreed with the
    // workstation's over the recording (after the warm-up).
    std::optional<core::detector::ProbeAgreement> probeAgreement;
    double end_s = 0.0;  // session time of the last sample
    // What the mode's analysis stored, in a line: "20 defects stored at 1
    // site, verdict defects found", "5 stiffness readings stored".
    std::string analysis;
    // An end that was not a stop: the probe went silent (lost, and not back
    // by the stop) at lostAt_s, and the samples to the stop are a gap;
    // or the link failed for good (why, in stoppedBecause).
    std::optional<double> lostAt_s;
    std::uint64_t samplesLostAtEnd = 0;
    std::string stoppedBecause;
};

}  // namespace tactiscope::devices::session
