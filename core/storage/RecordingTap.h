// A sink that stays on the acquisition for as long as the device streams
// and passes blocks to a Recorder while one is attached: recording starts
// and stops at any moment, while sinks can only be added before the
// acquisition starts. attach() and detach() come from the GUI thread,
// consume() from the acquisition thread.
//
// A recording begins at an instant; where that lies on the stream's block
// time the source's clock says, and a clock may need the stream that
// follows to say it (a board's lines that waited in its port look, until
// later lines arrive on time, like the latest ones). The tap holds the
// blocks until the start is known, then records from it; a recording of a
// set length (`record --seconds`) ends where the stream's clock says.
#pragma once

#include "core/BlockSink.h"
#include "core/SampleBlock.h"
#include "core/storage/Recorder.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace tactiscope::core::storage {

// Where a recording begins: not known yet, at a block time, or from the
// first block that reaches it.
struct RecordingStart {
    bool known = false;
    std::optional<double> from_s;

    static RecordingStart notYet() { return {}; }
    static RecordingStart at(double from_s) { return {true, from_s}; }
    static RecordingStart fromFirstBlock() { return {true, std::nullopt}; }
};

// Asked as blocks come while the start is not known, with the end time of
// the newest; `mustAnswer` when the recording stops or the blocks held
// reach the most the tap holds (then a start that is not known is taken as
// the first block's). How long to wait is the finder's to say: the blocks'
// own time says nothing of it (a board catching up sends a minute of lines
// in a second).
using RecordingStartFinder = std::function<RecordingStart(double newestEnd_s, bool mustAnswer)>;

class RecordingTap final : public BlockSink {
public:
    // The values (samples times channels) a start not yet known may hold
    // back: 128 MB, ten seconds of the fastest probe's every channel.
    static constexpr std::size_t kMostHeldValues = std::size_t{1} << 24;

    explicit RecordingTap(std::size_t mostHeldValues = kMostHeldValues)
        : m_mostHeldValues(mostHeldValues)
    {
    }

    // From the first block when no finder is given; `length_s`: only the
    // samples whose periods lie (most of each) within it of the first one
    // recorded, so a recording of a set length holds exactly that, however
    // late the stop comes.
    void attach(std::shared_ptr<Recorder> recorder, RecordingStartFinder start = {},
                std::optional<double> length_s = std::nullopt);
    // Whether a recording of a set length has all of it.
    bool complete() const;
    // Returns the recorder that was attached, with what was held for it;
    // no block reaches it afterwards.
    std::shared_ptr<Recorder> detach();
    void consume(const SampleBlock& block) override;
    // To the recorder attached, and to each attached later.
    void channelsGrew(const std::vector<ChannelDescriptor>& all) override;

private:
    // Records the blocks held, from `start` on (and later blocks too, until
    // one reaches it).
    void release(const RecordingStart& start);
    void record(const SampleBlock& block);

    mutable std::mutex m_mutex;
    std::shared_ptr<Recorder> m_recorder;
    RecordingStartFinder m_finder;    // until the start is known
    std::vector<SampleBlock> m_held;  // meanwhile
    std::size_t m_heldValues = 0;     // in them
    const std::size_t m_mostHeldValues;
    std::optional<double> m_from_s;    // until a block reaches it
    std::optional<double> m_length_s;  // a set length
    std::optional<double> m_until_s;   // its end, once the first sample is recorded
    bool m_complete = false;
    std::vector<ChannelDescriptor> m_grownTo;  // the device's channels, once they grew
};

}  // namespace tactiscope::core::storage
