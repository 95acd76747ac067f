// WatchBanner: the trigger's words and colour, the alarms' words and colour.
#include "ui/live/WatchBanner.h"

#include "ui/common/NumberText.h"

#include <QApplication>
#include <QHBoxLayout>
#include <QLabel>

namespace tactiscope::ui {
namespace {

const QString kArmed = QStringLiteral("background: #e3ecf5; color: #17324d; padding: 4px 8px; border-radius: 3px;");
const QString kTriggered = QStringLiteral("background: #dff0d8; color: #1e4620; padding: 4px 8px; border-radius: 3px;");
const QString kWarning =
    QStringLiteral("background: #fff3cd; color: #5c4200; padding: 4px 8px; border-radius: 3px; font-weight: bold;");
const QString kCritical =
    QStringLiteral("background: #c62828; color: white; padding: 4px 8px; border-radius: 3px; font-weight: bold;");

}  // namespace

WatchBanner::WatchBanner(QWidget* parent)
    : QWidget(parent),
      m_trigger(new QLabel(this)),
      m_alarm(new QLabel(this))
{
    m_trigger->setObjectName(QStringLiteral("triggerState"));
    m_alarm->setObjectName(QStringLiteral("alarmBanner"));
    m_alarm->setWordWrap(true);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->addWidget(m_trigger);
    layout->addWidget(m_alarm, 1);
    m_trigger->hide();
    m_alarm->hide();
    hide();
}

void WatchBanner::showTrigger(const std::optional<TriggerView>& trigger)
{
    if (!trigger) {
        m_trigger->hide();
        return updateVisibility();
    }
    using core::trigger::TriggerState;
    const unsigned number = trigger->status.sessionsCut + (trigger->status.state == TriggerState::Finished ? 0 : 1);
    const QString of = trigger->sessions ? tr(" of %1").arg(*trigger->sessions) : QString();
    QString text;
    switch (trigger->status.state) {
    case TriggerState::Waiting:
        text = tr("Trigger waiting for %1 to clear before session %2%3").arg(trigger->condition).arg(number).arg(of);
        break;
    case TriggerState::Armed:
        text = tr("Trigger armed: session %1%2 (%3) starts when %4")
                   .arg(number)
                   .arg(of, trigger->subject.isEmpty() ? tr("no subject") : trigger->subject, trigger->condition);
        break;
    case TriggerState::Triggered:
        text = tr("Triggered: recording session %1%2 (%3)")
                   .arg(number)
                   .arg(of, trigger->subject.isEmpty() ? tr("no subject") : trigger->subject);
        break;
    case TriggerState::Finished:
        text =
            tr("Trigger done: %1 recorded").arg(countText(trigger->status.sessionsCut, tr("session"), tr("sessions")));
        break;
    }
    m_trigger->setText(text);
    m_trigger->setStyleSheet(trigger->recording ? kTriggered : kArmed);
    m_trigger->show();
    updateVisibility();
}

void WatchBanner::showAlarms(const std::vector<AlarmLine>& raised, bool fresh)
{
    if (raised.empty()) {
        m_alarm->hide();
        return updateVisibility();
    }
    bool critical = false;
    QStringList lines;
    for (const auto& alarm : raised) {
        critical = critical || alarm.critical;
        lines << (alarm.critical ? tr("CRITICAL: %1") : tr("Warning: %1")).arg(alarm.text);
    }
    m_alarm->setText(lines.join(QLatin1Char('\n')));
    m_alarm->setStyleSheet(critical ? kCritical : kWarning);
    m_alarm->show();
    if (fresh && m_sound) QApplication::beep();
    updateVisibility();
}

QString WatchBanner::triggerText() const
{
    return m_trigger->isVisibleTo(this) ? m_trigger->text() : QString();
}

QString WatchBanner::alarmText() const
{
    return m_alarm->isVisibleTo(this) ? m_alarm->text() : QString();
}

void WatchBanner::updateVisibility()
{
    setVisible(!m_trigger->isHidden() || !m_alarm->isHidden());
}

}  // namespace tactiscope::ui
