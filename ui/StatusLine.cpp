// StatusLine: the three fields of the main window's status bar.
#include "ui/StatusLine.h"

#include "core/storage/Recorder.h"
#include "ui/LinkStatus.h"

#include <QLabel>
#include <QLocale>
#include <QStatusBar>

namespace tactiscope::ui {
namespace {

const QString kAlarmStyle = QStringLiteral("color: #c62828; font-weight: 600;");

QString count(std::uint64_t n)
{
    return QLocale().toString(static_cast<qulonglong>(n));
}

}  // namespace

StatusLine::StatusLine(QStatusBar* bar)
    : QObject(bar),
      m_device(new QLabel(tr("No device"), bar)),
      m_link(new QLabel(bar)),
      m_recording(new QLabel(bar))
{
    m_device->setObjectName(QStringLiteral("deviceLabel"));
    m_link->setObjectName(QStringLiteral("linkLabel"));
    m_recording->setObjectName(QStringLiteral("recordingLabel"));
    m_device->setContentsMargins(6, 0, 6, 0);
    bar->addWidget(m_device, 1);
    // Fixed fields on the right, each with breathing room.
    for (QLabel* label : {m_link, m_recording}) {
        label->setContentsMargins(10, 0, 10, 0);
        bar->addPermanentWidget(label);
    }
}

void StatusLine::setDevice(const QString& name)
{
    m_device->setText(name.isEmpty() ? tr("No device") : name);
}

void StatusLine::setLink(const QString& state)
{
    m_link->setStyleSheet(QString());
    m_link->setText(state);
}

void StatusLine::showLink(const LinkCounters& counters)
{
    m_link->setText(linkLine(counters));
    m_link->setStyleSheet(counters.healthy ? QString() : kAlarmStyle);
}

void StatusLine::showRecording(std::int64_t session, const core::storage::RecorderStats& stats)
{
    QString text = tr("● REC session %1: %2 samples").arg(session).arg(count(stats.samplesWritten));
    if (stats.samplesDropped > 0) text += tr(", %1 lost").arg(count(stats.samplesDropped));
    m_recording->setText(text);
    m_recording->setStyleSheet(kAlarmStyle);
}

void StatusLine::showSaved(std::int64_t session, const core::storage::RecorderStats& stats)
{
    QString text = tr("Session %1 saved: %2 samples per channel").arg(session).arg(count(stats.samplesWritten));
    if (stats.samplesDropped > 0) text += tr(", %1 lost").arg(count(stats.samplesDropped));
    m_recording->setText(text);
    m_recording->setStyleSheet(stats.samplesDropped > 0 ? kAlarmStyle : QString());
}

}  // namespace tactiscope::ui
