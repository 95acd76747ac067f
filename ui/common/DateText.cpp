// Date, time and duration texts for screen and files.
#include "ui/common/DateText.h"

#include "ui/common/NumberText.h"

#include <QLocale>
#include <QObject>

#include <cmath>

namespace tactiscope::ui {
namespace {

// The locale's short time format with seconds added after its minutes
// ("h:mm AP" → "h:mm:ss AP", "H.mm" → "H.mm.ss"): a session list needs them
// to tell two sessions of one minute apart, and the long format adds a zone.
QString timeFormatWithSeconds(const QLocale& locale)
{
    QString format = locale.timeFormat(QLocale::ShortFormat);
    if (format.contains(QStringLiteral("ss"))) return format;
    const qsizetype minutes = format.indexOf(QStringLiteral("mm"));
    if (minutes <= 0) return locale.timeFormat(QLocale::LongFormat);
    return format.insert(minutes + 2, format.at(minutes - 1) + QStringLiteral("ss"));
}

}  // namespace

QDateTime storedTime(const std::string& utcIso8601)
{
    QDateTime time = QDateTime::fromString(QString::fromStdString(utcIso8601), Qt::ISODateWithMs);
    return time.isValid() ? time.toUTC() : QDateTime();
}

QString screenDateTime(const QDateTime& time)
{
    const QLocale locale;
    const QDateTime local = time.toLocalTime();
    return locale.toString(local.date(), QLocale::ShortFormat) + u' ' +
           locale.toString(local.time(), timeFormatWithSeconds(locale));
}

QString screenDate(const QDate& date)
{
    return QLocale().toString(date, QLocale::ShortFormat);
}

QString screenTime(const QTime& time)
{
    return QLocale().toString(time, QLocale::ShortFormat);
}

QString durationText(double seconds)
{
    if (seconds < 60.0) return QObject::tr("%1 s").arg(fixedText(seconds, 1));
    const auto whole = static_cast<long long>(std::llround(seconds));
    if (whole < 3600) return QObject::tr("%1 min %2 s").arg(whole / 60).arg(whole % 60, 2, 10, QLatin1Char('0'));
    return QObject::tr("%1 h %2 min").arg(whole / 3600).arg((whole % 3600) / 60, 2, 10, QLatin1Char('0'));
}

QString fileDateTime(const QDateTime& time)
{
    const QDateTime local = time.toLocalTime();
    return local.toOffsetFromUtc(local.offsetFromUtc()).toString(Qt::ISODate);
}

QString screenDateTime(const std::string& utcIso8601)
{
    const QDateTime time = storedTime(utcIso8601);
    return time.isValid() ? screenDateTime(time) : QString::fromStdString(utcIso8601);
}

QString fileDateTime(const std::string& utcIso8601)
{
    const QDateTime time = storedTime(utcIso8601);
    return time.isValid() ? fileDateTime(time) : QString::fromStdString(utcIso8601);
}

}  // namespace tactiscope::ui
