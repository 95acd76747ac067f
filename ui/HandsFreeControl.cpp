// HandsFreeControl: the dialogs, arming, and what each poll brings.
#include "ui/HandsFreeControl.h"

#include "devices/session/LiveSession.h"
#include "ui/DisplayUnits.h"
#include "ui/LimitsDialog.h"
#include "ui/NumberText.h"
#include "ui/ProblemReport.h"
#include "ui/TriggerDialog.h"
#include "ui/WatchBanner.h"

#include <QAction>
#include <QMenu>
#include <QSettings>
#include <QWidget>

#include <algorithm>

namespace tactiscope::ui {
namespace {

// An alarm in the quantity's display unit: "force above its critical limit
// 956 µN (978 µN)", "force back below its warning limit 597 µN".
QString alarmText(const devices::session::LimitAlarm& alarm, const std::vector<core::ChannelDescriptor>& watchable,
                  core::Mode mode)
{
    const DisplayUnit unit = watchedUnit(watchable, alarm.limit.quantity, mode);
    const core::trigger::LimitWording wording{
        [&unit](double si) { return typedText(si * unit.scale).toStdString(); },
        [&unit](double si) { return significantText(si * unit.scale, 3).toStdString(); }, unit.symbol.toStdString()};
    return QString::fromStdString(alarm.change.text(alarm.limit, wording));
}

}  // namespace

HandsFreeControl::HandsFreeControl(WatchBanner* banner, Hooks hooks, QWidget* window)
    : QObject(window),
      m_hooks(std::move(hooks)),
      m_banner(banner),
      m_window(window)
{
    m_banner->setSoundOn(QSettings().value(QStringLiteral("alarms/sound"), false).toBool());
}

void HandsFreeControl::addActions(QMenu* session)
{
    QAction* trigger = session->addAction(tr("&Trigger…"), this, [this] { showTrigger(); });
    trigger->setObjectName(QStringLiteral("triggerAction"));
    m_disarm = session->addAction(tr("&Disarm trigger"), this, &HandsFreeControl::disarm);
    m_disarm->setObjectName(QStringLiteral("disarmAction"));
    m_disarm->setEnabled(false);
    QAction* limits = session->addAction(tr("&Limits…"), this, [this] { showLimits(); });
    limits->setObjectName(QStringLiteral("limitsAction"));
    m_sound = session->addAction(tr("Sound on &alarms"));
    m_sound->setCheckable(true);
    m_sound->setChecked(m_banner->soundOn());
    connect(m_sound, &QAction::toggled, this, [this](bool on) {
        m_banner->setSoundOn(on);
        QSettings().setValue(QStringLiteral("alarms/sound"), on);
    });
}

TriggerDialog* HandsFreeControl::showTrigger()
{
    auto* live = m_hooks.session();
    if (!live) {
        m_hooks.tell(tr("Connect a device to arm a trigger."));
        return nullptr;
    }
    if (live->isRecording() && !live->triggerArmed()) {
        m_hooks.tell(tr("A recording is running: stop it before arming a trigger."));
        return nullptr;
    }
    if (m_triggerDialog) m_triggerDialog->close();
    auto* dialog = new TriggerDialog(live->watchableQuantities(), live->mode(), m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    if (m_last) dialog->setSettings(*m_last);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        if (const auto settings = dialog->settings()) arm(*settings);
    });
    dialog->open();
    m_triggerDialog = dialog;
    return dialog;
}

bool HandsFreeControl::arm(const core::trigger::TriggerSettings& settings)
{
    auto* live = m_hooks.session();
    if (!live) return false;
    if (live->triggerArmed()) disarm();
    const auto metadata = m_hooks.metadata();
    if (const QString refusal = m_hooks.refusal(metadata); !refusal.isEmpty()) {
        m_hooks.problem({tr("Cannot arm the trigger"), tr("The trigger was not armed."), refusal, {}});
        return false;
    }
    if (const auto refusal = live->armTrigger(settings, metadata)) {
        m_hooks.problem(
            {tr("Cannot arm the trigger"), tr("The trigger was not armed."), QString::fromStdString(*refusal), {}});
        return false;
    }
    m_last = settings;
    m_disarm->setEnabled(true);
    m_hooks.stateChanged();
    update();
    return true;
}

bool HandsFreeControl::armed() const
{
    auto* live = m_hooks.session();
    return live && live->triggerArmed();
}

void HandsFreeControl::disarm()
{
    auto* live = m_hooks.session();
    if (!live || !live->triggerArmed()) return;
    const auto open = live->disarmTrigger();
    m_disarm->setEnabled(false);
    if (open) m_hooks.sessionEnded(*open);
    m_hooks.stateChanged();
    update();
}

LimitsDialog* HandsFreeControl::showLimits()
{
    auto* live = m_hooks.session();
    if (!live) {
        m_hooks.tell(tr("Connect a device to see and set its limits."));
        return nullptr;
    }
    if (m_limitsDialog) m_limitsDialog->close();
    LimitsDialog::Session session{live->watchableQuantities(), live->mode(),
                                  [this] {
                                      auto* now = m_hooks.session();
                                      return now ? now->limits() : std::vector<core::sensors::SensorLimit>{};
                                  },
                                  live->givenLimits(),
                                  [this](const std::vector<core::trigger::LimitSpec>& given) {
                                      auto* now = m_hooks.session();
                                      return now ? now->setLimits(given)
                                                 : std::optional<std::string>("the device was disconnected");
                                  }};
    auto* dialog = new LimitsDialog(std::move(session), m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
    m_limitsDialog = dialog;
    return dialog;
}

void HandsFreeControl::update()
{
    auto* live = m_hooks.session();
    if (!live) return;
    const auto watchable = live->watchableQuantities();  // once per poll, for every alarm
    for (const auto& summary : live->takeTriggeredSummaries()) m_hooks.sessionEnded(summary);
    if (const auto refusal = live->takeTriggerRefusal()) {
        m_disarm->setEnabled(false);
        m_hooks.stateChanged();
        m_hooks.problem({tr("Trigger disarmed"), tr("The trigger fired, but no recording could start."),
                         QString::fromStdString(*refusal),
                         tr("Free space for the session store, or choose another, then arm the trigger again.")});
    }
    bool fresh = false;
    for (const auto& alarm : live->takeAlarms()) {
        const bool critical = alarm.change.severity == core::trigger::LimitSeverity::Critical;
        const QString text =
            alarm.change.raised
                ? (critical ? tr("Critical alarm at %1 s: %2") : tr("Warning at %1 s: %2"))
                      .arg(fixedText(alarm.time_s, 1), alarmText(alarm, watchable, live->mode()))
                : tr("Cleared at %1 s: %2").arg(fixedText(alarm.time_s, 1), alarmText(alarm, watchable, live->mode()));
        logProblem({tr("Limit alarm"), text, {}, {}});
        m_hooks.tell(text);
        fresh = fresh || alarm.change.raised;
    }
    // A limit's critical alarm says all its warning would.
    std::vector<WatchBanner::AlarmLine> lines;
    const auto& raised = live->raisedAlarms();
    for (const auto& alarm : raised) {
        const bool critical = alarm.change.severity == core::trigger::LimitSeverity::Critical;
        const bool outdone = !critical && std::ranges::any_of(raised, [&alarm](const auto& other) {
            return other.change.severity == core::trigger::LimitSeverity::Critical &&
                   other.limit.text() == alarm.limit.text();
        });
        if (!outdone) lines.push_back({critical, alarmText(alarm, watchable, live->mode())});
    }
    m_banner->showAlarms(lines, fresh);
    if (!live->triggerArmed()) {
        m_banner->showTrigger(std::nullopt);
        return;
    }
    // Every session asked for is stored: the trigger is done.
    if (live->triggerStatus().state == core::trigger::TriggerState::Finished && !live->isRecording()) {
        const unsigned cut = live->triggerStatus().sessionsCut;
        disarm();
        m_hooks.tell(tr("Trigger done: %n session(s) recorded.", nullptr, static_cast<int>(cut)));
        return;
    }
    WatchBanner::TriggerView view;
    view.status = live->triggerStatus();
    view.recording = live->isRecording();
    if (m_last) {
        view.condition = conditionText(m_last->condition, watchable, live->mode());
        view.sessions = m_last->sessions;
    }
    view.subject = QString::fromStdString(
        view.recording ? live->recordingMetadata().subject
                       : core::trigger::numberedSubject(m_hooks.metadata().subject, view.status.sessionsCut));
    m_banner->showTrigger(view);
}

void HandsFreeControl::disconnected()
{
    if (m_triggerDialog) m_triggerDialog->close();
    if (m_limitsDialog) m_limitsDialog->close();
    if (m_disarm) m_disarm->setEnabled(false);
    m_banner->showTrigger(std::nullopt);
    m_banner->showAlarms({}, false);
}

}  // namespace tactiscope::ui
