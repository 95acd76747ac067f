// LiveTraces: the device's channels on the traces, one clock and one scroll for every plot.
#include "ui/live/LiveTraces.h"

#include "devices/session/LiveSession.h"
#include "ui/live/LiveStation.h"
#include "ui/plot/LivePlotWidget.h"

#include <algorithm>

namespace tactiscope::ui {

LiveTraces::LiveTraces(LiveStation& station, LivePlotWidget* traces, std::vector<LivePlotWidget*> lanes,
                       QObject* parent)
    : QObject(parent),
      m_station(station),
      m_traces(traces),
      m_lanes(std::move(lanes))
{
    // Every plot's window begins at the stream's start until it is full:
    // traces bound again (other filters) line up with the lanes.
    m_traces->setGrowsFrom(0.0);
    for (LivePlotWidget* lane : m_lanes) {
        lane->setPausedBannerShown(false);
        lane->setCompactTimeTitle(true);  // the traces above name the clock
    }
    for (LivePlotWidget* from : plots())
        connect(from, &LivePlotWidget::userScrolled, this, [this, from](double start_s, double end_s) {
            for (LivePlotWidget* to : plots())
                if (to != from) to->followTimeRange(start_s, end_s);
        });
    connect(&station, &LiveStation::connected, this, &LiveTraces::showChannels);
    connect(&station, &LiveStation::disconnecting, this, [this] { m_traces->clearSource(); });
    connect(&station, &LiveStation::polled, this, &LiveTraces::updateTimeBase);
}

std::vector<LivePlotWidget*> LiveTraces::plots() const
{
    std::vector<LivePlotWidget*> all{m_traces};
    all.insert(all.end(), m_lanes.begin(), m_lanes.end());
    return all;
}

void LiveTraces::showChannels()
{
    const auto* live = m_station.device();
    if (!live) return;
    const auto chain = live->signalChain();
    m_showingFiltered = m_filteredTraces && chain && chain->displaysFiltered();
    auto channels = live->channels();
    if (m_showingFiltered)  // the chain's channels: the device's when the filters were set
        channels.resize(std::min(channels.size(), chain->display()->channelCount()));
    m_traces->setSource(m_showingFiltered ? chain->display() : live->buffer(), channels,
                        live->source().nominalSampleRate_hz());
    updateTimeBase();
}

void LiveTraces::setFilteredTraces(bool filtered)
{
    m_filteredTraces = filtered;
    showChannels();
}

void LiveTraces::addMarker(double time_s, const QString& note)
{
    const auto* live = m_station.device();
    if (!live) return;
    if (const auto origin = live->recordingOrigin_s())
        for (LivePlotWidget* plot : plots()) plot->addMarker(*origin + time_s, note);
}

void LiveTraces::updateTimeBase()
{
    const auto* live = m_station.device();
    if (!live) return;
    if (!m_showingFiltered) m_traces->showMoreChannels(live->channels());  // a board's new layout
    const auto origin = live->recordingOrigin_s();
    const QString label = origin ? tr("Recording time (s)") : tr("Time since connect (s)");
    for (LivePlotWidget* plot : plots()) plot->setTimeOrigin(origin.value_or(0.0), label);
}

}  // namespace tactiscope::ui
