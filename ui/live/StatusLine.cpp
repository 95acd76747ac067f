// StatusLine: the three fields of the main window's status bar.
#include "ui/live/StatusLine.h"

#include "core/storage/Recorder.h"
#include "devices/session/LiveSession.h"
#include "ui/common/NumberText.h"
#include "ui/common/ProblemReport.h"
#include "ui/device/LinkStatus.h"
#include "ui/live/LiveStation.h"

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
      m_bar(bar),
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

void StatusLine::watch(LiveStation& station)
{
    connect(&station, &LiveStation::connecting, this, [this](const QString& label) {
        setDevice(label);
        setLink(tr("Connecting…"));
    });
    connect(&station, &LiveStation::connectFailed, this, [this] { setLink(tr("Connection failed")); });
    connect(&station, &LiveStation::connected, this,
            [this, &station] { setDevice(QString::fromStdString(station.device()->source().name())); });
    connect(&station, &LiveStation::disconnected, this, [this] {
        setDevice({});
        setLink({});
    });
    connect(&station, &LiveStation::polled, this, [this, &station](const devices::session::PipelineNews& news) {
        const auto* live = station.device();
        if (!live) return;
        showLink(linkCounters(live->stats(), live->source()));
        if (station.isRecording()) showRecording(station.pipeline().sessionId(), live->recorderStats());
        // What the links noticed is in the record (an alarm) and told here.
        for (const auto& [device, notice] : news.notices) {
            const QString from = device.empty() ? tr("Device") : QString::fromStdString(device);
            const QString text =
                tr("%1, at %2 s: %3").arg(from, fixedText(notice.time_s, 1), QString::fromStdString(notice.text));
            logProblem({tr("Device"), text, {}, {}});
            m_bar->showMessage(text, 15000);
        }
    });
    connect(&station, &LiveStation::recordingEnded, this, [this](const devices::session::RecordingEnd& end) {
        if (!end.parts.empty()) showSaved(end.session, end.parts.front().what.stats);
    });
    connect(&station, &LiveStation::told, this, [this](const QString& line) { m_bar->showMessage(line, 8000); });
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
