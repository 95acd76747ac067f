// SignalControl: the menu action, the dialog's hooks, the plot of the chain.
#include "ui/signal/SignalControl.h"

#include "core/dsp/MainsHum.h"
#include "core/dsp/WelchSpectrum.h"
#include "devices/session/LiveSession.h"
#include "ui/common/DisplayUnits.h"
#include "ui/common/NumberText.h"
#include "ui/live/LiveStation.h"
#include "ui/plot/LivePlotWidget.h"
#include "ui/signal/SignalDialog.h"

#include <QLabel>
#include <QMenu>
#include <QSplitter>
#include <QVBoxLayout>

#include <algorithm>

namespace tactiscope::ui {
namespace {

// The strongest mains hum in the device's last seconds (its live buffer):
// its frequency and, in words, its level on the channel it is strongest on.
std::optional<std::pair<double, QString>> strongestHum(const devices::session::LiveSession& live)
{
    core::LiveCursor cursor;
    core::LiveChunk chunk;
    live.buffer()->readNew(cursor, chunk);
    const double rate_hz = live.source().nominalSampleRate_hz();
    std::optional<std::pair<double, QString>> found;
    double strongest = 0.0;  // in display units' multiples of the noise: compared within a channel's own
    for (std::size_t c = 0; c < chunk.values.size() && c < live.channels().size(); ++c) {
        // A 2 Hz resolution at most, to tell 50 from 60 Hz.
        const auto spectrum = core::dsp::welchSpectrum(chunk.values[c], rate_hz, {core::dsp::SpectralWindow::Hann, 4});
        const auto hum = core::dsp::findMainsHum(spectrum);
        if (!hum) continue;
        const double floor = core::dsp::noiseFloor(spectrum);
        const double standsOut = floor > 0.0 ? hum->amplitude / floor : hum->amplitude;
        if (found && standsOut <= strongest) continue;
        strongest = standsOut;
        const DisplayUnit unit = displayUnitFor(live.channels()[c]);
        found = {hum->mains_hz,
                 SignalControl::tr("%1 Hz hum, %2 %3 on %4 (the line at %5 Hz)")
                     .arg(hum->mains_hz)
                     .arg(significantText(hum->amplitude * unit.scale, 3), unit.symbol,
                          QString::fromStdString(live.channels()[c].name), significantText(hum->line_hz, 4))};
    }
    return found;
}

}  // namespace

SignalControl::SignalControl(LiveStation& station, QWidget* window)
    : QObject(window),
      m_station(station),
      m_window(window),
      m_panel(new QWidget(window)),
      m_line(new QLabel(m_panel)),
      m_plot(new LivePlotWidget(m_panel)),
      m_filteredTraces(new QAction(tr("Traces as &filtered"), this))
{
    m_filteredTraces->setObjectName(QStringLiteral("filteredTracesAction"));
    m_filteredTraces->setCheckable(true);
    m_filteredTraces->setChecked(true);
    m_filteredTraces->setToolTip(tr("A filtered channel's trace as filtered; unticked, as it came, with the "
                                    "filtered one plotted under the traces."));
    connect(m_filteredTraces, &QAction::toggled, this, &SignalControl::bind);
    m_panel->setObjectName(QStringLiteral("signalPanel"));
    m_line->setObjectName(QStringLiteral("signalLine"));
    m_line->setWordWrap(true);
    m_line->setContentsMargins(6, 2, 6, 0);
    m_plot->setObjectName(QStringLiteral("signalPlot"));
    m_plot->setGrowsFrom(0.0);  // the stream's start, where the traces above begin
    auto* layout = new QVBoxLayout(m_panel);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(m_line);
    layout->addWidget(m_plot, 1);
    m_panel->hide();
    connect(&station, &LiveStation::connected, this, &SignalControl::bind);
    connect(&station, &LiveStation::disconnecting, this, [this] {
        m_plot->clearSource();
        m_panel->hide();
        if (m_dialog) m_dialog->close();
    });
}

void SignalControl::addActions(QMenu* session)
{
    QAction* action = session->addAction(tr("&Filters and math channels…"), this, [this] { showDialog(); });
    action->setObjectName(QStringLiteral("signalAction"));
}

SignalDialog* SignalControl::showDialog(std::size_t device)
{
    auto& pipeline = m_station.pipeline();
    if (device >= pipeline.size()) return nullptr;
    auto& live = pipeline.device(device);
    if (m_dialog) m_dialog->close();
    // The device is found again by its name when applied: the session's
    // devices may have changed while the dialog was open.
    const std::string name = pipeline.name(device);
    const auto deviceNow = [this, name]() -> devices::session::LiveSession* {
        auto& now = m_station.pipeline();
        for (std::size_t i = 0; i < now.size(); ++i)
            if (now.name(i) == name) return &now.device(i);
        return nullptr;
    };
    SignalDialog::Session session{
        .channels = live.channels(),
        .rate_hz = live.source().nominalSampleRate_hz(),
        .setup = live.signalSetup(),
        .apply = [this, deviceNow](const core::signal::SignalSetup& setup) -> std::optional<std::string> {
            auto* now = deviceNow();
            if (!now) return "the device was disconnected";
            auto refusal = now->setSignal(setup);
            if (!refusal && now == m_station.device()) bind();  // the panel shows the window's device
            return refusal;
        },
        .findMains = [deviceNow]() -> std::optional<std::pair<double, QString>> {
            const auto* now = deviceNow();
            return now ? strongestHum(*now) : std::nullopt;
        },
        .devices = pipeline.size() > 1 ? pipeline.names() : std::vector<std::string>{},
        .device = device,
        .showDevice = [this](std::size_t other) { showDialog(other); },
    };
    auto* dialog = new SignalDialog(std::move(session), m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
    m_dialog = dialog;
    return dialog;
}

void SignalControl::bind()
{
    const bool filtered = m_filteredTraces->isChecked();
    emit tracesChanged(filtered);
    const auto* live = m_station.device();
    const auto chain = live ? live->signalChain() : nullptr;
    if (!chain) {
        m_plot->clearSource();
        m_panel->hide();
        return;
    }
    // The traces show the filtered channels: the plot, the math ones alone.
    const bool tracesFiltered = filtered && chain->displaysFiltered();
    const double rate_hz = live->source().nominalSampleRate_hz();
    if (!tracesFiltered)
        m_plot->setSource(chain->output(), chain->outputs(), rate_hz);
    else if (chain->mathOutput())
        m_plot->setSource(chain->mathOutput(), chain->mathOutputs(), rate_hz);
    else
        m_plot->clearSource();
    const bool plotWasShown = m_panel->isVisible() && m_plot->isVisibleTo(m_panel);
    const bool plotShown = !tracesFiltered || chain->mathOutput();
    m_plot->setVisible(plotShown);
    QStringList parts;
    for (std::size_t o = 0; o < chain->outputs().size(); ++o) {
        const QString name = QString::fromStdString(chain->outputs()[o].name);
        if (o < chain->setup().filters.size())
            parts << tr("%1: %2, delay %3 ms")
                         .arg(name, QString::fromStdString(chain->setup().filters[o].settings.text()),
                              significantText(chain->delay_s(o) * 1e3, 3));
        else
            parts << QString::fromStdString(chain->setup().math[o - chain->setup().filters.size()].text());
    }
    if (chain->setup().analysisFiltered) parts << tr("the mode analyses the filtered channels");
    if (tracesFiltered) parts.prepend(tr("The traces show the filtered channels"));
    m_line->setText(parts.join(QStringLiteral(" · ")));
    m_panel->show();
    // The line alone takes its own height; with the plot, a third of the
    // room each for traces, plot and the mode's view, read side by side.
    m_panel->setMaximumHeight(
        plotShown ? QWIDGETSIZE_MAX : std::max(m_line->sizeHint().height(), m_line->heightForWidth(m_panel->width())));
    if (plotShown && !plotWasShown)
        if (auto* splitter = qobject_cast<QSplitter*>(m_panel->parentWidget())) {
            QList<int> sizes = splitter->sizes();
            int total = 0;
            for (const int size : sizes) total += size;
            for (int& size : sizes) size = total / static_cast<int>(sizes.size());
            splitter->setSizes(sizes);
        }
}

}  // namespace tactiscope::ui
