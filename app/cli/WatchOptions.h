// `record`'s hands-free options: a trigger that starts and ends the
// recordings (--trigger, --pre, --post, --hold-off, --sessions, --rearm)
// and limit alarms (--limit, repeatable; --stop-on critical), read into the
// rules below the UI (core/trigger) that the GUI uses too.
#pragma once

#include "core/trigger/LimitWatch.h"
#include "core/trigger/TriggerMachine.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QList>

#include <optional>
#include <vector>

namespace tactiscope::cli {

struct WatchOptions {
    std::optional<core::trigger::TriggerSettings> trigger;
    std::vector<core::trigger::LimitSpec> limits;
    bool stopOnCritical = false;
};

QList<QCommandLineOption> watchOptions();
// The options given, or none with `error` saying what is wrong.
std::optional<WatchOptions> parseWatchOptions(const QCommandLineParser& parser, QString& error);

}  // namespace tactiscope::cli
