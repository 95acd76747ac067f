// ModeViews: each mode's view, made from its ui entry and bound to the live session.
#include "ui/ModeViews.h"

#include "core/modes/ModeDefinition.h"
#include "devices/session/LiveSession.h"
#include "ui/modes/LiveModeView.h"
#include "ui/modes/ModeUi.h"

namespace tactiscope::ui {

ModeViews::ModeViews(QWidget* parent)
    : QStackedWidget(parent)
{
    setObjectName(QStringLiteral("modeViews"));
    for (const auto& definition : core::modeDefinitions())
        if (const auto make = modeUi(definition.mode).liveView) {
            LiveModeView* view = make(this);
            addWidget(view);
            m_views.emplace(definition.mode, view);
        }
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
    if (shown) setCurrentWidget(shown);
    setVisible(shown != nullptr);
    return shown ? std::optional(mode) : std::nullopt;
}

void ModeViews::update(devices::session::LiveSession& session)
{
    for (const auto& [mode, view] : m_views) view->update(session);
}

}  // namespace tactiscope::ui
