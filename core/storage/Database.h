// A thin RAII layer over the SQLite C API: a connection and prepared
// statements that throw StorageError with SQLite's message and the file
// name, so callers never check return codes and never leak handles.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

struct sqlite3;
struct sqlite3_stmt;

namespace tactiscope::core::storage {

class StorageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Bad input, where a plain StorageError is a failure to reach, read or
// write: the file given is not a store, the store's own content contradicts
// itself (a count, an index, a page), or what was given to store cannot be
// (text that is not UTF-8, a uuid that is not one).
class StoreInputError : public StorageError {
public:
    using StorageError::StorageError;
};

class Statement {
public:
    Statement(sqlite3* db, std::string_view sql);
    ~Statement();
    Statement(Statement&& other) noexcept;
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;
    Statement& operator=(Statement&&) = delete;

    // Parameters are numbered from 1, as in SQL.
    Statement& bind(int index, std::int64_t value);
    Statement& bind(int index, double value);
    Statement& bind(int index, std::string_view text);
    Statement& bindBlob(int index, std::span<const std::uint8_t> bytes);
    Statement& bindNull(int index);

    // True while a row is available; false when done. Throws on error.
    bool step();
    // Runs a statement that returns no rows.
    void run();
    void reset();

    // Columns are numbered from 0, as in sqlite3_column_*.
    std::int64_t int64(int column) const;
    double real(int column) const;
    std::string text(int column) const;  // empty for NULL
    bool isNull(int column) const;
    std::span<const std::uint8_t> blob(int column) const;  // valid until the next step()

private:
    void check(int code) const;

    sqlite3* m_db;
    sqlite3_stmt* m_statement = nullptr;
};

class Database {
public:
    enum class Access { ReadOnly, ReadWrite };

    // Opens (and for ReadWrite creates) the file. Throws StorageError.
    Database(const std::string& path, Access access);
    ~Database();
    Database(const Database&) = delete;
    Database& operator=(const Database&) = delete;

    void exec(std::string_view sql);
    Statement prepare(std::string_view sql) { return Statement(m_db, sql); }
    std::int64_t lastInsertId() const;
    int changes() const;  // rows changed by the last INSERT, UPDATE or DELETE
    bool inTransaction() const;
    const std::string& path() const { return m_path; }
    Access access() const { return m_access; }
    // What a reader should be told about how the store was read (e.g. from
    // a private copy, a read-only disk's write-ahead log applied); none
    // when it was read as it is.
    const std::optional<std::string>& note() const { return m_note; }
    void addNote(const std::string& note);

    // From now on reads the store through a private copy this connection
    // may change (an older store brought up to date only to be read: the
    // store itself is never written); `note` tells the reader so. The copy
    // is SQLite's backup of what this connection reads, consistent however
    // the store is being written. Throws StorageError when no copy can be
    // made.
    void readThroughPrivateCopy(const std::string& note);
    // Whether the connection is to such a copy, which prepareSchema() updates.
    bool readsUpdatableCopy() const { return m_updatableCopy; }

private:
    void removeCopy();

    sqlite3* m_db = nullptr;
    std::string m_path;
    Access m_access;
    std::string m_copyFolder;  // a private copy read instead of the store, removed on close
    bool m_updatableCopy = false;
    std::optional<std::string> m_note;
};

// Runs a scope in one transaction: committed by commit(), rolled back when
// the scope is left by an exception. Inside another transaction it is a
// savepoint, so a whole import (many appends, each its own transaction
// when alone) commits at once or not at all, even through kill -9.
class Transaction {
public:
    explicit Transaction(Database& db);
    ~Transaction();
    Transaction(const Transaction&) = delete;
    Transaction& operator=(const Transaction&) = delete;
    void commit();

private:
    Database& m_db;
    bool m_nested = false;
    bool m_done = false;
};

// Runs a scope's reads on one snapshot of the file, so a reader sees a
// consistent state (e.g. samples and pyramid of the same commit) while the
// recorder keeps committing. Inside another transaction it adds nothing.
class ReadSnapshot {
public:
    explicit ReadSnapshot(Database& db);
    ~ReadSnapshot();
    ReadSnapshot(const ReadSnapshot&) = delete;
    ReadSnapshot& operator=(const ReadSnapshot&) = delete;

private:
    Database& m_db;
    bool m_began = false;
};

}  // namespace tactiscope::core::storage
