// A small RAII layer over libpq, as Database is over the SQLite C API: one
// connection, statements with parameters always bound (never spliced into
// the SQL), results freed when they go out of scope. Connection strings
// are libpq's own (a postgresql:// URI or key=value), so passwords come
// from ~/.pgpass, PGPASSFILE or a service file and TLS from sslmode.
#pragma once

#include "core/storage/Database.h"

#include <chrono>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

struct pg_conn;
struct pg_result;

namespace tactiscope::core::storage::central {

// The server could not be reached, stopped answering, or the connection
// was lost: a fact about the network and the server, not about what was
// asked (which a plain StorageError from the server's refusal is).
class CentralUnreachable : public StorageError {
public:
    using StorageError::StorageError;
};

// A statement's parameters $1, $2, …: numbers as exact text (a double as
// the shortest text that reads back to it), bytes copied and bound as
// binary (no hex on the wire).
class PgParams {
public:
    PgParams() = default;
    PgParams(std::initializer_list<std::optional<std::string>> texts);
    PgParams(const std::vector<std::optional<std::string>>& texts);

    PgParams& text(std::string value);
    PgParams& int64(std::int64_t value);
    PgParams& real(double value);
    PgParams& optionalReal(std::optional<double> value);
    PgParams& bytes(std::span<const std::uint8_t> value);
    PgParams& null();
    std::size_t bytesHeld() const { return m_bytesHeld; }

private:
    friend class PgConnection;
    std::vector<std::optional<std::string>> m_values;  // text, or bytes where m_formats says binary
    std::vector<int> m_formats;
    std::size_t m_bytesHeld = 0;
};

// How a statement's values come back: as text, or binary (raw bytea, no
// hex to decode; integers and doubles in network order).
enum class PgFormat { Text, Binary };

// One statement's rows. text() reads any column of a text result and text
// columns of a binary one; int64(), real() and bytes() read either.
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
    std::int64_t int64(int row, int column) const;
    double real(int row, int column) const;
    std::optional<double> optionalReal(int row, int column) const;
    std::span<const std::uint8_t> bytes(int row, int column) const;  // valid while the result lives

private:
    friend class PgConnection;
    pg_result* m_result;
};

// A connection heals: when the server has closed it since the last
// statement (a restart, a network outage that ended it), the next
// statement connects again first (three quick tries: a server starting up
// refuses for a moment), with the settings given to
// runOnEveryConnection(). A transaction's work, or a lock, cannot be carried
// over: a connection lost under one throws until it has been released.
// Which server of a connection string naming several hosts: the one its
// target_session_attrs chooses (a reviewer's read replica, say), or the
// primary, which alone takes writes.
enum class PgTarget { AsGiven, Primary };

class PgConnection {
public:
    // Throws StorageError with libpq's reason when it cannot connect.
    explicit PgConnection(const std::string& conninfo, PgTarget target = PgTarget::AsGiven);
    ~PgConnection();
    PgConnection(const PgConnection&) = delete;
    PgConnection& operator=(const PgConnection&) = delete;

    // A script of statements without parameters (schema, roles). Throws
    // StorageError naming the server's message.
    void run(const std::string& sql);
    // One statement with parameters $1, $2, ….
    PgResult query(const std::string& sql, const PgParams& parameters = {}, PgFormat results = PgFormat::Text);
    // A session setting (SET …), run now and again on every new connection.
    void runOnEveryConnection(const std::string& sql);
    // For the owner's work on the whole store (an upgrade moving a year of
    // samples, a month attached): no statement timeout on the server, and
    // an answer awaited up to a day (a host gone away is still found by
    // the keepalives within a minute; Ctrl-C ends the command).
    void allowLongStatements();
    // How many times the connection was made again.
    int reconnects() const { return m_reconnects; }
    // Server state tied to this connection (a transaction, a session-level
    // lock): while any is held, a lost connection is an error for the
    // holder, never made again behind its back.
    void holdServerState() { ++m_serverState; }
    void releaseServerState() { --m_serverState; }

    std::string user() const;
    bool isOpen() const;  // false once the server is lost (until the next statement connects again)
    // The server and database, for messages (never the password).
    std::string location() const;

private:
    friend class PgTransaction;
    [[noreturn]] void failed() const;
    void check(const PgResult& result) const;
    static pg_conn* connect(const std::string& conninfo, PgTarget target, std::string& reason);
    void ensureConnected();
    void reconnect();
    PgResult awaitResult();

    std::string m_conninfo;
    PgTarget m_target;
    pg_conn* m_connection;  // null once closed for not answering
    // How long a statement's answer is awaited (see openConnection()).
    std::chrono::milliseconds m_answerTimeout;
    std::vector<std::string> m_onEveryConnection;
    bool m_transactionOpen = false;  // a PgTransaction began one on this connection
    int m_serverState = 0;           // transactions and locks held (holdServerState)
    int m_reconnects = 0;
};

// Why `conninfo` cannot be kept as typed: libpq cannot read it, or it holds
// a password (which belongs in ~/.pgpass, PGPASSFILE or a service file,
// never in a program's settings). Nothing when it can.
std::optional<std::string> connectionStringProblem(const std::string& conninfo);

// `text` with every password a connection string may hold hidden: the
// value of password=… (quoted or not) and a URI's user:password@. For
// messages, which may quote what a user typed.
std::string withoutPasswords(std::string_view text);

// A transaction that rolls back unless committed, so a failure half way
// leaves nothing on the server. Inside another one it is part of it. While
// it is open the connection is never made again behind its back.
class PgTransaction {
public:
    explicit PgTransaction(PgConnection& connection);
    ~PgTransaction();
    PgTransaction(const PgTransaction&) = delete;
    PgTransaction& operator=(const PgTransaction&) = delete;
    void commit();

private:
    void end();

    PgConnection& m_connection;
    bool m_open;
};

}  // namespace tactiscope::core::storage::central
