// WatchOptions: the trigger's and the limits' options, checked.
#include "WatchOptions.h"

#include "CliSupport.h"

#include <cmath>

namespace tactiscope::cli {

QList<QCommandLineOption> watchOptions()
{
    return {
        {QStringLiteral("trigger"),
         QStringLiteral(
             "Record only when CONDITION begins, one session per trigger: CHANNEL>LEVEL, <, "
             "'CHANNEL rising LEVEL', 'falling', 'inside A..B', 'outside A..B'; CHANNEL a channel or a "
             "mode quantity (force, deflection, force_high, decision, …), in SI units (a math channel in its "
             "own UNIT, a.filtered as a)."),
         QStringLiteral("CONDITION")},
        {QStringLiteral("pre"), QStringLiteral("With --trigger: seconds kept before the trigger (default 0)."),
         QStringLiteral("S")},
        {QStringLiteral("post"),
         QStringLiteral("With --trigger: seconds kept after the condition clears (an edge: after it; default 0)."),
         QStringLiteral("S")},
        {QStringLiteral("hold-off"),
         QStringLiteral("With --trigger: seconds after a session before the next may trigger (default 0)."),
         QStringLiteral("S")},
        {QStringLiteral("sessions"),
         QStringLiteral("With --trigger: record N sessions, then stop (default 1); the subject is numbered on "
                        "(door-17, door-18, …)."),
         QStringLiteral("N")},
        {QStringLiteral("rearm"), QStringLiteral("With --trigger: re-arm after every session until stopped.")},
        {QStringLiteral("limit"),
         QStringLiteral("Alarm limits, repeatable: QUANTITY>warning:W,critical:C[,hold:S] (or <; either level "
                        "alone), or a window: QUANTITY outside warning:A..B,critical:C..D (or inside), in SI units (a "
                        "math channel in its own UNIT), "
                        "besides the probe's own (its profile's or its sensor model's, e.g. a capacitive "
                        "beam's safe force), whose limit on the same quantity and side it replaces; alarms are "
                        "printed and stored as alarm events."),
         QStringLiteral("LIMIT")},
        {QStringLiteral("stop-on"),
         QStringLiteral("critical: end the recording at the first critical alarm (exit 1, data kept)."),
         QStringLiteral("critical")},
    };
}

std::optional<WatchOptions> parseWatchOptions(const QCommandLineParser& parser, QString& error)
{
    WatchOptions options;
    const auto seconds = [&](const char* name, const core::NumberRange& range, double& into) {
        const auto value = numberInRange(parser, name, range, into, error);
        if (value) into = *value;
        return value.has_value();
    };
    if (parser.isSet(QStringLiteral("trigger"))) {
        const auto parsed = core::trigger::parseTrigger(parser.value(QStringLiteral("trigger")).toStdString());
        if (!parsed.condition) {
            error = QStringLiteral("--trigger: %1").arg(QString::fromStdString(parsed.error));
            return std::nullopt;
        }
        core::trigger::TriggerSettings settings;
        settings.condition = *parsed.condition;
        if (!seconds("pre", core::kPreTriggerRange, settings.pre_s) ||
            !seconds("post", core::kPostTriggerRange, settings.post_s) ||
            !seconds("hold-off", core::kHoldOffRange, settings.holdOff_s))
            return std::nullopt;
        if (parser.isSet(QStringLiteral("sessions")) && parser.isSet(QStringLiteral("rearm"))) {
            error = QStringLiteral("give --sessions N or --rearm, not both");
            return std::nullopt;
        }
        settings.sessions = 1u;
        if (parser.isSet(QStringLiteral("sessions"))) {
            const auto count = numberInRange(parser, "sessions", core::kTriggeredSessionsRange, 1.0, error);
            if (!count || *count != std::floor(*count)) {
                if (count) error = QStringLiteral("--sessions must be a whole number");
                return std::nullopt;
            }
            settings.sessions = static_cast<unsigned>(*count);
        }
        if (parser.isSet(QStringLiteral("rearm"))) settings.sessions.reset();
        options.trigger = settings;
    } else {
        for (const char* name : {"pre", "post", "hold-off", "sessions", "rearm"})
            if (parser.isSet(QLatin1String(name))) {
                error = QStringLiteral("--%1 needs --trigger").arg(QLatin1String(name));
                return std::nullopt;
            }
    }
    for (const QString& text : parser.values(QStringLiteral("limit"))) {
        const auto parsed = core::trigger::parseLimit(text.toStdString());
        if (!parsed.limit) {
            error = QStringLiteral("--limit: %1").arg(QString::fromStdString(parsed.error));
            return std::nullopt;
        }
        options.limits.push_back(*parsed.limit);
    }
    if (parser.isSet(QStringLiteral("stop-on"))) {
        if (parser.value(QStringLiteral("stop-on")) != QStringLiteral("critical")) {
            error = QStringLiteral("--stop-on takes critical");
            return std::nullopt;
        }
        options.stopOnCritical = true;
    }
    return options;
}

}  // namespace tactiscope::cli
