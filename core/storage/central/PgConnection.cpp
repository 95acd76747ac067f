// libpq connections and results.
#include "core/storage/central/PgConnection.h"

#include <libpq-fe.h>

namespace tactiscope::core::storage::central {
namespace {

// libpq's messages end in a newline; a user reads one line.
std::string oneLine(const char* message)
{
    std::string text = message ? message : "";
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    for (char& c : text)
        if (c == '\n') c = ' ';
    return text;
}

}  // namespace

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
    return PQgetvalue(m_result, row, column);
}

PgConnection::PgConnection(const std::string& conninfo)
    : m_connection(PQconnectdb(conninfo.c_str()))
{
    if (!m_connection) throw StorageError("cannot reach the central store: out of memory");
    if (PQstatus(m_connection) != CONNECTION_OK) {
        const std::string reason = oneLine(PQerrorMessage(m_connection));
        PQfinish(m_connection);
        throw StorageError("cannot reach the central store: " + reason);
    }
    // Server notices ("relation already exists, skipping") are not for the user.
    PQsetNoticeProcessor(
        m_connection, [](void*, const char*) {}, nullptr);
}

PgConnection::~PgConnection()
{
    PQfinish(m_connection);
}

// A statement that failed throws, with the server's reason.
void PgConnection::check(const PgResult& result) const
{
    if (result.m_result == nullptr) throw StorageError("the central store: " + oneLine(PQerrorMessage(m_connection)));
    const ExecStatusType status = PQresultStatus(result.m_result);
    if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK)
        throw StorageError("the central store refused: " + oneLine(PQresultErrorMessage(result.m_result)));
}

void PgConnection::run(const std::string& sql)
{
    check(PgResult(PQexec(m_connection, sql.c_str())));
}

PgResult PgConnection::query(const std::string& sql, const std::vector<std::optional<std::string>>& parameters)
{
    std::vector<const char*> values;
    values.reserve(parameters.size());
    for (const auto& p : parameters) values.push_back(p ? p->c_str() : nullptr);
    PgResult result(PQexecParams(m_connection, sql.c_str(), static_cast<int>(values.size()), nullptr, values.data(),
                                 nullptr, nullptr, 0));
    check(result);
    return result;
}

std::string PgConnection::user() const
{
    return PQuser(m_connection);
}

}  // namespace tactiscope::core::storage::central
