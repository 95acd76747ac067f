// LiveSession's signal setup: the chain of filters and math channels on
// the acquisition thread, built, replaced, and offered to the watches.
#include "devices/session/LiveSession.h"

#include "core/NumberRanges.h"
#include "core/SinkSlot.h"

#include <cmath>
#include <stdexcept>

namespace tactiscope::devices::session {
namespace {

// How far back a recording's first sample may lie when the chain hears of
// it: a start the clock places up to ten seconds later (LiveSession.cpp:
// kLongestStartWait_s), or a trigger's longest pre-trigger stretch.
constexpr double kLongestReplay_s = 12.0 + core::kPreTriggerRange.most;

}  // namespace

std::shared_ptr<core::signal::SignalChain> LiveSession::makeChain(const core::signal::SignalSetup& setup) const
{
    const double rate_hz = source().nominalSampleRate_hz();
    const auto capacity = static_cast<std::size_t>(std::ceil(m_options.displaySeconds * rate_hz)) + 1;
    // The traces read its display as they read the device's buffer: as much of it.
    return std::make_shared<core::signal::SignalChain>(setup, m_channels, rate_hz, capacity, kLongestReplay_s,
                                                       m_buffer->capacity());
}

std::optional<std::string> LiveSession::setSignal(core::signal::SignalSetup setup)
{
    if (isRecording()) return "a recording keeps its filters and math channels; stop it first";
    if (m_trigger) return "the armed trigger records with these filters and math channels; disarm it first";
    if (setup.analysisFiltered && setup.filters.empty())
        return "the mode can analyse the filtered channels only when a channel is filtered";
    std::shared_ptr<core::signal::SignalChain> chain;
    if (!setup.empty()) {
        try {
            chain = makeChain(setup);
        } catch (const std::invalid_argument& e) {  // math::MathError among them
            return e.what();
        }
    }
    m_modeInput->setChain(setup.analysisFiltered ? chain : nullptr);
    m_options.signal = std::move(setup);
    m_chain = chain;
    m_signalSlot->set(std::move(chain));
    refreshReaders();
    return std::nullopt;
}

}  // namespace tactiscope::devices::session
