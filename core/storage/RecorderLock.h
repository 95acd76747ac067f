// One recorder per store at a time, across processes: an exclusive flock()
// on a lock file beside the store (FILE-recorder.lock). The kernel drops the
// lock when its holder dies, so a lock that cannot be taken means a live
// recorder, and a session still marked "recording" without one was cut
// short by a crash.
//
// A separate file, because closing any descriptor of the database itself
// would drop SQLite's own POSIX locks on it.
#pragma once

#include <optional>
#include <string>

namespace tactiscope::core::storage {

class RecorderLock {
public:
    // Throws StorageError when another recorder holds the store.
    static RecorderLock acquire(const std::string& storePath);
    // The lock file beside a store.
    static std::string lockPath(const std::string& storePath);
    // Nothing when another recorder holds it (or the lock file cannot be made).
    static std::optional<RecorderLock> tryAcquire(const std::string& storePath);
    // Whether a recorder (in this process or another) holds the store, for
    // readers: probed with a shared lock, so a reader never takes the store
    // from a recorder, and without creating the lock file (read-only media).
    static bool isHeld(const std::string& storePath);

    RecorderLock(RecorderLock&& other) noexcept;
    RecorderLock& operator=(RecorderLock&&) = delete;
    RecorderLock(const RecorderLock&) = delete;
    RecorderLock& operator=(const RecorderLock&) = delete;
    ~RecorderLock();

private:
    explicit RecorderLock(int fd)
        : m_fd(fd)
    {
    }

    int m_fd = -1;
};

}  // namespace tactiscope::core::storage
