// A station's store's sessions checked against their own bounds
// (SessionBounds) before any count read from the file sizes a buffer or a
// loop; incrementally: a recording another connection is writing is checked
// only as far as it is new.
#pragma once

#include "core/storage/Database.h"
#include "core/storage/SessionBounds.h"

#include <cstdint>
#include <map>

namespace tactiscope::core::storage {

class SessionLayout {
public:
    explicit SessionLayout(Database& db)
        : m_db(db)
    {
    }

    // Throws StoreInputError naming the session and what is damaged. A
    // session that does not exist passes (there is nothing of it to read).
    void check(std::int64_t session);

private:
    Database& m_db;
    std::map<std::int64_t, SessionBounds> m_checked;
};

}  // namespace tactiscope::core::storage
