// CentralMonths: the month partitions made, detached and attached.
#include "core/storage/central/CentralMonths.h"

#include <cstdio>
#include <regex>

namespace tactiscope::core::storage::central {
namespace {

// A month's table of `parent` (chunks or lod): "months.chunks_2026_11".
std::string monthTable(const std::string& parent, const std::string& month)
{
    return "months." + parent + "_" + month.substr(0, 4) + "_" + month.substr(5, 2);
}

std::string firstDay(const std::string& month)
{
    return month + "-01";
}

// The first day of the month after.
std::string nextFirstDay(const std::string& month)
{
    int year = std::stoi(month.substr(0, 4)), number = std::stoi(month.substr(5, 2)) + 1;
    if (number > 12) {
        number = 1;
        ++year;
    }
    char day[32];
    std::snprintf(day, sizeof day, "%04d-%02d-01", year, number);
    return day;
}

}  // namespace

bool isMonthText(const std::string& text)
{
    static const std::regex month("[0-9]{4}-(0[1-9]|1[0-2])");
    return std::regex_match(text, month);
}

std::vector<StoreMonth> storeMonths(PgConnection& owner)
{
    // The chunks' month tables, attached or not (a detached month is in
    // detached_months; its tables may have been dropped since).
    const PgResult r = owner.query(
        "SELECT to_char(m.month, 'YYYY-MM'), d.month IS NULL, "
        "coalesce(pg_total_relation_size(to_regclass(format('months.chunks_%s', to_char(m.month, 'YYYY_MM')))), 0) + "
        "coalesce(pg_total_relation_size(to_regclass(format('months.lod_%s', to_char(m.month, 'YYYY_MM')))), 0) "
        "FROM (SELECT to_date(substr(c.relname, 8), 'YYYY_MM') AS month FROM pg_class c "
        "      JOIN pg_namespace n ON n.oid = c.relnamespace WHERE n.nspname = 'months' AND c.relname ~ "
        "'^chunks_[0-9]{4}_[0-9]{2}$' UNION SELECT month FROM detached_months) m "
        "LEFT JOIN detached_months d ON d.month = m.month ORDER BY m.month");
    std::vector<StoreMonth> months;
    for (int i = 0; i < r.rows(); ++i) months.push_back({r.text(i, 0), r.text(i, 1) == "t", r.int64(i, 2)});
    return months;
}

std::vector<std::string> makeComingMonths(PgConnection& owner, int ahead)
{
    const PgResult r = owner.query(
        "SELECT to_char(m, 'YYYY-MM'), to_regclass(format('months.chunks_%s', to_char(m, 'YYYY_MM'))) IS NULL "
        "FROM generate_series(date_trunc('month', now() AT TIME ZONE 'UTC'), "
        "date_trunc('month', now() AT TIME ZONE 'UTC') + make_interval(months => $1::int), interval '1 month') m",
        PgParams().int64(ahead));
    std::vector<std::string> made;
    for (int i = 0; i < r.rows(); ++i) {
        if (r.text(i, 1) != "t") continue;
        owner.query("SELECT make_month($1::date)", {firstDay(r.text(i, 0))});
        made.push_back(r.text(i, 0));
    }
    return made;
}

std::vector<std::string> detachMonthsBefore(PgConnection& owner, const std::string& before)
{
    if (!isMonthText(before)) throw StorageError("'" + before + "' is not a month such as 2026-01");
    const std::string now = owner.query("SELECT to_char(now() AT TIME ZONE 'UTC', 'YYYY-MM')").text(0, 0);
    if (before > now)
        throw StorageError("months before " + before + " include this month (" + now +
                           "), whose sessions are still being sent; detach only months that have ended");
    std::vector<std::string> detached;
    for (const StoreMonth& m : storeMonths(owner)) {
        if (!m.attached || m.month >= before) continue;
        // One month at a time, each whole: its two tables and its mark.
        PgTransaction transaction(owner);
        owner.run("ALTER TABLE chunks DETACH PARTITION " + monthTable("chunks", m.month) +
                  ";\nALTER TABLE lod DETACH PARTITION " + monthTable("lod", m.month) + ";");
        owner.query("INSERT INTO detached_months (month, detached_utc) VALUES ($1::date, server_utc())",
                    {firstDay(m.month)});
        transaction.commit();
        detached.push_back(m.month);
    }
    return detached;
}

bool attachMonth(PgConnection& owner, const std::string& month)
{
    if (!isMonthText(month)) throw StorageError("'" + month + "' is not a month such as 2026-01");
    const PgResult r =
        owner.query("SELECT EXISTS (SELECT 1 FROM detached_months WHERE month = $1::date), "
                    "to_regclass($2) IS NOT NULL AND to_regclass($3) IS NOT NULL",
                    PgParams().text(firstDay(month)).text(monthTable("chunks", month)).text(monthTable("lod", month)));
    if (r.text(0, 0) != "t") {
        if (r.text(0, 1) == "t") return false;
        throw StorageError("the central store has no month " + month + " to attach");
    }
    if (r.text(0, 1) != "t")
        throw StorageError("the tables of " + month + " (" + monthTable("chunks", month) + ", " +
                           monthTable("lod", month) +
                           ") are no longer in the database: restore them from the archive first");
    PgTransaction transaction(owner);
    const std::string range = " FOR VALUES FROM ('" + firstDay(month) + "') TO ('" + nextFirstDay(month) + "');";
    owner.run("ALTER TABLE chunks ATTACH PARTITION " + monthTable("chunks", month) + range +
              "\nALTER TABLE lod ATTACH PARTITION " + monthTable("lod", month) + range);
    owner.query("DELETE FROM detached_months WHERE month = $1::date", {firstDay(month)});
    transaction.commit();
    return true;
}

}  // namespace tactiscope::core::storage::central
