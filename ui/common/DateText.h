// How every view, dialog and report writes a date and time. One form per
// context: on screen the user's locale in local time ("11/24/26 10:49:56
// PM"), in files — reports, exports — ISO 8601 in local time with its offset
// ("2026-11-24T22:49:56+01:00"), which sorts and reads back anywhere. The
// stores keep UTC ("2026-11-24T21:49:56.890Z"); these turn that into either.
#pragma once

#include <QDate>
#include <QDateTime>
#include <QString>

#include <string>

namespace tactiscope::ui {

// A stored UTC time as a date-time, invalid for any text that is not one.
QDateTime storedTime(const std::string& utcIso8601);

// On screen: the locale's short date and its time with seconds, local time.
QString screenDateTime(const QDateTime& time);
QString screenDate(const QDate& date);
QString screenTime(const QTime& time);  // "10:49 PM", no seconds: for "last answered at"

// "2 h 05 min", "3 min 20 s", "12.5 s": a duration as people read it.
QString durationText(double seconds);

// In files: ISO 8601, local time to the second with its offset from UTC.
QString fileDateTime(const QDateTime& time);

// A stored time in either form; a text that is not a time is given back
// as it is (it came from a file this program does not trust), never a
// made-up date.
QString screenDateTime(const std::string& utcIso8601);
QString fileDateTime(const std::string& utcIso8601);

}  // namespace tactiscope::ui
