// RecorderLock: flock() on FILE-recorder.lock.
#include "core/storage/RecorderLock.h"

#include "core/storage/Database.h"
#include "core/storage/StoreIdentity.h"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <thread>
#include <unistd.h>

namespace tactiscope::core::storage {

// Beside the store's own file, as SQLite's -wal: one lock whatever link
// the store is reached by (core/storage/StoreIdentity.h).
std::string RecorderLock::lockPath(const std::string& storePath)
{
    return realStorePath(storePath) + "-recorder.lock";
}

namespace {

// The locked descriptor, or -1 with errno set.
int lockFile(const std::string& storePath)
{
    const int fd = ::open(RecorderLock::lockPath(storePath).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) return -1;
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        const int error = errno;
        ::close(fd);
        errno = error;
        return -1;
    }
    return fd;
}

}  // namespace

RecorderLock RecorderLock::acquire(const std::string& storePath)
{
    // A reader's probe (isHeld) or a read-write open (tryAcquire) holds the
    // lock for microseconds: only a lock held past a short wait is a recorder.
    constexpr auto kProbeWait = std::chrono::milliseconds(250);
    const auto deadline = std::chrono::steady_clock::now() + kProbeWait;
    int fd = lockFile(storePath);
    while (fd < 0 && errno == EWOULDBLOCK && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        fd = lockFile(storePath);
    }
    if (fd >= 0) return RecorderLock(fd);
    if (errno == EWOULDBLOCK)
        throw StorageError("another Tactiscope is recording into " + storePath +
                           "; record into another file or stop that recording first");
    throw StorageError("cannot create " + RecorderLock::lockPath(storePath) + ": " + std::strerror(errno));
}

std::optional<RecorderLock> RecorderLock::tryAcquire(const std::string& storePath)
{
    const int fd = lockFile(storePath);
    if (fd < 0) return std::nullopt;
    return RecorderLock(fd);
}

bool RecorderLock::isHeld(const std::string& storePath)
{
    const int fd = ::open(RecorderLock::lockPath(storePath).c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return errno != ENOENT;  // no lock file: no recorder ever ran; unreadable: cannot tell
    const bool held = ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
    ::close(fd);  // releases the shared lock, if it was taken
    return held;
}

RecorderLock::RecorderLock(RecorderLock&& other) noexcept
    : m_fd(other.m_fd)
{
    other.m_fd = -1;
}

RecorderLock::~RecorderLock()
{
    if (m_fd >= 0) ::close(m_fd);  // closing releases the lock
}

}  // namespace tactiscope::core::storage
