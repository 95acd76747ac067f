// The signal chain (issue 57): a device's channels through the filters of
// a session's signal setup, and its math channels over them, sample for
// sample, into an output buffer the views, the limits and the trigger read
// like a mode's derived quantities (each block's outputs are there once the
// block has passed).
//
// Its inputs are the samples as the store keeps them (IEEE binary32,
// core/storage/ChunkCodec.h). The filters run on through a recording's
// start: the chain keeps where each filter's sections stood at the
// recording's first sample (recordingBegins(); when it hears of that
// sample after passing it, it finds the state again from what it kept)
// and starts the moving averages afresh there. The session stores those
// states with its setup (SignalSetup::startState), and re-analysis
// (chainSeries()) starts from them: the filtered series of a recording is
// exactly what re-analysis computes from the stored samples, and nothing
// rings at the record press. A lost sample (a jump in the block's sample
// index) is missing for the filters too, which start afresh after it, as
// they do on a stored gap.
//
// Math channels read each channel as the chain outputs it: filtered where
// it is filtered, as stored elsewhere.
//
// Threading: consume() on the acquisition thread; recordingBegins() from any.
#pragma once

#include "core/BlockSink.h"
#include "core/ChannelDescriptor.h"
#include "core/LiveBuffer.h"
#include "core/RingBuffer.h"
#include "core/dsp/ChannelFilter.h"
#include "core/math/MathChannels.h"
#include "core/signal/SignalSetup.h"

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace tactiscope::core::signal {

// The name a filtered channel is watched and shown by: "a.filtered".
std::string filteredName(const std::string& channel);

class SignalChain final : public BlockSink {
public:
    // `outputCapacity`: samples kept per output for the readers;
    // `replay_s`: how far back a restart can reach; `displayCapacity`:
    // samples kept for the traces (display(), mathOutput()), none when 0.
    // Throws std::invalid_argument (signalSetupRefusal's words) or
    // math::MathError.
    SignalChain(const SignalSetup& setup, const std::vector<ChannelDescriptor>& channels, double sampleRate_hz,
                std::size_t outputCapacity, double replay_s = 0.0, std::size_t displayCapacity = 0);
    ~SignalChain() override;

    const SignalSetup& setup() const { return m_setup; }
    // Each filtered channel ("a.filtered", the channel's unit and kind),
    // then each math channel (its declared unit).
    const std::vector<ChannelDescriptor>& outputs() const { return m_outputs; }
    std::shared_ptr<const LiveBuffer> output() const { return m_output; }
    // For the window's traces: every device channel as they show it,
    // filtered where it is filtered (as stored elsewhere), so a filtered
    // device is drawn once, not twice; and the math channels alone. Null
    // without a display capacity (and the latter without math channels).
    std::shared_ptr<const LiveBuffer> display() const { return m_display; }
    std::shared_ptr<const LiveBuffer> mathOutput() const { return m_mathOutput; }
    // Whether its display differs from the channels as they came: it has
    // one, and a filter.
    bool displaysFiltered() const { return m_display && !m_filters.empty(); }
    // The math channels' descriptors (the tail of outputs()).
    std::vector<ChannelDescriptor> mathOutputs() const;
    // How far output `index` lags its channel (a filter's group delay; 0
    // for a math channel).
    double delay_s(std::size_t index) const;

    // Where each filter's sections stood at a recording's first sample.
    using StartState = std::vector<std::optional<std::vector<double>>>;
    // A recording's first sample is device sample `first`: `found` is told
    // where the filters stood there (on the acquisition thread) when the
    // chain reaches it, or at once when it has passed it and kept it. One
    // kept too long ago is found at the oldest sample kept.
    void recordingBegins(std::uint64_t first, std::function<void(StartState)> found);

    void consume(const SampleBlock& block) override;

    // `block`, with each filtered channel as the chain filtered it, when it
    // is the block the chain consumed last (a mode analysing the filtered
    // channels reads them so, on the same thread, right after the chain);
    // otherwise `block` as it is. Acquisition thread.
    void filteredCopy(const SampleBlock& block, SampleBlock& out) const;

private:
    struct Begin {
        std::uint64_t first = 0;
        std::function<void(StartState)> found;
    };
    // A beginning within `block` at `offset` (or none: `block`'s size), or
    // one before it, found again from what was kept.
    std::optional<Begin> takeBegin(const SampleBlock& block, std::size_t& offset);
    void beginPassed(const Begin& begin);
    StartState states() const;
    void lose(std::uint64_t samples);

    SignalSetup m_setup;
    std::vector<std::size_t> m_filtered;  // the channel of each filter
    std::vector<dsp::ChannelFilter> m_filters;
    std::unique_ptr<math::MathChannels> m_math;
    std::vector<ChannelDescriptor> m_outputs;
    std::shared_ptr<LiveBuffer> m_output;
    std::shared_ptr<LiveBuffer> m_display;
    std::shared_ptr<LiveBuffer> m_mathOutput;
    std::size_t m_channelCount = 0;

    // What the filters read since the oldest sample a restart may reach
    // (none when it may reach none); NaN where samples were lost. Ring
    // index r holds device sample m_keptBase + r. Binary32, as the inputs
    // are rounded to it: half the memory, nothing lost.
    std::vector<RingBuffer<float>> m_kept;
    std::uint64_t m_keptBase = 0;
    std::optional<std::uint64_t> m_next;  // the device index expected next

    // Each filter's state at a kept block's first sample, oldest first.
    struct Snapshot {
        std::uint64_t first = 0;
        StartState states;
    };
    std::deque<Snapshot> m_snapshots;
    StartState m_startState;  // the setup's, for the first block (re-analysis)

    std::mutex m_beginMutex;
    std::optional<Begin> m_begin;

    // Per block, reused; kept until the next (filteredCopy()).
    std::vector<std::vector<double>> m_values;  // rounded inputs, filtered where filtered
    std::uint64_t m_lastFirst = 0;              // the last block's first sample index
    std::vector<std::vector<double>> m_mathValues;
};

// Re-analysis: the chain's outputs over stored samples (one vector per
// channel, NaN where missing), from the first: one vector per output.
std::vector<std::vector<double>> chainSeries(const SignalSetup& setup, const std::vector<ChannelDescriptor>& channels,
                                             double sampleRate_hz, const std::vector<std::vector<double>>& values);

}  // namespace tactiscope::core::signal
