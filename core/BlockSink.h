// A BlockSink receives every SampleBlock of one device, in order, on the
// acquisition thread: the live buffer, the recorder and the processors are
// all sinks. consume() must not block for long, since it delays the device.
#pragma once

#include "core/ChannelDescriptor.h"

#include <vector>

namespace tactiscope::core {

class SampleBlock;

class BlockSink {
public:
    virtual ~BlockSink() = default;
    virtual void consume(const SampleBlock& block) = 0;
    // The device's channels grew (a board printing lines began to print
    // another value): `all` are its channels now, and the blocks from the
    // next one on hold them all. A sink that reads only the channels it
    // was made for ignores it.
    virtual void channelsGrew(const std::vector<ChannelDescriptor>& /*all*/) {}
};

}  // namespace tactiscope::core
