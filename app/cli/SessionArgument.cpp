// --db → a store; "ID", "UUID" or "last" → a session id of the store.
#include "SessionArgument.h"

#include "core/storage/OpenSessionSource.h"

#include <QFileInfo>

#include <algorithm>
#include <iostream>

namespace tactiscope::cli {

bool storeArgumentExists(const QString& db)
{
    return core::storage::isCentralStoreAddress(db.toStdString()) || QFileInfo::exists(db);
}

std::unique_ptr<core::storage::SessionSource> openStoreArgument(const QString& db,
                                                                core::storage::Database::Access access)
{
    auto store = core::storage::openSessionSource(db.toStdString(), access);
    printStoreNote(*store);
    return store;
}

void printStoreNote(const core::storage::SessionSource& store)
{
    if (const auto note = store.readNote()) std::cerr << "note: " << *note << '\n';
}

std::optional<std::int64_t> resolveSession(core::storage::SessionSource& store, const QString& text)
{
    std::optional<std::int64_t> id;
    if (text == QLatin1String("last")) {
        id = store.lastSession();
    } else if (text.size() == 36 && text.count(QLatin1Char('-')) == 4) {  // a uuid: 8-4-4-4-12 hex digits
        id = store.sessionWithUuid(text.toStdString());
    } else {
        bool ok = false;
        const qlonglong number = text.toLongLong(&ok);
        if (ok && store.session(number)) id = number;
    }
    // A damaged session says so here, before a command sizes anything by it.
    if (id) store.channels(*id);
    return id;
}

}  // namespace tactiscope::cli
