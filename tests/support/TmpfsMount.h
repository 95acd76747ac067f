// A small tmpfs mounted on a fresh folder for one test: a full disk or,
// remounted read-only, write-protected media, on a real file system.
// Mounting needs root (CI runs as root); elsewhere mounted() is false and
// the test skips, saying why.
#pragma once

#include <sys/mount.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace tactiscope::testing {

class TmpfsMount {
public:
    // `size` as mount(8) takes it, e.g. "64k" or "8m".
    explicit TmpfsMount(const std::string& size)
        : m_size(size)
    {
        char folder[] = "/tmp/tactiscope-tmpfs-XXXXXX";
        if (::mkdtemp(folder) == nullptr) return;
        if (::mount("tmpfs", folder, "tmpfs", 0, ("size=" + m_size).c_str()) != 0) {
            std::filesystem::remove(folder);
            return;
        }
        m_path = folder;
    }
    ~TmpfsMount()
    {
        if (m_path.empty()) return;
        ::umount(m_path.c_str());
        std::filesystem::remove(m_path);
    }
    TmpfsMount(const TmpfsMount&) = delete;
    TmpfsMount& operator=(const TmpfsMount&) = delete;

    bool mounted() const { return !m_path.empty(); }
    const std::string& path() const { return m_path; }
    std::string file(const std::string& name) const { return m_path + "/" + name; }
    // Fills it to the last byte with a file of its own: a full disk.
    void fill() const
    {
        std::ofstream filler(file("filler"), std::ios::binary);
        const std::vector<char> block(1024, 'x');
        while (filler.write(block.data(), static_cast<std::streamsize>(block.size())) && filler.flush()) {
        }
    }
    // Write-protects it, as a locked card or a mounted archive is.
    bool makeReadOnly() const
    {
        return ::mount("tmpfs", m_path.c_str(), "tmpfs", MS_REMOUNT | MS_RDONLY, ("size=" + m_size).c_str()) == 0;
    }

    static constexpr const char* kSkipReason = "mounting a tmpfs needs root (CI runs as root): skipped";

private:
    std::string m_size;
    std::string m_path;
};

}  // namespace tactiscope::testing
