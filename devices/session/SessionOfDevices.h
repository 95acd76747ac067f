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
    // is, else interrupted. Idempotent.
    void finish();

private:
    std::string m_storePath;
    core::storage::RecorderLock m_lock;
    std::int64_t m_session = 0;
    double m_start_host_s = 0.0;
    bool m_finished = false;
};

}  // namespace tactiscope::devices::session
