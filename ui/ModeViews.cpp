// ModeViews: binding each mode's view to the live session's processor.
#include "ui/ModeViews.h"

#include "core/modes/ModeDefinition.h"
#include "devices/session/LiveSession.h"
#include "ui/CapacitiveView.h"
#include "ui/PalpationView.h"
#include "ui/PanelScanView.h"
#include "ui/SiteGridMap.h"
#include "ui/calibration/StoredCalibrations.h"

namespace tactiscope::ui {

ModeViews::ModeViews(QWidget* parent)
    : QStackedWidget(parent),
      m_panelScan(new PanelScanView(this)),
      m_palpation(new PalpationView(this)),
      m_capacitive(new CapacitiveView(this))
{
    setObjectName(QStringLiteral("modeViews"));
    addWidget(m_panelScan);
    addWidget(m_palpation);
    addWidget(m_capacitive);
}

std::vector<LivePlotWidget*> ModeViews::lanes() const
{
    return {m_panelScan->lanes(), m_palpation->lanes(), m_capacitive->lanes()};
}

void ModeViews::bind(const devices::session::LiveSession* session, core::Mode mode)
{
    const double rate_hz = session ? session->source().nominalSampleRate_hz() : 0.0;
    const auto* profile = session ? session->profile(mode) : nullptr;
    const QString probe = profile ? QString::fromStdString(core::sensors::profileName(*profile)) : QString();
    const QString calibrations = session ? calibrationsText(session->calibrations(mode)) : QString();
    // A mode without a view of its own (general) shows the device's traces.
    if (mode == core::Mode::PanelScan) m_panelScan->setDetection(session ? session->detection() : nullptr, rate_hz);
    if (mode == core::Mode::Palpation)
        m_palpation->setPalpation(session ? session->palpation() : nullptr, rate_hz, probe, calibrations);
    if (mode == core::Mode::Capacitive)
        m_capacitive->setCapacitive(
            session ? session->capacitive() : nullptr, rate_hz, probe,
            calibrations.isEmpty() ? tr("none — the beam model (uncalibrated); drift tracking off") : calibrations);
}

void ModeViews::bindAll(const devices::session::LiveSession* session)
{
    for (const auto& definition : core::modeDefinitions()) bind(session, definition.mode);
}

std::optional<core::Mode> ModeViews::show(const devices::session::LiveSession* session, core::Mode mode)
{
    QWidget* view = nullptr;
    if (session) {
        if (session->detection() && mode == core::Mode::PanelScan) view = m_panelScan;
        if (session->palpation() && mode == core::Mode::Palpation) view = m_palpation;
        if (session->capacitive() && mode == core::Mode::Capacitive) view = m_capacitive;
    }
    if (view) setCurrentWidget(view);
    setVisible(view != nullptr);
    return view ? std::optional(mode) : std::nullopt;
}

void ModeViews::update(devices::session::LiveSession& session)
{
    // The clinician's grid and choice of site first: a press completed in
    // this poll was taken there.
    SiteGridMap* grid = m_palpation->siteGrid();
    session.setSiteGrid(grid->grid());
    if (const auto chosen = grid->takeChosenSite()) session.selectSite(*chosen);
    m_panelScan->showDefects(session.panelDefects(), session.lists());
    m_palpation->showPresses(session.presses(), session.lists(), session.siteGrid());
    m_palpation->updateReadout();
    m_capacitive->updateReadouts();
}

}  // namespace tactiscope::ui
