// RecorderLock: flock() on FILE-recorder.lock.
#include "core/storage/RecorderLock.h"

#include "core/storage/Database.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace tactiscope::core::storage {

std::string RecorderLock::lockPath(const std::string& storePath)
{
    return storePath + "-recorder.lock";
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
    const int fd = lockFile(storePath);
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
