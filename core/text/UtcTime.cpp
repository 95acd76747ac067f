// UtcTime: ISO 8601 formatting without the locale.
#include "core/text/UtcTime.h"

#include <cctype>
#include <cstdio>
#include <ctime>

namespace tactiscope::core::text {

std::string utcIso8601(std::chrono::system_clock::time_point time)
{
    const std::time_t seconds = std::chrono::system_clock::to_time_t(time);
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(time.time_since_epoch()).count() % 1000;
    std::tm utc{};
    gmtime_r(&seconds, &utc);
    char text[64];  // roomy enough for any int the compiler imagines in a field
    std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", utc.tm_year + 1900, utc.tm_mon + 1,
                  utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec, static_cast<int>(ms));
    return text;
}

std::optional<double> utcSeconds(std::string_view text)
{
    // YYYY-MM-DDTHH:MM:SS[.fff…]Z, every field its digits, read by position.
    const auto digits = [&](std::size_t at, std::size_t count) -> std::optional<int> {
        if (at + count > text.size()) return std::nullopt;
        int value = 0;
        for (std::size_t i = at; i < at + count; ++i) {
            if (!std::isdigit(static_cast<unsigned char>(text[i]))) return std::nullopt;
            value = value * 10 + (text[i] - '0');
        }
        return value;
    };
    const auto at = [&](std::size_t i, char c) { return i < text.size() && text[i] == c; };
    const auto year = digits(0, 4), month = digits(5, 2), day = digits(8, 2);
    const auto hour = digits(11, 2), minute = digits(14, 2), second = digits(17, 2);
    if (!(year && month && day && hour && minute && second && at(4, '-') && at(7, '-') && at(10, 'T') && at(13, ':') &&
          at(16, ':')))
        return std::nullopt;
    const std::chrono::year_month_day date{std::chrono::year{*year}, std::chrono::month{static_cast<unsigned>(*month)},
                                           std::chrono::day{static_cast<unsigned>(*day)}};
    if (!date.ok() || *hour > 23 || *minute > 59 || *second > 60) return std::nullopt;
    double fraction = 0.0;
    std::size_t i = 19;
    if (at(i, '.')) {
        double scale = 0.1;
        for (++i; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i, scale /= 10)
            fraction += (text[i] - '0') * scale;
        if (scale == 0.1) return std::nullopt;  // a point without digits
    }
    if (!at(i, 'Z') || i + 1 != text.size()) return std::nullopt;
    const auto days = std::chrono::sys_days{date}.time_since_epoch().count();
    return static_cast<double>(days) * 86400.0 + *hour * 3600.0 + *minute * 60.0 + *second + fraction;
}

}  // namespace tactiscope::core::text
