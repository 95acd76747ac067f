// Which backend a location names.
#include "core/storage/OpenSessionSource.h"

#include "core/storage/SessionStore.h"
#include "core/storage/central/CentralStore.h"

#include <regex>

namespace tactiscope::core::storage {

bool isCentralStoreAddress(std::string_view location)
{
    if (location.starts_with("postgresql://") || location.starts_with("postgres://")) return true;
    // key=value pairs: "host=… dbname=…", with spaces around '=' allowed.
    static const std::regex keyword(R"((^|\s)(host|hostaddr|dbname|service)\s*=)");
    return std::regex_search(location.begin(), location.end(), keyword);
}

std::unique_ptr<SessionSource> openSessionSource(const std::string& location, Database::Access access)
{
    if (isCentralStoreAddress(location)) return std::make_unique<central::CentralStore>(location, access);
    return std::make_unique<SessionStore>(location, access);
}

}  // namespace tactiscope::core::storage
