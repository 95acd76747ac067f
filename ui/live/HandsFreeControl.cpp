// HandsFreeControl: the dialogs, arming, and what each poll brings.
#include "ui/live/HandsFreeControl.h"

#include "devices/session/LiveSession.h"
#include "ui/common/DisplayUnits.h"
#include "ui/common/NumberText.h"
#include "ui/common/ProblemReport.h"
#include "ui/live/LimitsDialog.h"
#include "ui/live/LiveStation.h"
#include "ui/live/TriggerDialog.h"
#include "ui/live/WatchBanner.h"

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
    const core::trigger::LimitWording wording{[&unit](double si) { return typedText(si * unit.scale).toStdString(); },
                                              [&unit](double si) {
                                                  return (significantText(si * unit.scale, 3) +
                                                          (unit.symbol.isEmpty() ? QString() : u' ' + unit.symbol))
                                                      .toStdString();
                                              },
                                              unit.symbol.toStdString()};
    return QString::fromStdString(alarm.change.text(alarm.limit, wording));
}

}  // namespace

HandsFreeControl::HandsFreeControl(LiveStation& station, WatchBanner* banner, Hooks hooks, QWidget* window)
    : QObject(window),
      m_station(station),
      m_hooks(std::move(hooks)),
      m_banner(banner),
      m_window(window)
{
    m_banner->setSoundOn(QSettings().value(QStringLiteral("alarms/sound"), false).toBool());
    connect(&station, &LiveStation::polled, this, &HandsFreeControl::update);
    connect(&station, &LiveStation::disconnected, this, &HandsFreeControl::disconnected);
    connect(&station, &LiveStation::armedChanged, this, [this](bool armed) {
        if (m_disarm) m_disarm->setEnabled(armed);
        if (!armed) m_banner->showTrigger(std::nullopt);
    });
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
    auto* live = m_station.device();
    if (!live) {
        m_hooks.tell(tr("Connect a device to arm a trigger."));
        return nullptr;
    }
    if (m_station.isRecording() && !m_station.armed()) {
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
    if (!m_station.device()) return false;
    const auto metadata = m_hooks.metadata();
    if (const QString refusal = m_hooks.refusal(metadata); !refusal.isEmpty()) {
        m_hooks.problem({tr("Cannot arm the trigger"), tr("The trigger was not armed."), refusal, {}});
        return false;
    }
    if (const auto refusal = m_station.armTrigger(settings, metadata)) {
        m_hooks.problem({tr("Cannot arm the trigger"), tr("The trigger was not armed."), *refusal, {}});
        return false;
    }
    m_last = settings;
    showTriggerState(*m_station.device());
    return true;
}

bool HandsFreeControl::armed() const
{
    return m_station.armed();
}

void HandsFreeControl::disarm()
{
    m_station.disarmTrigger();
}

LimitsDialog* HandsFreeControl::showLimits()
{
    auto* live = m_station.device();
    if (!live) {
        m_hooks.tell(tr("Connect a device to see and set its limits."));
        return nullptr;
    }
    if (m_limitsDialog) m_limitsDialog->close();
    LimitsDialog::Session session{
        .watchable = live->watchableQuantities(),
        .mode = live->mode(),
        .limits =
            [this] {
                auto* now = m_station.device();
                return now ? now->limits() : std::vector<core::sensors::SensorLimit>{};
            },
        .given = live->givenLimits(),
        .apply =
            [this](const std::vector<core::trigger::LimitSpec>& given) {
                auto* now = m_station.device();
                return now ? now->setLimits(given) : std::optional<std::string>("the device was disconnected");
            },
    };
    auto* dialog = new LimitsDialog(std::move(session), m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
    m_limitsDialog = dialog;
    return dialog;
}

void HandsFreeControl::update(const devices::session::PipelineNews& news)
{
    if (news.triggerRefused)
        m_hooks.problem({tr("Trigger disarmed"), tr("The trigger fired, but no recording could start."),
                         QString::fromStdString(*news.triggerRefused),
                         tr("Free space for the session store, or choose another, then arm the trigger again.")});
    auto* live = m_station.device();
    if (!live) return;
    showAlarms(news);
    if (!m_station.armed()) return;
    // Every session asked for is stored: the trigger is done.
    if (live->triggerStatus().state == core::trigger::TriggerState::Finished && !live->isRecording()) {
        const unsigned cut = live->triggerStatus().sessionsCut;
        disarm();
        m_hooks.tell(tr("Trigger done: %n session(s) recorded.", nullptr, static_cast<int>(cut)));
        return;
    }
    showTriggerState(*live);
}

// Each alarm told (in its device's display unit), then the banner of
// those raised on the window's device.
void HandsFreeControl::showAlarms(const devices::session::PipelineNews& news)
{
    const auto& pipeline = m_station.pipeline();
    bool fresh = false;
    for (const auto& [device, alarm] : news.alarms) {
        std::size_t index = 0;
        while (!device.empty() && index + 1 < pipeline.size() && pipeline.name(index) != device) ++index;
        const auto& from = pipeline.device(index);
        const QString what = alarmText(alarm, from.watchableQuantities(), from.mode());
        const bool critical = alarm.change.severity == core::trigger::LimitSeverity::Critical;
        QString text = alarm.change.raised ? (critical ? tr("Critical alarm at %1 s: %2") : tr("Warning at %1 s: %2"))
                                                 .arg(fixedText(alarm.time_s, 1), what)
                                           : tr("Cleared at %1 s: %2").arg(fixedText(alarm.time_s, 1), what);
        if (!device.empty()) text = QString::fromStdString(device) + QStringLiteral(": ") + text;
        logProblem({tr("Limit alarm"), text, {}, {}});
        m_hooks.tell(text);
        fresh = fresh || alarm.change.raised;
    }
    // A limit's critical alarm says all its warning would.
    const auto& live = pipeline.device(0);
    const auto watchable = live.watchableQuantities();
    std::vector<WatchBanner::AlarmLine> lines;
    const auto& raised = live.raisedAlarms();
    for (const auto& alarm : raised) {
        const bool critical = alarm.change.severity == core::trigger::LimitSeverity::Critical;
        const bool outdone = !critical && std::ranges::any_of(raised, [&alarm](const auto& other) {
            return other.change.severity == core::trigger::LimitSeverity::Critical &&
                   other.limit.text() == alarm.limit.text();
        });
        if (!outdone) lines.push_back({critical, alarmText(alarm, watchable, live.mode())});
    }
    m_banner->showAlarms(lines, fresh);
}

void HandsFreeControl::showTriggerState(const devices::session::LiveSession& live)
{
    WatchBanner::TriggerView view;
    view.status = live.triggerStatus();
    view.recording = live.isRecording();
    if (m_last) {
        view.condition = conditionText(m_last->condition, live.watchableQuantities(), live.mode());
        view.sessions = m_last->sessions;
    }
    view.subject = QString::fromStdString(
        view.recording ? live.recordingMetadata().subject
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
