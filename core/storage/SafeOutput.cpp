// SafeOutput: same-file checks by identity, and write-then-rename.
#include "core/storage/SafeOutput.h"

#include "core/storage/Database.h"
#include "core/storage/RecorderLock.h"

#include <filesystem>
#include <fstream>

namespace tactiscope::core::storage {

std::vector<std::string> storeFiles(const std::string& storePath)
{
    return {storePath, storePath + "-wal", storePath + "-shm", RecorderLock::lockPath(storePath)};
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
    const std::string temporary = path + ".partial";
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    if (!file) throw StorageError("cannot write " + path);
    std::error_code code;
    try {
        write(file);
    } catch (...) {  // the writer's own failure: no half file left behind
        file.close();
        std::filesystem::remove(temporary, code);
        throw;
    }
    file.close();  // flushes: a full disk shows here, if not before
    if (!file) {
        std::filesystem::remove(temporary, code);
        throw StorageError("writing " + path + " failed: is the disk full or read-only?");
    }
    std::filesystem::rename(temporary, path, code);
    if (code) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw StorageError("cannot write " + path + ": " + code.message());
    }
}

}  // namespace tactiscope::core::storage
