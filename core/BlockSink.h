// A BlockSink receives every SampleBlock of one device, in order, on the
// acquisition thread: the live buffer, the recorder and the processors are
// all sinks. consume() must not block for long, since it delays the device.
#pragma once

namespace tactiscope::core {

class SampleBlock;

class BlockSink {
public:
    virtual ~BlockSink() = default;
    virtual void consume(const SampleBlock& block) = 0;
};

}  // namespace tactiscope::core
