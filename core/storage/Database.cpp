// The SQLite wrapper: error translation and handle ownership.
#include "core/storage/Database.h"

#include "core/storage/StoreIdentity.h"

#include <sqlite3.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace tactiscope::core::storage {
namespace {

// Whether the store's folder cannot be written at all (a read-only mount:
// access() says so even to root, who ignores file modes).
bool onReadOnlyMedia(const std::string& path)
{
    const auto folder = std::filesystem::path(path).parent_path();
    return ::access(folder.empty() ? "." : folder.c_str(), W_OK) != 0 && errno == EROFS;
}

// The store as an SQLite URI that reads it as immutable; the characters a
// URI gives a meaning to are escaped.
std::string immutableUri(const std::string& path)
{
    std::string uri = "file:";
    for (const char c : std::filesystem::absolute(path).string()) {
        if (c == '%' || c == '?' || c == '#') {
            char escaped[4];
            std::snprintf(escaped, sizeof escaped, "%%%02X", static_cast<unsigned char>(c));
            uri += escaped;
        } else {
            uri += c;
        }
    }
    return uri + "?immutable=1";
}

// Whether the store has a write-ahead log with something in it: a station
// that crashed, or was copied while recording, left its newest commits there.
bool hasPendingLog(const std::string& path)
{
    std::error_code error;
    const auto size = std::filesystem::file_size(path + "-wal", error);
    return !error && size > 0;
}

// A new private folder for a copy of the store at `path`, read `why`.
// Throws StorageError.
std::string privateFolder(const std::string& path, const std::string& why)
{
    std::string folder = (std::filesystem::temp_directory_path() / "tactiscope-store-XXXXXX").string();
    if (::mkdtemp(folder.data()) == nullptr)
        throw StorageError(path + ": cannot make a private copy to read " + why + ": " + std::strerror(errno));
    return folder;
}

// A private folder holding a copy of the store and its log, where SQLite
// can make the shared memory a log needs. Throws StorageError.
std::string copyWithLog(const std::string& path)
{
    const std::string folder = privateFolder(path, "its write-ahead log");
    const std::string copy = folder + "/store";
    std::error_code error;
    std::filesystem::copy_file(path, copy, error);
    if (!error) std::filesystem::copy_file(path + "-wal", copy + "-wal", error);
    if (error) {
        std::filesystem::remove_all(folder, error);
        throw StorageError(path + ": cannot make a private copy to read its write-ahead log (" + error.message() +
                           "); copy the store with its -wal file to a writable disk");
    }
    return folder;
}

// SQLite's message for the last error, with what a user can do about the
// ones recording meets: a full disk, a read-only file, an I/O error (with
// the system's reason, e.g. "Read-only file system").
std::string describeError(sqlite3* db)
{
    const std::string message = sqlite3_errmsg(db);
    const int code = sqlite3_extended_errcode(db) & 0xFF;
    const int system = sqlite3_system_errno(db);
    // A quota or a file-size limit is a full disk to the user too.
    const bool noSpace = system == ENOSPC || system == EDQUOT || system == EFBIG;
    if (code == SQLITE_FULL || (code == SQLITE_IOERR && noSpace))
        return "the disk is full (" + message + (system ? std::string(": ") + std::strerror(system) : "") + ")";
    if (code == SQLITE_READONLY)
        return "the file is read-only (" + message +
               "); check its permissions and whether its disk is mounted read-only";
    if ((code == SQLITE_IOERR || code == SQLITE_CANTOPEN) && system != 0)
        return message + " (" + std::strerror(system) + ")";
    // SQLite keeps no errno for a failed write: say what usually causes one.
    const int extended = sqlite3_extended_errcode(db);
    if (extended == SQLITE_IOERR_WRITE || extended == SQLITE_IOERR_FSYNC)
        return "writing failed (" + message + "): is the disk full, removed or mounted read-only?";
    return message;
}

}  // namespace

Statement::Statement(sqlite3* db, std::string_view sql)
    : m_db(db)
{
    check(sqlite3_prepare_v2(m_db, sql.data(), static_cast<int>(sql.size()), &m_statement, nullptr));
}

Statement::~Statement()
{
    sqlite3_finalize(m_statement);
}

Statement::Statement(Statement&& other) noexcept
    : m_db(other.m_db),
      m_statement(other.m_statement)
{
    other.m_statement = nullptr;
}

void Statement::check(int code) const
{
    if (code == SQLITE_OK || code == SQLITE_ROW || code == SQLITE_DONE) return;
    const char* file = sqlite3_db_filename(m_db, "main");
    throw StorageError(std::string(file && *file ? file : "session store") + ": " + describeError(m_db));
}

Statement& Statement::bind(int index, std::int64_t value)
{
    check(sqlite3_bind_int64(m_statement, index, value));
    return *this;
}

Statement& Statement::bind(int index, double value)
{
    check(sqlite3_bind_double(m_statement, index, value));
    return *this;
}

Statement& Statement::bind(int index, std::string_view text)
{
    // An empty view may have no data at all, which SQLite would bind as NULL:
    // text is text, however short.
    const char* data = text.data() ? text.data() : "";
    check(sqlite3_bind_text(m_statement, index, data, static_cast<int>(text.size()), SQLITE_TRANSIENT));
    return *this;
}

Statement& Statement::bindBlob(int index, std::span<const std::uint8_t> bytes)
{
    check(sqlite3_bind_blob(m_statement, index, bytes.data(), static_cast<int>(bytes.size()), SQLITE_TRANSIENT));
    return *this;
}

Statement& Statement::bindNull(int index)
{
    check(sqlite3_bind_null(m_statement, index));
    return *this;
}

bool Statement::step()
{
    const int code = sqlite3_step(m_statement);
    check(code);
    return code == SQLITE_ROW;
}

void Statement::run()
{
    while (step()) {
    }
    reset();
}

void Statement::reset()
{
    sqlite3_reset(m_statement);
    sqlite3_clear_bindings(m_statement);
}

std::int64_t Statement::int64(int column) const
{
    return sqlite3_column_int64(m_statement, column);
}

double Statement::real(int column) const
{
    return sqlite3_column_double(m_statement, column);
}

std::string Statement::text(int column) const
{
    const auto* text = sqlite3_column_text(m_statement, column);
    return text ? std::string(reinterpret_cast<const char*>(text),
                              static_cast<std::size_t>(sqlite3_column_bytes(m_statement, column)))
                : std::string();
}

bool Statement::isNull(int column) const
{
    return sqlite3_column_type(m_statement, column) == SQLITE_NULL;
}

std::span<const std::uint8_t> Statement::blob(int column) const
{
    const auto* data = static_cast<const std::uint8_t*>(sqlite3_column_blob(m_statement, column));
    return {data, static_cast<std::size_t>(sqlite3_column_bytes(m_statement, column))};
}

Database::Database(const std::string& path, Access access)
    : m_path(path),
      m_access(access)
{
    std::error_code error;
    if (std::filesystem::is_directory(path, error))  // else SQLite says "disk I/O error"
        throw StoreInputError(path +
                              " is a folder, not a session store; choose a store file (or a new file name) in it");
    refuseSeveralNames(path);
    const int flags = access == Access::ReadOnly ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
    // On read-only media SQLite cannot make the WAL's shared-memory file a
    // reader needs: nobody can be writing there, so the file is read as
    // immutable.
    const bool readOnlyMedia = onReadOnlyMedia(path);
    if (access == Access::ReadWrite && readOnlyMedia)
        throw StorageError(path + ": the store is on a read-only disk; it can be reviewed (opened read-only), not "
                                  "written; copy it to a writable disk to record into it");
    // Immutable ignores the write-ahead log, so a store with one (its newest
    // sessions there) is read whole from a private copy instead: never a
    // silent subset.
    const bool logPending = access == Access::ReadOnly && readOnlyMedia && hasPendingLog(path);
    if (logPending) {
        m_copyFolder = copyWithLog(path);
        m_note = path + " is on a read-only disk with sessions still in its write-ahead log (" + path +
                 "-wal): read whole from a private copy";
    }
    const bool immutable = access == Access::ReadOnly && readOnlyMedia && !logPending;
    const std::string name = logPending ? m_copyFolder + "/store" : immutable ? immutableUri(path) : path;
    const int code = sqlite3_open_v2(name.c_str(), &m_db,
                                     (logPending ? SQLITE_OPEN_READWRITE : flags) | SQLITE_OPEN_NOMUTEX |
                                         (immutable ? SQLITE_OPEN_URI : 0),
                                     nullptr);
    if (code != SQLITE_OK) {
        const std::string message = m_db ? sqlite3_errmsg(m_db) : sqlite3_errstr(code);
        sqlite3_close(m_db);
        removeCopy();
        throw StorageError(path + ": " + message);
    }
    if (logPending) exec("PRAGMA query_only = 1");  // a copy, but opened to be read
    sqlite3_extended_result_codes(m_db, 1);
    // Another connection (the recorder, a second reader) may hold the write
    // lock briefly; wait for it rather than failing.
    sqlite3_busy_timeout(m_db, 5000);
    // Pages are read through a memory map rather than a read() each: the
    // session list and overviews touch thousands of scattered small pages.
    exec("PRAGMA mmap_size = 1073741824");
}

Database::~Database()
{
    sqlite3_close(m_db);
    removeCopy();
}

void Database::removeCopy()
{
    if (m_copyFolder.empty()) return;
    std::error_code ignored;
    std::filesystem::remove_all(m_copyFolder, ignored);
}

void Database::addNote(const std::string& note)
{
    m_note = m_note ? *m_note + "; " + note : note;
}

void Database::readThroughPrivateCopy(const std::string& note)
{
    const std::string folder = privateFolder(m_path, "it");
    const std::string copy = folder + "/store";
    sqlite3* target = nullptr;
    int code = sqlite3_open_v2(copy.c_str(), &target, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX,
                               nullptr);
    sqlite3_backup* backup = code == SQLITE_OK ? sqlite3_backup_init(target, "main", m_db, "main") : nullptr;
    if (backup) {
        code = sqlite3_backup_step(backup, -1);  // all of it, under one read lock
        sqlite3_backup_finish(backup);
    }
    if (!backup || code != SQLITE_DONE) {
        const std::string reason = backup ? sqlite3_errstr(code) : target ? sqlite3_errmsg(target) : "out of memory";
        sqlite3_close(target);
        std::error_code ignored;
        std::filesystem::remove_all(folder, ignored);
        throw StorageError(m_path + ": cannot make a private copy to read it (" + reason + " in " +
                           std::filesystem::temp_directory_path().string() + ")");
    }
    sqlite3_close(m_db);
    removeCopy();
    m_db = target;
    m_copyFolder = folder;
    m_updatableCopy = true;
    sqlite3_extended_result_codes(m_db, 1);
    exec("PRAGMA mmap_size = 1073741824");
    addNote(note);
}

void Database::exec(std::string_view sql)
{
    char* error = nullptr;
    const std::string text(sql);
    if (sqlite3_exec(m_db, text.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
        const std::string message = describeError(m_db);
        sqlite3_free(error);
        throw StorageError(m_path + ": " + message);
    }
}

std::int64_t Database::lastInsertId() const
{
    return sqlite3_last_insert_rowid(m_db);
}

int Database::changes() const
{
    return sqlite3_changes(m_db);
}

bool Database::inTransaction() const
{
    return sqlite3_get_autocommit(m_db) == 0;
}

Transaction::Transaction(Database& db)
    : m_db(db),
      m_nested(db.inTransaction())
{
    m_db.exec(m_nested ? "SAVEPOINT nested" : "BEGIN IMMEDIATE");
}

Transaction::~Transaction()
{
    if (m_done) return;
    try {
        m_db.exec(m_nested ? "ROLLBACK TO nested; RELEASE nested" : "ROLLBACK");
    } catch (const StorageError&) {
        // SQLite already rolled back (e.g. after a full disk); nothing to undo.
    }
}

void Transaction::commit()
{
    m_db.exec(m_nested ? "RELEASE nested" : "COMMIT");
    m_done = true;
}

ReadSnapshot::ReadSnapshot(Database& db)
    : m_db(db)
{
    if (m_db.inTransaction()) return;
    m_db.exec("BEGIN DEFERRED");
    m_began = true;
}

ReadSnapshot::~ReadSnapshot()
{
    if (!m_began) return;
    try {
        m_db.exec("COMMIT");  // a read-only transaction: nothing to write
    } catch (const StorageError&) {
        // Nothing was changed, so nothing can be lost.
    }
}

}  // namespace tactiscope::core::storage
