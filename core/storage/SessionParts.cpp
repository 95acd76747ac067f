// SessionStore: sessions of several devices, each device a part (a session
// row whose parent_id is the session; schema version 7).
#include "core/storage/SessionStore.h"

#include "core/storage/Schema.h"

#include <cmath>

namespace tactiscope::core::storage {

std::int64_t SessionStore::beginSessionOfDevices(const SessionMetadata& metadata, const SessionOrigin& origin)
{
    if (metadata.partOf != 0) throw StorageError("a session of several devices cannot itself be a device's part");
    SessionMetadata own = metadata;
    own.deviceModel.clear();  // each part has its device's
    own.deviceSerial.clear();
    own.deviceFirmware.clear();
    own.deviceName.clear();
    Transaction transaction(m_db);
    const std::int64_t id = insertSessionRow(own, origin);
    transaction.commit();
    return id;
}

// A part belongs to a session of several devices: one that exists, is not
// itself a part and holds no channels of its own.
void SessionStore::refuseUnknownParent(std::int64_t session)
{
    auto query = m_db.prepare("SELECT parent_id IS NULL, (SELECT count(*) FROM channels WHERE session_id = s.id) FROM "
                              "sessions s WHERE id = ?");
    query.bind(1, session);
    if (!query.step() || query.int64(0) == 0 || query.int64(1) != 0)
        throw StorageError("session " + std::to_string(session) + " is not a session of several devices");
}

void SessionStore::setClockMapping(std::int64_t part, const std::string& clockJson)
{
    m_db.prepare("UPDATE sessions SET clock_json = ? WHERE id = ? AND parent_id IS NOT NULL")
        .bind(1, clockJson)
        .bind(2, part)
        .run();
    if (m_db.changes() != 1) throw StorageError("session " + std::to_string(part) + " is not a device's part");
}

std::vector<SessionPart> SessionStore::parts(std::int64_t session)
{
    std::vector<SessionPart> result;
    auto query = m_db.prepare("SELECT id, device_name, device_model, device_serial, device_firmware, clock_json, "
                              "status FROM sessions WHERE parent_id = ? AND id != parent_id ORDER BY id");
    query.bind(1, session);
    while (query.step())
        result.push_back({query.int64(0), query.text(1), query.text(2), query.text(3), query.text(4), query.text(5),
                          sessionStatusFromString(query.text(6)).value_or(SessionStatus::Interrupted)});
    return result;
}

}  // namespace tactiscope::core::storage
