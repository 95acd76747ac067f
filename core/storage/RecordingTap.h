// A sink that stays on the acquisition for as long as the device streams
// and passes blocks to a Recorder while one is attached: recording starts
// and stops at any moment, while sinks can only be added before the
// acquisition starts. attach() and detach() come from the GUI thread,
// consume() from the acquisition thread.
#pragma once

#include "core/BlockSink.h"
#include "core/storage/Recorder.h"

#include <memory>
#include <mutex>
#include <optional>

namespace tactiscope::core::storage {

class RecordingTap final : public BlockSink {
public:
    // From the sample at block time `from_s` on, when given: what the
    // device measured before the recording began (a backlog in the port, a
    // text board's lines held while its rate was timed) is not recorded.
    void attach(std::shared_ptr<Recorder> recorder, std::optional<double> from_s = std::nullopt);
    // Returns the recorder that was attached; no block reaches it afterwards.
    std::shared_ptr<Recorder> detach();
    void consume(const SampleBlock& block) override;

private:
    std::mutex m_mutex;
    std::shared_ptr<Recorder> m_recorder;
    std::optional<double> m_from_s;  // until a block reaches it
};

}  // namespace tactiscope::core::storage
