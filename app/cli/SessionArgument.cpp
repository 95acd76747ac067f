// --db → a store; "ID", "UUID" or "last" → a session id of the store.
#include "SessionArgument.h"

#include "core/storage/OpenSessionSource.h"

#include <QFileInfo>

namespace tactiscope::cli {

bool storeArgumentExists(const QString& db)
{
    return core::storage::isCentralStoreAddress(db.toStdString()) || QFileInfo::exists(db);
}

std::unique_ptr<core::storage::SessionSource> openStoreArgument(const QString& db,
                                                                core::storage::Database::Access access)
{
    return core::storage::openSessionSource(db.toStdString(), access);
}

std::optional<std::int64_t> resolveSession(core::storage::SessionSource& store, const QString& text)
{
    if (text == QLatin1String("last")) {
        const auto sessions = store.sessions();
        if (sessions.empty()) return std::nullopt;
        return sessions.front().id;
    }
    // A uuid: 8-4-4-4-12 hexadecimal digits.
    if (text.size() == 36 && text.count(QLatin1Char('-')) == 4) return store.sessionWithUuid(text.toStdString());
    bool ok = false;
    const qlonglong id = text.toLongLong(&ok);
    if (!ok || !store.session(id)) return std::nullopt;
    return id;
}

}  // namespace tactiscope::cli
