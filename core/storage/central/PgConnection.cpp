// libpq connections and results.
#include "core/storage/central/PgConnection.h"

#include <libpq-fe.h>
#include <poll.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <thread>

namespace tactiscope::core::storage::central {
namespace {

// libpq's messages span lines (and indent their hints); a user reads one
// line, with single spaces.
std::string oneLine(const char* message)
{
    std::string text;
    for (const char* c = message ? message : ""; *c; ++c) {
        const bool space = *c == ' ' || *c == '\n' || *c == '\t';
        if (!space)
            text += *c;
        else if (!text.empty() && text.back() != ' ')
            text += ' ';
    }
    if (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
}

// Binary results are in network order (big-endian).
std::uint64_t bigEndian(const char* bytes, int length)
{
    std::uint64_t value = 0;
    for (int i = 0; i < length; ++i) value = value << 8 | static_cast<std::uint8_t>(bytes[i]);
    return value;
}

std::string exactText(double value)
{
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::string(text, end);
}

// The connection string's own settings win over these defaults: a server
// that does not answer is given up after 10 s (libpq would wait as long as
// the system's TCP timeout); TCP keepalives find a host that went away
// within a minute; a statement may run a minute on the server; the
// server compiles none of our queries (JIT: its default spends about
// 280 ms compiling a listing that does 43 ms of work, docs/fleet.md); and
// the server's activity view names us. The primary, when asked for,
// overrides the string's own choice among its hosts.
pg_conn* openConnection(const std::string& conninfo, PgTarget target)
{
    const char* const keywords[] = {
        "connect_timeout",      "keepalives", "keepalives_idle",           "keepalives_interval",
        "keepalives_count",     "options",    "fallback_application_name", "dbname",
        "target_session_attrs", nullptr};
    const char* const values[] = {"10",
                                  "1",
                                  "30",
                                  "10",
                                  "3",
                                  "-c statement_timeout=60000 -c jit=off",
                                  "tactiscope",
                                  conninfo.c_str(),
                                  target == PgTarget::Primary ? "read-write" : nullptr,
                                  nullptr};
    return PQconnectdbParams(keywords, values, 1);  // 1: dbname holds the whole connection string
}

// How long a statement's answer is awaited: TACTISCOPE_CENTRAL_ANSWER_S
// seconds when set to a positive number, else 90 s (the server's own
// statement_timeout, 60 s, ends any statement it is still running first).
std::chrono::milliseconds answerTimeout()
{
    if (const char* text = std::getenv("TACTISCOPE_CENTRAL_ANSWER_S")) {
        char* end = nullptr;
        const double seconds = std::strtod(text, &end);
        if (end != text && std::isfinite(seconds) && seconds > 0.0 && seconds < 86400.0)
            return std::chrono::milliseconds(static_cast<std::int64_t>(seconds * 1000.0));
    }
    return std::chrono::seconds(90);
}

}  // namespace

PgParams::PgParams(std::initializer_list<std::optional<std::string>> texts)
    : PgParams(std::vector<std::optional<std::string>>(texts))
{
}

PgParams::PgParams(const std::vector<std::optional<std::string>>& texts)
{
    for (const auto& t : texts) t ? text(*t) : null();
}

PgParams& PgParams::text(std::string value)
{
    m_bytesHeld += value.size();
    m_values.emplace_back(std::move(value));
    m_formats.push_back(0);
    return *this;
}

PgParams& PgParams::int64(std::int64_t value)
{
    return text(std::to_string(value));
}

PgParams& PgParams::real(double value)
{
    return text(exactText(value));
}

PgParams& PgParams::optionalReal(std::optional<double> value)
{
    return value ? real(*value) : null();
}

PgParams& PgParams::bytes(std::span<const std::uint8_t> value)
{
    m_bytesHeld += value.size();
    m_values.emplace_back(std::string(reinterpret_cast<const char*>(value.data()), value.size()));
    m_formats.push_back(1);
    return *this;
}

PgParams& PgParams::null()
{
    m_values.emplace_back(std::nullopt);
    m_formats.push_back(0);
    return *this;
}

PgResult::PgResult(pg_result* result)
    : m_result(result)
{
}

PgResult::~PgResult()
{
    if (m_result) PQclear(m_result);
}

PgResult::PgResult(PgResult&& other) noexcept
    : m_result(other.m_result)
{
    other.m_result = nullptr;
}

int PgResult::rows() const
{
    return PQntuples(m_result);
}

bool PgResult::isNull(int row, int column) const
{
    return PQgetisnull(m_result, row, column) != 0;
}

std::string PgResult::text(int row, int column) const
{
    return std::string(PQgetvalue(m_result, row, column), static_cast<std::size_t>(PQgetlength(m_result, row, column)));
}

std::int64_t PgResult::int64(int row, int column) const
{
    const char* value = PQgetvalue(m_result, row, column);
    const int length = PQgetlength(m_result, row, column);
    if (PQfformat(m_result, column) == 1) {
        // int2, int4 or int8: sign-extend from the length given.
        const std::uint64_t raw = bigEndian(value, length);
        const int unused = 64 - 8 * length;
        return unused > 0 ? static_cast<std::int64_t>(raw << unused) >> unused : static_cast<std::int64_t>(raw);
    }
    std::int64_t result = 0;
    std::from_chars(value, value + length, result);
    return result;
}

double PgResult::real(int row, int column) const
{
    const char* value = PQgetvalue(m_result, row, column);
    const int length = PQgetlength(m_result, row, column);
    if (PQfformat(m_result, column) == 1) {
        if (length == 4)
            return static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(bigEndian(value, 4))));
        return std::bit_cast<double>(bigEndian(value, 8));
    }
    double result = 0.0;
    std::from_chars(value, value + length, result);
    return result;
}

std::optional<double> PgResult::optionalReal(int row, int column) const
{
    if (isNull(row, column)) return std::nullopt;
    return real(row, column);
}

std::span<const std::uint8_t> PgResult::bytes(int row, int column) const
{
    // Only a binary result gives a bytea's bytes as they are.
    return {reinterpret_cast<const std::uint8_t*>(PQgetvalue(m_result, row, column)),
            static_cast<std::size_t>(PQgetlength(m_result, row, column))};
}

// A connection made, or nothing with the reason.
pg_conn* PgConnection::connect(const std::string& conninfo, PgTarget target, std::string& reason)
{
    pg_conn* connection = openConnection(conninfo, target);
    if (!connection) {
        reason = "out of memory";
        return nullptr;
    }
    if (PQstatus(connection) != CONNECTION_OK) {
        reason = oneLine(PQerrorMessage(connection));
        PQfinish(connection);
        return nullptr;
    }
    // Server notices ("relation already exists, skipping") are not for the user.
    PQsetNoticeProcessor(
        connection, [](void*, const char*) {}, nullptr);
    return connection;
}

PgConnection::PgConnection(const std::string& conninfo, PgTarget target)
    : m_conninfo(conninfo),
      m_target(target),
      m_connection(nullptr),
      m_answerTimeout(answerTimeout())
{
    std::string reason;
    m_connection = connect(conninfo, target, reason);
    if (!m_connection) throw CentralUnreachable("cannot reach the central store: " + reason);
}

void PgConnection::allowLongStatements()
{
    runOnEveryConnection("SET statement_timeout = 0");
    m_answerTimeout = std::chrono::hours(24);
}

void PgConnection::runOnEveryConnection(const std::string& sql)
{
    run(sql);
    m_onEveryConnection.push_back(sql);
}

// Before a statement. Between statements nothing is owed to us, so anything
// to read on an idle connection is the server ending it (a restart: its
// FATAL message, or the end of the stream): the connection is dropped
// before anything is sent on it, and made again.
void PgConnection::ensureConnected()
{
    if (m_connection && PQstatus(m_connection) == CONNECTION_OK && !PQisBusy(m_connection)) {
        pollfd socket{PQsocket(m_connection), POLLIN, 0};
        if (::poll(&socket, 1, 0) > 0) {
            PQfinish(m_connection);
            m_connection = nullptr;
        }
    }
    if (m_connection && PQstatus(m_connection) == CONNECTION_OK) return;
    if (m_serverState > 0)
        throw CentralUnreachable("the central store: the connection was lost; the transaction under way was not kept");
    reconnect();
}

void PgConnection::reconnect()
{
    // A server starting again refuses for a moment ("the database system is
    // starting up"): three quick tries, half a second apart. A try that
    // took its time (a host that does not answer: up to connect_timeout) is
    // not repeated, so a reader waits for one timeout at most.
    constexpr int kTries = 3;
    PQfinish(m_connection);
    m_connection = nullptr;
    std::string reason;
    for (int attempt = 0; attempt < kTries && !m_connection; ++attempt) {
        if (attempt > 0) std::this_thread::sleep_for(std::chrono::milliseconds(500));
        const auto started = std::chrono::steady_clock::now();
        m_connection = connect(m_conninfo, m_target, reason);
        if (std::chrono::steady_clock::now() - started > std::chrono::seconds(1)) break;
    }
    if (!m_connection) throw CentralUnreachable("cannot reach the central store: " + reason);
    ++m_reconnects;
    for (const std::string& sql : m_onEveryConnection) run(sql);
}

PgConnection::~PgConnection()
{
    PQfinish(m_connection);
}

// A statement that could not be sent or answered throws with libpq's
// reason; a connection that went bad on the way (the server closed it) is
// the server gone, whatever the statement was.
void PgConnection::failed() const
{
    const std::string reason = "the central store: " + oneLine(PQerrorMessage(m_connection));
    if (PQstatus(m_connection) != CONNECTION_OK) throw CentralUnreachable(reason);
    throw StorageError(reason);
}

// A statement the server refused throws with its reason.
void PgConnection::check(const PgResult& result) const
{
    if (result.m_result == nullptr) failed();
    const ExecStatusType status = PQresultStatus(result.m_result);
    if (status == PGRES_COMMAND_OK || status == PGRES_TUPLES_OK) return;
    // The server's sentence, its detail and hint: not its severity or the
    // CONTEXT lines (which function of ours raised it, on which line).
    const auto field = [&result](int code) {
        const char* text = PQresultErrorField(result.m_result, code);
        return text ? oneLine(text) : std::string();
    };
    std::string reason = field(PG_DIAG_MESSAGE_PRIMARY);
    if (reason.empty()) reason = oneLine(PQresultErrorMessage(result.m_result));
    for (const int extra : {PG_DIAG_MESSAGE_DETAIL, PG_DIAG_MESSAGE_HINT})
        if (const std::string text = field(extra); !text.empty()) reason += " (" + text + ")";
    throw StorageError("the central store refused: " + reason);
}

void PgConnection::run(const std::string& sql)
{
    ensureConnected();
    if (!PQsendQuery(m_connection, sql.c_str())) failed();
    check(awaitResult());
}

// The last result of what was sent, waiting at most m_answerTimeout: a
// server that stops answering once connected (stopped, or its host frozen
// with the link up) would keep libpq waiting for ever. After the deadline
// the connection is closed: it cannot be used again.
PgResult PgConnection::awaitResult()
{
    const auto deadline = std::chrono::steady_clock::now() + m_answerTimeout;
    pg_result* last = nullptr;
    const auto giveUp = [&](const std::string& why) {
        if (last) PQclear(last);
        throw CentralUnreachable("the central store: " + why);
    };
    for (;;) {
        if (!PQconsumeInput(m_connection)) giveUp(oneLine(PQerrorMessage(m_connection)));
        while (!PQisBusy(m_connection)) {
            pg_result* result = PQgetResult(m_connection);
            if (!result) return PgResult(last);
            if (last) PQclear(last);
            last = result;
        }
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            PQfinish(m_connection);
            m_connection = nullptr;  // closed: the next statement connects again
            giveUp("no answer within " + std::to_string(m_answerTimeout.count() / 1000) +
                   " s after the connection was made; the server or its host has stopped answering");
        }
        pollfd socket{PQsocket(m_connection), POLLIN, 0};
        ::poll(&socket, 1, static_cast<int>(std::min<std::int64_t>(left.count(), 1000)));
    }
}

PgResult PgConnection::query(const std::string& sql, const PgParams& parameters, PgFormat results)
{
    const std::size_t n = parameters.m_values.size();
    std::vector<const char*> values(n);
    std::vector<int> lengths(n);  // read for binary ones only
    for (std::size_t i = 0; i < n; ++i) {
        if (const auto& value = parameters.m_values[i]) {
            values[i] = value->c_str();
            lengths[i] = static_cast<int>(value->size());
        }
    }
    ensureConnected();
    if (!PQsendQueryParams(m_connection, sql.c_str(), static_cast<int>(n), nullptr, values.data(), lengths.data(),
                           parameters.m_formats.data(), results == PgFormat::Binary ? 1 : 0))
        failed();
    PgResult result = awaitResult();
    check(result);
    return result;
}

std::string PgConnection::user() const
{
    return m_connection ? PQuser(m_connection) : "";
}

std::string PgConnection::location() const
{
    if (!m_connection) return "the central store (connection closed)";
    const std::string host = PQhost(m_connection) ? PQhost(m_connection) : "";
    return "database " + std::string(PQdb(m_connection)) + " on " + host + ":" + PQport(m_connection);
}

bool PgConnection::isOpen() const
{
    return PQstatus(m_connection) == CONNECTION_OK;
}

std::optional<std::string> connectionStringProblem(const std::string& conninfo)
{
    char* error = nullptr;
    PQconninfoOption* options = PQconninfoParse(conninfo.c_str(), &error);
    if (!options) {
        const std::string reason = error ? oneLine(error) : "out of memory";
        PQfreemem(error);
        return "not a connection string: " + reason;
    }
    bool password = false;
    for (const PQconninfoOption* o = options; o->keyword; ++o)
        if (std::string_view(o->keyword) == "password" && o->val && *o->val) password = true;
    PQconninfoFree(options);
    if (password)
        return std::string("it holds a password; keep passwords in ~/.pgpass (or PGPASSFILE, a service file)");
    return std::nullopt;
}

std::string withoutPasswords(std::string_view text)
{
    std::string out(text);
    // password=secret, password = 'se cret', PASSWORD=…
    for (std::size_t at = 0;;) {
        std::string lower = out;
        for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        at = lower.find("password", at);
        if (at == std::string::npos) break;
        std::size_t i = at + 8;
        while (i < out.size() && out[i] == ' ') ++i;
        if (i >= out.size() || out[i] != '=') {
            at = i;
            continue;
        }
        ++i;
        while (i < out.size() && out[i] == ' ') ++i;
        std::size_t end = i;
        if (end < out.size() && out[end] == '\'') {
            for (++end; end < out.size() && out[end] != '\''; ++end)
                if (out[end] == '\\') ++end;
            end = std::min(out.size(), end + 1);
        } else {
            while (end < out.size() && out[end] != ' ' && out[end] != '&' && out[end] != '\n') ++end;
        }
        out.replace(i, end - i, "***");
        at = i + 3;
    }
    // scheme://user:secret@host
    for (std::size_t scheme = out.find("://"); scheme != std::string::npos; scheme = out.find("://", scheme + 3)) {
        const std::size_t start = scheme + 3;
        const std::size_t stop = out.find_first_of("/? \n", start);
        const std::size_t at = out.rfind('@', stop == std::string::npos ? out.size() : stop);
        if (at == std::string::npos || at < start) continue;
        const std::size_t colon = out.find(':', start);
        if (colon == std::string::npos || colon > at) continue;
        out.replace(colon + 1, at - colon - 1, "***");
    }
    return out;
}

PgTransaction::PgTransaction(PgConnection& connection)
    : m_connection(connection),
      m_open(!connection.m_transactionOpen)
{
    if (!m_open) return;
    m_connection.run("BEGIN");
    m_connection.m_transactionOpen = true;
    m_connection.holdServerState();
}

PgTransaction::~PgTransaction()
{
    if (!m_open) return;
    try {
        if (m_connection.isOpen()) m_connection.run("ROLLBACK");
    } catch (const StorageError&) {
        // The connection is gone; the server rolls back by itself.
    }
    end();
}

void PgTransaction::commit()
{
    if (!m_open) return;
    m_open = false;
    // Still held while COMMIT is sent: on a lost connection it must fail,
    // not connect again and "commit" nothing on a new one.
    try {
        m_connection.run("COMMIT");
    } catch (const StorageError&) {
        end();
        throw;
    }
    end();
}

void PgTransaction::end()
{
    m_connection.m_transactionOpen = false;
    m_connection.releaseServerState();
}

}  // namespace tactiscope::core::storage::central
