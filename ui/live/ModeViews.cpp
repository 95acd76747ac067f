// ModeViews: each mode's view, made from its ui entry and bound to the live session.
#include "ui/live/ModeViews.h"

#include "core/modes/ModeDefinition.h"
#include "devices/session/LiveSession.h"
#include "ui/live/LiveStation.h"
#include "ui/modes/LiveModeView.h"
#include "ui/modes/ModeUi.h"

#include <QStackedWidget>

namespace tactiscope::ui {

ModeViews::ModeViews(QWidget* parent)
    : QScrollArea(parent),
      m_stack(new QStackedWidget)
{
    setObjectName(QStringLiteral("modeViews"));
    setWidgetResizable(true);
    setFrameShape(QFrame::NoFrame);
    // Only sideways: a scroll bar that came and went with the view's height
    // would move its lists under the operator's eyes.
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    for (const auto& definition : core::modeDefinitions())
        if (const auto make = modeUi(definition.mode).liveView) {
            LiveModeView* view = make(m_stack);
            m_stack->addWidget(view);
            m_views.emplace(definition.mode, view);
        }
    setWidget(m_stack);
}

void ModeViews::watch(LiveStation& station, LivePlotWidget* traces)
{
    for (const auto& [mode, view] : m_views) view->setTraces(traces);
    connect(&station, &LiveStation::connected, this, [this, &station] { bindAll(station.device()); });
    connect(&station, &LiveStation::disconnecting, this, [this] { bindAll(nullptr); });
    const auto feed = [this, &station] {
        if (auto* live = station.device()) update(*live);
    };
    // Each poll; at a record press (the lists start again: a new panel shows
    // at once) and at a recording's end (they hold what was stored).
    connect(&station, &LiveStation::polled, this, feed);
    connect(&station, &LiveStation::recordingChanged, this, feed);
    connect(&station, &LiveStation::recordingEnded, this, feed);
}

LiveModeView* ModeViews::view(core::Mode mode) const
{
    const auto found = m_views.find(mode);
    return found == m_views.end() ? nullptr : found->second;
}

std::vector<LiveModeView*> ModeViews::views() const
{
    std::vector<LiveModeView*> all;
    for (const auto& [mode, view] : m_views) all.push_back(view);
    return all;
}

std::vector<LivePlotWidget*> ModeViews::lanes() const
{
    std::vector<LivePlotWidget*> all;
    for (const auto& [mode, view] : m_views) all.push_back(view->lanes());
    return all;
}

void ModeViews::bind(const devices::session::LiveSession* session, core::Mode mode)
{
    if (LiveModeView* shown = view(mode)) shown->bind(session);
}

void ModeViews::bindAll(const devices::session::LiveSession* session)
{
    for (const auto& [mode, view] : m_views) view->bind(session);
}

std::optional<core::Mode> ModeViews::show(const devices::session::LiveSession* session, core::Mode mode)
{
    LiveModeView* shown = session && session->unit(mode) ? view(mode) : nullptr;
    if (shown) m_stack->setCurrentWidget(shown);
    setVisible(shown != nullptr);
    return shown ? std::optional(mode) : std::nullopt;
}

LiveModeView* ModeViews::shown() const
{
    return isVisible() ? static_cast<LiveModeView*>(m_stack->currentWidget()) : nullptr;
}

QSize ModeViews::minimumSizeHint() const
{
    return {QScrollArea::minimumSizeHint().width(), m_stack->minimumSizeHint().height()};
}

void ModeViews::update(devices::session::LiveSession& session)
{
    for (const auto& [mode, view] : m_views) view->update(session);
}

}  // namespace tactiscope::ui
