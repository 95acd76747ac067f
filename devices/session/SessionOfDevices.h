// The recording of a session of several devices (issue 40): it holds the
// store's RecorderLock for all of them, begins the session (a row with no
// channels of its own) and ends it; each device records its part through
// its own LiveSession, given LiveSessionOptions::partOf(), so each part
// keeps its device's rate, clock, gaps and analysis, and a device lost
// mid-session is a gap in its part only.
#pragma once

#include "core/Vocabulary.h"
#include "core/storage/RecorderLock.h"
#include "core/storage/SessionSource.h"
#include "devices/session/LiveSession.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace tactiscope::devices::session {

class SessionOfDevices {
public:
    // Takes the lock (StorageError when another recorder holds the store),
    // marks what a crash left "recording" as interrupted, and begins the
    // session now: its t = 0 is this host instant.
    SessionOfDevices(const std::string& storePath, const core::storage::SessionMetadata& metadata);
    ~SessionOfDevices();  // ends it interrupted unless finished

    SessionOfDevices(const SessionOfDevices&) = delete;
    SessionOfDevices& operator=(const SessionOfDevices&) = delete;

    std::int64_t sessionId() const { return m_session; }
    // What a device's LiveSession is given to record its part.
    LiveSessionOptions::PartOfSession partFor(const std::string& deviceName) const;
    // Ends the session once its parts have ended: complete when every part
    // is, else interrupted, with its parts' verdict (AutomaticVerdict.h:
    // partsDecision), which it returns. Idempotent.
    std::optional<core::Verdict> finish();

private:
    std::string m_storePath;
    core::storage::RecorderLock m_lock;
    std::int64_t m_session = 0;
    double m_start_host_s = 0.0;
    bool m_finished = false;
    std::optional<core::Verdict> m_verdict;
};

// A device's name in a session (its channels read DEVICE/CHANNEL): its
// model in lower case, words joined by '-' ("tactiscope-simulator"); a
// second device of a model taken already adds its serial
// ("tactiscope-simulator-reference-load-cell"), and a number where that is
// taken too ("…-2"). Never empty, never with '/', '=' or a space.
std::string partName(const DeviceIdentity& identity, std::span<const std::string> taken);

}  // namespace tactiscope::devices::session
