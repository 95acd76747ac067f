// A small RAII layer over libpq, as Database is over the SQLite C API: one
// connection, statements with parameters always bound (never spliced into
// the SQL), results freed when they go out of scope. Connection strings
// are libpq's own (a postgresql:// URI or key=value), so passwords come
// from ~/.pgpass, PGPASSFILE or a service file and TLS from sslmode.
#pragma once

#include "core/storage/Database.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

struct pg_conn;
struct pg_result;

namespace tactiscope::core::storage::central {

// One statement's rows; values as text (NULL as nothing).
class PgResult {
public:
    explicit PgResult(pg_result* result);
    ~PgResult();
    PgResult(PgResult&& other) noexcept;
    PgResult& operator=(PgResult&&) = delete;
    PgResult(const PgResult&) = delete;
    PgResult& operator=(const PgResult&) = delete;

    int rows() const;
    bool isNull(int row, int column) const;
    std::string text(int row, int column) const;

private:
    friend class PgConnection;
    pg_result* m_result;
};

class PgConnection {
public:
    // Throws StorageError with libpq's reason when it cannot connect.
    explicit PgConnection(const std::string& conninfo);
    ~PgConnection();
    PgConnection(const PgConnection&) = delete;
    PgConnection& operator=(const PgConnection&) = delete;

    // A script of statements without parameters (schema, roles). Throws
    // StorageError naming the server's message.
    void run(const std::string& sql);
    // One statement with text parameters $1, $2, … (nothing binds NULL).
    PgResult query(const std::string& sql, const std::vector<std::optional<std::string>>& parameters = {});

    std::string user() const;

private:
    void check(const PgResult& result) const;

    pg_conn* m_connection;
};

}  // namespace tactiscope::core::storage::central
