// StoreIdentity: a store's resolved name, and a refusal of hard links.
#include "core/storage/StoreIdentity.h"

#include "core/storage/Database.h"

#include <filesystem>
#include <sys/stat.h>

namespace tactiscope::core::storage {

std::string realStorePath(const std::string& path)
{
    std::error_code error;
    const auto resolved = std::filesystem::weakly_canonical(path, error);
    return error ? path : resolved.string();
}

void refuseSeveralNames(const std::string& path)
{
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0 || !S_ISREG(status.st_mode) || status.st_nlink <= 1) return;
    throw StoreInputError(path + " has " + std::to_string(status.st_nlink) +
                          " names (hard links): SQLite keeps a store's write-ahead log beside the name it is opened "
                          "by, so each name would be a store of its own and a recording through one lost through "
                          "another; keep one name (remove the other links, or use a symbolic link) and open it by "
                          "that");
}

}  // namespace tactiscope::core::storage
