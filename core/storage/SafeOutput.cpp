// SafeOutput: same-file checks by identity, and write-then-rename through a
// temporary that only this process can have made.
#include "core/storage/SafeOutput.h"

#include "core/storage/Database.h"
#include "core/storage/RecorderLock.h"
#include "core/storage/StoreIdentity.h"

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <ostream>

namespace tactiscope::core::storage {
namespace {

// An output stream's buffer over a file descriptor, remembering the first
// failed write (std::ofstream cannot be opened on a descriptor mkstemp made).
class DescriptorBuffer final : public std::streambuf {
public:
    explicit DescriptorBuffer(int descriptor)
        : m_descriptor(descriptor)
    {
        setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
    }

    int error() const { return m_error; }

protected:
    int_type overflow(int_type ch) override
    {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(ch, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(ch);
            pbump(1);
        }
        return traits_type::not_eof(ch);
    }

    int sync() override { return drain() ? 0 : -1; }

private:
    bool drain()
    {
        if (m_error != 0) return false;
        const char* next = pbase();
        auto left = static_cast<std::size_t>(pptr() - pbase());
        while (left > 0) {
            const ssize_t written = ::write(m_descriptor, next, left);
            if (written < 0) {
                if (errno == EINTR) continue;
                m_error = errno;
                return false;
            }
            next += written;
            left -= static_cast<std::size_t>(written);
        }
        setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
        return true;
    }

    int m_descriptor;
    int m_error = 0;
    std::array<char, 1 << 16> m_buffer{};
};

// The permissions a file created by open(…, 0666) would have.
mode_t ordinaryMode()
{
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return 0666 & ~mask;
}

}  // namespace

std::vector<std::string> storeFiles(const std::string& storePath)
{
    const std::string real = realStorePath(storePath);  // SQLite's -wal and -shm are beside it
    return {storePath, real + "-wal", real + "-shm", RecorderLock::lockPath(storePath)};
}

void refuseOverwriting(const std::string& output, const std::vector<std::string>& inputs)
{
    for (const auto& input : inputs) {
        std::error_code code;
        if (std::filesystem::equivalent(output, input, code) && !code)
            throw StorageError("refusing to write " + output + ": it is " + input +
                               ", which this command reads; choose another output");
    }
}

void writeAtomically(const std::string& path, const std::function<void(std::ostream&)>& write)
{
    // The temporary is a new file (O_EXCL) with a name nobody can guess, in
    // the target's folder so the rename stays on one file system: a file or
    // link already there under any name is never opened, so never harmed.
    const std::filesystem::path target(path);
    const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
    std::string name = (folder / ("." + target.filename().string() + ".XXXXXX")).string();
    const int descriptor = ::mkstemp(name.data());
    if (descriptor < 0) throw StorageError("cannot write " + path + ": " + std::strerror(errno));
    std::error_code ignored;
    const auto fail = [&](const std::string& message) {
        ::close(descriptor);
        std::filesystem::remove(name, ignored);
        throw StorageError(message);
    };
    DescriptorBuffer buffer(descriptor);
    std::ostream out(&buffer);
    try {
        write(out);
    } catch (...) {  // the writer's own failure: no half file left behind
        ::close(descriptor);
        std::filesystem::remove(name, ignored);
        throw;
    }
    out.flush();
    if (!out || buffer.error() != 0)
        fail("writing " + path + " failed: " + std::strerror(buffer.error() != 0 ? buffer.error() : EIO) +
             " (is the disk full or read-only?)");
    // On the disk before it takes the target's name: a crash leaves the old
    // file or the new one, never a torn one.
    if (::fchmod(descriptor, ordinaryMode()) != 0 || ::fsync(descriptor) != 0)
        fail("writing " + path + " failed: " + std::strerror(errno));
    if (::close(descriptor) != 0) {
        const int error = errno;
        std::filesystem::remove(name, ignored);
        throw StorageError("writing " + path + " failed: " + std::strerror(error));
    }
    std::error_code code;
    std::filesystem::rename(name, target, code);
    if (code) {
        std::filesystem::remove(name, ignored);
        throw StorageError("cannot write " + path + ": " + code.message());
    }
}

}  // namespace tactiscope::core::storage
