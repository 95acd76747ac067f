// Damage as a failing disk or a bad copy leaves it: 16 KiB of junk over the
// middle of a store file, where the sample chunks live. The file still
// opens; SQLite's checks and the pages' readers find the damage.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

namespace tactiscope::testing {

// Returns false when the file cannot be written. Close every connection
// first, so the WAL has been folded into the file.
inline bool scribbleOverTheMiddle(const std::string& path)
{
    const auto size = std::filesystem::file_size(path);
    std::FILE* file = std::fopen(path.c_str(), "r+b");
    if (file == nullptr) return false;
    std::fseek(file, static_cast<long>(size / 2), SEEK_SET);
    const std::string junk(16384, '\xA5');
    const bool written = std::fwrite(junk.data(), 1, junk.size(), file) == junk.size();
    return std::fclose(file) == 0 && written;
}

}  // namespace tactiscope::testing
